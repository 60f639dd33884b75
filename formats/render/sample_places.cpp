#include "render/sample_places.h"

#include <algorithm>
#include <cmath>

#include "core/halo.h"
#include "core/tile.h"

namespace maquette {
namespace {

constexpr int kLattice = 32;  // lattice intervals per side
// Beyond this latitude longitudes bend too fast across a lattice interval to interpolate them
// (their error grows as the interval squared over the distance to the pole).
constexpr double kPolarLatitude = 80;

SamplePlace exact(const EnuFrame& frame, const EllipsoidalHeights& heights, LonLat p) {
  std::array<double, 9> axes{};
  const auto base = frame.to_enu(p.lon, p.lat, heights(p, 0), axes);
  return {p, base, {axes[2], axes[5], axes[8]}, true};  // column 2: the point's up
}

}  // namespace

SamplePlaces::SamplePlaces(const Grid& grid, CellId cell, int size, int halo, const EnuFrame& frame,
                           const EllipsoidalHeights& heights)
    : size_(size), halo_(halo), places_(size_t(size + 2 * halo) * size_t(size + 2 * halo)) {
  const int pixel_level = cell.level() + log2_tile_size(size);
  auto slot = [&](int col, int row) {
    return size_t(row + halo) * size_t(size + 2 * halo) + size_t(col + halo);
  };
  const FaceCoord origin = *pixel_source(grid, cell, size, 0, 0);
  const PlaneSquare square = grid.plane_square(cell);
  auto plane = [&](int col, int row) {
    return PlanePoint{square.x_min + (col + 0.5) * square.side / size,
                      square.y_max - (row + 0.5) * square.side / size};
  };
  auto place_exactly = [&](int col, int row) {
    const std::optional<FaceCoord> source = pixel_source(grid, cell, size, col, row);
    if (!source) return;
    SamplePlace& s = places_[slot(col, row)];
    s = exact(frame, heights, pixel_centre(grid, *source, pixel_level));
    if (source->face == origin.face && source->col == origin.col + col &&
        source->row == origin.row + row)
      s.plane = plane(col, row);
  };
  for (int ring = 1; ring <= halo; ++ring)
    for (int k = -ring; k < size + ring; ++k) {
      place_exactly(k, -ring);
      place_exactly(k, size + ring - 1);
      place_exactly(-ring, k);
      place_exactly(size + ring - 1, k);
    }
  // The lattice on the cell's own face: nodes at samples i (size - 1) / m, i = 0 .. m.
  const int m = std::min(kLattice, size - 1);
  std::vector<SamplePlace> nodes;
  double west = INFINITY, east = -INFINITY, poleward = 0;
  for (int j = 0; j <= m; ++j)
    for (int i = 0; i <= m; ++i) {
      const double step = m == 0 ? 0 : double(size - 1) / m;
      nodes.push_back(exact(frame, heights,
                            face_point_lonlat(grid, origin.face, double(origin.col) + i * step,
                                              double(origin.row) + j * step, pixel_level)));
      west = std::min(west, nodes.back().position.lon);
      east = std::max(east, nodes.back().position.lon);
      poleward = std::max(poleward, std::abs(nodes.back().position.lat));
    }
  if (m < 2 || east - west > 90 || poleward > kPolarLatitude) {
    for (int row = 0; row < size; ++row)
      for (int col = 0; col < size; ++col) place_exactly(col, row);
    return;
  }
  for (int row = 0; row < size; ++row) {
    const double y = double(row) * m / (size - 1);
    const int j = std::min(m - 1, int(y));
    const double fy = y - j;
    for (int col = 0; col < size; ++col) {
      const double x = double(col) * m / (size - 1);
      const int i = std::min(m - 1, int(x));
      const double fx = x - i;
      const SamplePlace* q[4] = {
          &nodes[size_t(j * (m + 1) + i)], &nodes[size_t(j * (m + 1) + i + 1)],
          &nodes[size_t((j + 1) * (m + 1) + i)], &nodes[size_t((j + 1) * (m + 1) + i + 1)]};
      const double w[4] = {(1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy};
      SamplePlace& s = places_[slot(col, row)];
      s.known = true;
      s.plane = plane(col, row);
      s.position = {0, 0};
      for (int k = 0; k < 4; ++k) {
        s.position.lon += w[k] * q[k]->position.lon;
        s.position.lat += w[k] * q[k]->position.lat;
        for (size_t a = 0; a < 3; ++a) {
          s.base[a] += w[k] * q[k]->base[a];
          s.up[a] += w[k] * q[k]->up[a];
        }
      }
    }
  }
}

}  // namespace maquette
