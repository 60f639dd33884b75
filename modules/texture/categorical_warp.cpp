#include "categorical_warp.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/error.h"

namespace maquette::texture {
namespace {

struct Octave {
  double spacing, amplitude;  // input pixels
};
// The coarse octave rounds a border's corners, the fine one roughens its straight runs.
constexpr Octave kOctaves[] = {{2, 0.5}, {1, 0.25}};
constexpr size_t kOctaveCount = std::size(kOctaves);

// A node's value in [-1, 1]: SplitMix64's finaliser of the node and the field (2 o + axis: the
// column or row warp of octave o).
double node_value(int64_t i, int64_t j, uint64_t field) {
  uint64_t z = uint64_t(i) * 0x9E3779B97F4A7C15ull ^ uint64_t(j) * 0xC2B2AE3D27D4EB4Full ^
               field * 0x165667B19E3779F9ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  z ^= z >> 31;
  return double(z >> 11) * 0x1.0p-52 - 1;  // 53 bits: [-1, 1)
}

// A coordinate in lattice units: its cell and the fade of its fraction across it.
struct Place {
  int64_t cell;
  double weight;
};
Place place(double u) {
  const double f = std::floor(u), t = u - f;
  return {int64_t(f), t * t * t * (t * (t * 6 - 15) + 10)};
}

// Value noise from the nodes around a point (n[j][i]: j along rows) and its places' weights.
double blend(double n00, double n10, double n01, double n11, double wu, double wv) {
  const double top = n00 + wu * (n10 - n00), bottom = n01 + wu * (n11 - n01);
  return top + wv * (bottom - top);
}

}  // namespace

std::array<double, 2> categorical_warp(double x, double y) {
  std::array<double, 2> d{0, 0};
  for (uint64_t axis = 0; axis < 2; ++axis)
    for (uint64_t o = 0; o < kOctaveCount; ++o) {
      const Place u = place(x / kOctaves[o].spacing), v = place(y / kOctaves[o].spacing);
      const uint64_t f = 2 * o + axis;
      d[axis] += kOctaves[o].amplitude *
                 blend(node_value(u.cell, v.cell, f), node_value(u.cell + 1, v.cell, f),
                       node_value(u.cell, v.cell + 1, f), node_value(u.cell + 1, v.cell + 1, f),
                       u.weight, v.weight);
    }
  return d;
}

void nearest_warped(const Tile<float>& tile, int64_t col0, int64_t row0, int refine, int ring,
                    Plane& out) {
  if (tile.halo() < kInputHalo)
    throw Error("texture: input tiles need a halo of " + std::to_string(kInputHalo) + " pixels");
  out.reshape(tile.size() << refine, ring);
  const int side = out.side();
  const double step = 1.0 / double(1 << refine);  // a target pixel in input pixels (exact)
  // Global input pixel coordinates of the target pixels' centres, exact (a face has < 2^31
  // input pixels a side), so every tiling reads the same input pixel: the same values as
  // categorical_warp's, with the nodes of each octave computed once per tile.
  std::vector<double> x(static_cast<size_t>(side)), y(x.size());
  for (int k = 0; k < side; ++k) {
    x[size_t(k)] = double(col0) + (k - ring + 0.5) * step;
    y[size_t(k)] = double(row0) + (k - ring + 0.5) * step;
  }
  struct Lattice {
    std::vector<Place> column, row;
    int64_t i0 = 0, j0 = 0;
    size_t width = 0;
    std::array<std::vector<double>, 2> node;  // per axis, (j - j0) * width + (i - i0)
  };
  std::array<Lattice, kOctaveCount> lattice;
  for (size_t o = 0; o < kOctaveCount; ++o) {
    Lattice& l = lattice[o];
    for (int k = 0; k < side; ++k) {
      l.column.push_back(place(x[size_t(k)] / kOctaves[o].spacing));
      l.row.push_back(place(y[size_t(k)] / kOctaves[o].spacing));
    }
    l.i0 = l.column.front().cell, l.j0 = l.row.front().cell;
    l.width = size_t(l.column.back().cell - l.i0 + 2);
    const size_t height = size_t(l.row.back().cell - l.j0 + 2);
    for (uint64_t axis = 0; axis < 2; ++axis) {
      l.node[axis].resize(l.width * height);
      for (size_t j = 0; j < height; ++j)
        for (size_t i = 0; i < l.width; ++i)
          l.node[axis][j * l.width + i] =
              node_value(l.i0 + int64_t(i), l.j0 + int64_t(j), 2 * o + axis);
    }
  }
  for (int r = 0; r < side; ++r)
    for (int c = 0; c < side; ++c) {
      std::array<double, 2> d{0, 0};
      for (size_t axis = 0; axis < 2; ++axis)
        for (size_t o = 0; o < kOctaveCount; ++o) {
          const Lattice& l = lattice[o];
          const Place u = l.column[size_t(c)], v = l.row[size_t(r)];
          const double* n = &l.node[axis][size_t(v.cell - l.j0) * l.width + size_t(u.cell - l.i0)];
          d[axis] += kOctaves[o].amplitude *
                     blend(n[0], n[1], n[l.width], n[l.width + 1], u.weight, v.weight);
        }
      out.at(c - ring, r - ring) = tile.at(int(int64_t(std::floor(x[size_t(c)] + d[0])) - col0),
                                           int(int64_t(std::floor(y[size_t(r)] + d[1])) - row0));
    }
}

}  // namespace maquette::texture
