#include "field.h"

#include <cmath>
#include <limits>

#include "core/error.h"
#include "core/halo.h"

namespace maquette::texture {
namespace {

constexpr double kAuthalicRadius = 6371007.180918;

// Uniform cubic B-spline weights of taps i-1 .. i+2 at fraction f.
std::array<double, 4> bspline_weights(double f) {
  const double f2 = f * f, f3 = f2 * f;
  return {(1 - f) * (1 - f) * (1 - f) / 6, (3 * f3 - 6 * f2 + 4) / 6,
          (-3 * f3 + 3 * f2 + 3 * f + 1) / 6, f3 / 6};
}

struct Taps {
  int first = 0;  // input pixel of the first tap
  std::array<double, 4> w{};
};

// Target pixel t (of a tile 2^refine times finer) -> input taps; input pixel centres are at
// integer coordinates, target pixel centres at (t + 0.5) / 2^refine - 0.5.
Taps taps(int t, int refine) {
  const double u = (t + 0.5) / double(1 << refine) - 0.5, i = std::floor(u);
  return {int(i) - 1, bspline_weights(u - i)};
}

}  // namespace

Plane upsample(const Tile<float>& tile, int refine, int ring) {
  const int m = tile.size() << refine;
  if (tile.halo() < kInputHalo)
    throw Error("texture: input tiles need a halo of " + std::to_string(kInputHalo) + " pixels");
  Plane out(m, ring);
  std::vector<Taps> t(size_t(out.side()));
  for (int i = 0; i < out.side(); ++i) t[size_t(i)] = taps(i - ring, refine);
  // Separable: rows of the input first (at target columns), then columns.
  const int rows0 = t.front().first, rows1 = t.back().first + 4;
  std::vector<double> horizontal(size_t(rows1 - rows0) * size_t(out.side()));
  for (int r = rows0; r < rows1; ++r)
    for (int c = 0; c < out.side(); ++c) {
      const Taps& tc = t[size_t(c)];
      double s = 0;
      for (int k = 0; k < 4; ++k) s += tc.w[size_t(k)] * tile.at(tc.first + k, r);
      horizontal[size_t(r - rows0) * size_t(out.side()) + size_t(c)] = s;
    }
  for (int r = 0; r < out.side(); ++r) {
    const Taps& tr = t[size_t(r)];
    for (int c = 0; c < out.side(); ++c) {
      double s = 0;
      for (int k = 0; k < 4; ++k)
        s += tr.w[size_t(k)] *
             horizontal[size_t(tr.first + k - rows0) * size_t(out.side()) + size_t(c)];
      out.v[size_t(r) * size_t(out.side()) + size_t(c)] = float(s);  // NaN taps propagate
    }
  }
  return out;
}

Plane slope_degrees(const Plane& h, double pixel_m) {
  Plane s(h.size, h.ring - 1);
  const double k = 1 / (2 * pixel_m), deg = 180 / M_PI;
  for (int r = -s.ring; r < s.size + s.ring; ++r)
    for (int c = -s.ring; c < s.size + s.ring; ++c) {
      const double gx = (h.at(c + 1, r) - h.at(c - 1, r)) * k;
      const double gy = (h.at(c, r + 1) - h.at(c, r - 1)) * k;
      s.at(c, r) = float(std::atan(std::sqrt(gx * gx + gy * gy)) * deg);  // not hypot: slow
    }
  return s;
}

std::vector<Vec3d> pixel_positions(const Grid& grid, CellId cell, int size, int refine, int ring) {
  const int m = size << refine;
  const int level = cell.level() + log2_tile_size(m);
  // Exact every 8th pixel, or 16th or 32nd while that spans <= 300 m (bilinear positions then
  // deviate from the true ones by centimetres at most): the projection is the costly part.
  int shift = 3;
  while (shift < 5 && (2 << shift) * grid.level_info(level, 1).pixel_m <= 300) ++shift;
  const int step = 1 << shift;
  const int64_t gc0 = int64_t(cell.col()) * m - ring, gr0 = int64_t(cell.row()) * m - ring;
  const auto floor_div = [shift](int64_t a) { return a >> shift; };
  const int64_t nc0 = floor_div(gc0), nr0 = floor_div(gr0);
  const int nodes = (m + 2 * ring) / step + 3;
  std::vector<Vec3d> node(size_t(nodes) * size_t(nodes));
  for (int j = 0; j < nodes; ++j)
    for (int i = 0; i < nodes; ++i) {
      const int64_t lc = (nc0 + i) * step - int64_t(cell.col()) * m;
      const int64_t lr = (nr0 + j) * step - int64_t(cell.row()) * m;
      const std::optional<FaceCoord> src = pixel_source(grid, cell, m, int(lc), int(lr));
      if (!src) throw Error("texture: tile " + cell.ToText() + " too small for its noise lattice");
      const LonLat p = pixel_centre(grid, *src, level);
      const double lat = p.lat * M_PI / 180, lon = p.lon * M_PI / 180;
      node[size_t(j) * size_t(nodes) + size_t(i)] = {
          kAuthalicRadius * std::cos(lat) * std::cos(lon),
          kAuthalicRadius * std::cos(lat) * std::sin(lon), kAuthalicRadius * std::sin(lat)};
    }
  const int side = m + 2 * ring;
  std::vector<Vec3d> out(size_t(side) * size_t(side));
  for (int r = 0; r < side; ++r) {
    const int64_t gr = gr0 + r;
    const int j = int(floor_div(gr) - nr0);
    const double fy = double(gr - floor_div(gr) * step) / step;
    for (int c = 0; c < side; ++c) {
      const int64_t gc = gc0 + c;
      const int i = int(floor_div(gc) - nc0);
      const double fx = double(gc - floor_div(gc) * step) / step;
      const auto n = [&](int a, int b) {
        return node[size_t(j + b) * size_t(nodes) + size_t(i + a)];
      };
      Vec3d& p = out[size_t(r) * size_t(side) + size_t(c)];
      for (int k = 0; k < 3; ++k)
        p[size_t(k)] = (1 - fy) * ((1 - fx) * n(0, 0)[size_t(k)] + fx * n(1, 0)[size_t(k)]) +
                       fy * ((1 - fx) * n(0, 1)[size_t(k)] + fx * n(1, 1)[size_t(k)]);
    }
  }
  return out;
}

}  // namespace maquette::texture
