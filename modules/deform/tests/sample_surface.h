// A deformed mosaic's surface evaluated without the code under test: each sample at its position
// in a tangent plane (given by the test: the grid's pixel centre taken there by GeographicLib),
// the nearest sample found by walking from the last one (the samples need not form an affine
// grid: across a face seam they do not), the triangle holding the point among the squares near
// it, each split along its diagonal (col, row)-(col + 1, row + 1) as the solve triangulates, the
// height by barycentric weights.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <optional>

#include "core/tile.h"

namespace maquette::deform {

class SampleSurface {
 public:
  using Position = std::function<std::array<double, 2>(int col, int row)>;  // east, north (m)

  SampleSurface(Position at, const Tile<float>& out)
      : at_(std::move(at)), out_(out), col_(out.size() / 2), row_(out.size() / 2) {}

  double height(double e, double n) const {
    walk_to_nearest(e, n);
    for (int r0 = row_ - 2; r0 <= row_ + 1; ++r0)
      for (int c0 = col_ - 2; c0 <= col_ + 1; ++c0) {
        const std::array<std::array<int, 2>, 2> far = {{{c0 + 1, r0}, {c0, r0 + 1}}};
        for (const auto& v : far)
          if (const auto h = in_triangle({{{c0, r0}, v, {c0 + 1, r0 + 1}}}, e, n)) return *h;
      }
    ADD_FAILURE() << "no sample triangle holds (" << e << ", " << n << ")";
    return NAN;
  }

 private:
  double squared_distance(int c, int r, double e, double n) const {
    const auto p = at_(c, r);
    return (p[0] - e) * (p[0] - e) + (p[1] - n) * (p[1] - n);
  }

  void walk_to_nearest(double e, double n) const {
    const int last = out_.size() - 2;
    for (bool moved = true; moved;) {
      moved = false;
      double best = squared_distance(col_, row_, e, n);
      int bc = col_, br = row_;
      for (int dr = -1; dr <= 1; ++dr)
        for (int dc = -1; dc <= 1; ++dc) {
          const int c = std::clamp(col_ + dc, 1, last), r = std::clamp(row_ + dr, 1, last);
          if (const double d = squared_distance(c, r, e, n); d < best) best = d, bc = c, br = r;
        }
      moved = bc != col_ || br != row_;
      col_ = bc, row_ = br;
    }
  }

  std::optional<double> in_triangle(const std::array<std::array<int, 2>, 3>& v, double e,
                                    double n) const {
    const auto p0 = at_(v[0][0], v[0][1]), p1 = at_(v[1][0], v[1][1]), p2 = at_(v[2][0], v[2][1]);
    const double det = (p1[0] - p0[0]) * (p2[1] - p0[1]) - (p2[0] - p0[0]) * (p1[1] - p0[1]);
    const double w1 = ((e - p0[0]) * (p2[1] - p0[1]) - (p2[0] - p0[0]) * (n - p0[1])) / det;
    const double w2 = ((p1[0] - p0[0]) * (n - p0[1]) - (e - p0[0]) * (p1[1] - p0[1])) / det;
    const double w0 = 1 - w1 - w2;
    if (std::min({w0, w1, w2}) < -1e-12) return std::nullopt;
    return w0 * out_.at(v[0][0], v[0][1]) + w1 * out_.at(v[1][0], v[1][1]) +
           w2 * out_.at(v[2][0], v[2][1]);
  }

  Position at_;
  const Tile<float>& out_;
  mutable int col_, row_;  // the nearest sample of the last point asked
};

}  // namespace maquette::deform
