#include "render/sample_places.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/halo.h"
#include "core/tile.h"

namespace maquette {
namespace {

constexpr int kLattice = 32;  // lattice intervals per side
// Beyond this latitude longitudes bend too fast across a lattice interval to interpolate them
// (their error grows as the interval squared over the distance to the pole).
constexpr double kPolarLatitude = 80;
// A lattice whose rows or columns turn by more than this (radians) at a node is not smooth: on a
// polar face a diagonal crosses it (the places' rows turn there by tens of degrees on the ground).
// The ellipsoid's own bend, the interval over the earth's radius, reaches it only for intervals
// of 60 km.
constexpr double kKink = 1e-2;

// Whether `nodes` ((m + 1)^2, row-major) turn by more than kKink at a node along a row or column:
// the second difference of their places against the interval.
bool kinked(const std::vector<SamplePlace>& nodes, int m) {
  auto base = [&](int i, int j) { return nodes[size_t(j) * size_t(m + 1) + size_t(i)].base; };
  auto turns = [](const Vec3d& a, const Vec3d& b, const Vec3d& c) {
    double d2 = 0, step = 0;
    for (size_t k = 0; k < 3; ++k) {
      d2 += (a[k] - 2 * b[k] + c[k]) * (a[k] - 2 * b[k] + c[k]);
      step += (c[k] - a[k]) * (c[k] - a[k]) / 4;
    }
    return !(d2 <= kKink * kKink * step);
  };
  for (int j = 0; j <= m; ++j)
    for (int i = 1; i < m; ++i)
      if (turns(base(i - 1, j), base(i, j), base(i + 1, j)) ||
          turns(base(j, i - 1), base(j, i), base(j, i + 1)))
        return true;
  return false;
}

SamplePlace exact(const EnuFrame& frame, const EllipsoidalHeights& heights, LonLat p) {
  std::array<double, 9> axes{};
  const auto base = frame.to_enu(p.lon, p.lat, heights(p, 0), axes);
  return {p, base, {axes[2], axes[5], axes[8]}, true};  // column 2: the point's up
}

}  // namespace

SamplePlaces::SamplePlaces(const Grid& grid, CellId cell, int size, int halo, const EnuFrame& frame,
                           const EllipsoidalHeights& heights)
    : size_(size),
      halo_(halo),
      grid_(&grid),
      cell_(cell),
      frame_(frame),
      heights_(&heights),
      pixel_level_(cell.level() + log2_tile_size(size)),
      origin_(*pixel_source(grid, cell, size, 0, 0)),
      square_(grid.plane_square(cell)),
      border_(2 * size_t(halo) * size_t(size + 2 * halo) + 2 * size_t(halo) * size_t(size)) {
  for (int ring = 1; ring <= halo; ++ring)
    for (int k = -ring; k < size + ring; ++k)
      for (const auto& [col, row] : {std::pair{k, -ring}, std::pair{k, size + ring - 1},
                                     std::pair{-ring, k}, std::pair{size + ring - 1, k}})
        border_[border_slot(col, row)] = exact_place(col, row);
  // The lattice on the cell's own face: nodes at samples i (size - 1) / m, i = 0 .. m.
  const int m = std::min(kLattice, size - 1);
  double west = INFINITY, east = -INFINITY, poleward = 0;
  for (int j = 0; j <= m; ++j)
    for (int i = 0; i <= m; ++i) {
      const double step = m == 0 ? 0 : double(size - 1) / m;
      nodes_.push_back(exact(frame, heights,
                             face_point_lonlat(grid, origin_.face, double(origin_.col) + i * step,
                                               double(origin_.row) + j * step, pixel_level_)));
      west = std::min(west, nodes_.back().position.lon);
      east = std::max(east, nodes_.back().position.lon);
      poleward = std::max(poleward, std::abs(nodes_.back().position.lat));
    }
  if (m < 2 || east - west > 90 || poleward > kPolarLatitude || kinked(nodes_, m)) {
    nodes_.clear();  // every place exact, when asked
    return;
  }
  lattice_ = m;
  for (int k = 0; k < size; ++k) {
    const double t = double(k) * m / (size - 1);
    const int interval = std::min(m - 1, int(t));
    steps_.push_back({interval, t - interval});
  }
}

SamplePlace SamplePlaces::exact_place(int col, int row) const {
  SamplePlace s;
  const std::optional<FaceCoord> source = pixel_source(*grid_, cell_, size_, col, row);
  if (!source) return s;
  s = exact(frame_, *heights_, pixel_centre(*grid_, *source, pixel_level_));
  if (source->face == origin_.face && source->col == origin_.col + col &&
      source->row == origin_.row + row)
    s.plane = plane(col, row);
  return s;
}

size_t SamplePlaces::border_slot(int col, int row) const {
  const size_t side = size_t(size_ + 2 * halo_), ring = size_t(halo_);
  if (row < 0) return size_t(row + halo_) * side + size_t(col + halo_);
  if (row >= size_) return (ring + size_t(row - size_)) * side + size_t(col + halo_);
  return 2 * ring * side + size_t(row) * 2 * ring +
         (col < 0 ? size_t(col + halo_) : ring + size_t(col - size_));
}

PlanePoint SamplePlaces::plane(int col, int row) const {
  return {square_.x_min + (col + 0.5) * square_.side / size_,
          square_.y_max - (row + 0.5) * square_.side / size_};
}

// Inlined: out of line, the two calls per sample cost more than the interpolation they spare.
[[gnu::always_inline]] inline SamplePlaces::Corners SamplePlaces::corners(int col, int row) const {
  const int m = lattice_;
  const auto [j, fy] = steps_[size_t(row)];
  const auto [i, fx] = steps_[size_t(col)];
  return {{&nodes_[size_t(j * (m + 1) + i)], &nodes_[size_t(j * (m + 1) + i + 1)],
           &nodes_[size_t((j + 1) * (m + 1) + i)], &nodes_[size_t((j + 1) * (m + 1) + i + 1)]},
          {(1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy}};
}

[[gnu::always_inline]] inline void SamplePlaces::add_ground(const Corners& c, SamplePlace& s) {
  for (int k = 0; k < 4; ++k)
    for (size_t a = 0; a < 3; ++a) {
      s.base[a] += c.weight[k] * c.node[k]->base[a];
      s.up[a] += c.weight[k] * c.node[k]->up[a];
    }
}

SamplePlace SamplePlaces::at(int col, int row) const {
  if (col < 0 || row < 0 || col >= size_ || row >= size_) return border_[border_slot(col, row)];
  if (lattice_ == 0) return exact_place(col, row);
  const Corners c = corners(col, row);
  SamplePlace s;
  s.known = true;
  s.plane = plane(col, row);
  s.position = {0, 0};
  for (int k = 0; k < 4; ++k) {
    s.position.lon += c.weight[k] * c.node[k]->position.lon;
    s.position.lat += c.weight[k] * c.node[k]->position.lat;
  }
  add_ground(c, s);
  return s;
}

SamplePlace SamplePlaces::ground(int col, int row) const {
  if (col < 0 || row < 0 || col >= size_ || row >= size_ || lattice_ == 0) return at(col, row);
  SamplePlace s;
  s.known = true;
  add_ground(corners(col, row), s);
  return s;
}

}  // namespace maquette
