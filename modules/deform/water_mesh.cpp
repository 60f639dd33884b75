#include "water_mesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <tuple>
#include <utility>

#include "core/error.h"

namespace maquette::deform {
namespace {

using Corner = std::pair<int64_t, int64_t>;  // (col, row) of the corner lattice

constexpr uint32_t kNone = UINT32_MAX;

// Vertices by corner, in dense tables over the lake's bounding box. Where only two diagonal
// pixels around a corner are wet (the lake touches itself there, 8-connected), each of them gets
// its own vertices at the corner, so that every edge stays in two triangles. The pixel a corner
// is used for is its quadrant: 0 (col - 1, row - 1), 1 (col, row - 1), 2 (col - 1, row), 3 (col,
// row).
class Builder {
 public:
  Builder(const BasinRaster& basin, const WaterBody& body) : basin_(basin), body_(body) {
    wet_.assign(size_t(basin.width) * size_t(basin.height), 0);
    col0_ = basin.width, row0_ = basin.height;
    int64_t col1 = 0, row1 = 0;
    for (const int64_t i : body.wet) {
      wet_[size_t(i)] = 1;
      col0_ = std::min(col0_, i % basin.width), col1 = std::max(col1, i % basin.width + 1);
      row0_ = std::min(row0_, i / basin.width), row1 = std::max(row1, i / basin.width + 1);
    }
    corners_across_ = col1 - col0_ + 1;
    top_.assign(size_t(corners_across_ * (row1 - row0_ + 1)), kNone);
    bottom_.assign(top_.size(), kNone);
  }

  bool wet(int64_t col, int64_t row) const {
    return col >= 0 && row >= 0 && col < basin_.width && row < basin_.height &&
           wet_[size_t(row) * size_t(basin_.width) + size_t(col)];
  }

  uint32_t top(Corner c, int quadrant) { return vertex(c, quadrant, true); }
  uint32_t bottom(Corner c, int quadrant) { return vertex(c, quadrant, false); }

  // The top vertex at corner p of a triangle whose other vertices are at a and b: its quadrant
  // is where the triangle's angle at p opens (the bisector of its two edges).
  uint32_t top_at(Corner p, Corner a, Corner b) {
    const double ac = double(a.first - p.first), ar = double(a.second - p.second);
    const double bc = double(b.first - p.first), br = double(b.second - p.second);
    const double la = std::hypot(ac, ar), lb = std::hypot(bc, br);
    const double dc = ac / la + bc / lb, dr = ar / la + br / lb;
    return top(p, (dr > 0 ? 2 : 0) + (dc > 0 ? 1 : 0));
  }

  void top_triangle(Corner a, Corner b, Corner c) {
    triangle(top_at(a, b, c), top_at(b, c, a), top_at(c, a, b));
  }

  void triangle(uint32_t a, uint32_t b, uint32_t c) {
    mesh_.indices.insert(mesh_.indices.end(), {a, b, c});
  }

  LakeMesh take() { return std::move(mesh_); }

 private:
  bool quadrant_wet(Corner c, int q) const {
    return wet(c.first - 1 + (q & 1), c.second - 1 + (q >> 1));
  }

  bool touches_itself(Corner c) const {
    const bool w0 = quadrant_wet(c, 0), w1 = quadrant_wet(c, 1), w2 = quadrant_wet(c, 2),
               w3 = quadrant_wet(c, 3);
    return (w0 && w3 && !w1 && !w2) || (w1 && w2 && !w0 && !w3);
  }

  uint32_t vertex(Corner c, int quadrant, bool top) {
    uint32_t& unsplit =
        (top ? top_ : bottom_)[size_t((c.second - row0_) * corners_across_ + (c.first - col0_))];
    if (unsplit != kNone) return unsplit;  // set only for a corner that is not split
    const int part = touches_itself(c) ? quadrant : -1;
    uint32_t& id = part < 0 ? unsplit : split_[std::tuple(c.first, c.second, part, top)].id;
    if (id != kNone) return id;
    id = uint32_t(mesh_.vertices.size());
    double height = body_.level;
    if (!top) {  // the mean terrain of the wet pixels around the corner (of the part's pixel)
      double sum = 0;
      int count = 0;
      for (int q = 0; q < 4; ++q)
        if ((part < 0 || q == part) && quadrant_wet(c, q)) {
          const size_t i = size_t(c.second - 1 + (q >> 1)) * size_t(basin_.width) +
                           size_t(c.first - 1 + (q & 1));
          sum += double(basin_.terrain[i]);
          ++count;
        }
      height = sum / count;
    }
    mesh_.vertices.push_back({double(c.first), double(c.second), height});
    return id;
  }

  // A corner used by one diagonal pixel of a self-touching corner: its own vertex, added on first
  // use (kNone until then).
  struct SplitId {
    uint32_t id = kNone;
  };

  const BasinRaster& basin_;
  const WaterBody& body_;
  std::vector<uint8_t> wet_;
  int64_t col0_ = 0, row0_ = 0, corners_across_ = 0;  // the bounding box's corner lattice
  std::vector<uint32_t> top_, bottom_;                // by corner, when not split
  std::map<std::tuple<int64_t, int64_t, int, bool>, SplitId> split_;
  LakeMesh mesh_;
};

// The top of the wet run [col0, col1) of `row`: the strip between its upper corner line (row) and
// its lower one (row + 1), each with the run's ends and every shoreline corner between them (a
// corner touching a dry pixel of the row above, resp. below), zipped into triangles: each step
// takes the next corner of the line whose new diagonal is the shorter, so that no triangle
// reaches further along the strip than it must (a run whose one line has many corners and the
// other few would otherwise fan long triangles from one corner, costly to voxelize). Each
// triangle has one side on a corner line and its third vertex on the other line: none is
// degenerate. Neighbouring strips hold the same corners on their shared line (a corner inside a
// run is on the shore when one of the two pixels left and right of it above or below is dry,
// whichever strip asks), so the top has no T-junction.
void top_strip(Builder& m, int64_t row, int64_t col0, int64_t col1) {
  const auto chain = [&](int64_t line, int64_t beyond) {
    std::vector<int64_t> cols{col0};
    for (int64_t c = col0 + 1; c < col1; ++c)
      if (!m.wet(c - 1, beyond) || !m.wet(c, beyond)) cols.push_back(c);
    cols.push_back(col1);
    return std::pair(line, cols);
  };
  const auto [upper_row, upper] = chain(row, row - 1);
  const auto [lower_row, lower] = chain(row + 1, row + 1);
  size_t i = 0, j = 0;
  // Counter-clockwise in (col, -row): the upper line's side left to right is followed by the
  // lower vertex, the lower line's side by the upper vertex.
  while (i + 1 < upper.size() || j + 1 < lower.size()) {
    const Corner u{upper[i], upper_row}, l{lower[j], lower_row};
    if (j + 1 == lower.size() || (i + 1 < upper.size() && std::abs(upper[i + 1] - lower[j]) <=
                                                              std::abs(lower[j + 1] - upper[i]))) {
      m.top_triangle(u, l, {upper[i + 1], upper_row});
      ++i;
    } else {
      m.top_triangle(l, {lower[j + 1], lower_row}, u);
      ++j;
    }
  }
}

}  // namespace

LakeMesh lake_mesh(const BasinRaster& basin, const WaterBody& body) {
  if (body.wet.empty()) throw Error("lake_mesh: an empty body");
  Builder m(basin, body);

  // Top: one strip per wet run of a row (body.wet is sorted: runs are consecutive indices).
  for (size_t k = 0; k < body.wet.size();) {
    size_t end = k + 1;
    while (end < body.wet.size() && body.wet[end] == body.wet[end - 1] + 1 &&
           body.wet[end] % basin.width != 0)
      ++end;
    const int64_t row = body.wet[k] / basin.width, col0 = body.wet[k] % basin.width;
    top_strip(m, row, col0, col0 + int64_t(end - k));
    k = end;
  }

  for (const int64_t i : body.wet) {
    const int64_t c = i % basin.width, r = i / basin.width;
    const Corner c00{c, r}, c10{c + 1, r}, c01{c, r + 1}, c11{c + 1, r + 1};
    // The pixel is quadrant 3 of its corner c00, 2 of c10, 1 of c01, 0 of c11.
    const auto quadrant = [&](Corner k) { return int(k.second == r) * 2 + int(k.first == c); };
    const auto bottom = [&](Corner k) { return m.bottom(k, quadrant(k)); };
    const auto top = [&](Corner k) { return m.top(k, quadrant(k)); };
    // Bottom, facing down.
    m.triangle(bottom(c00), bottom(c10), bottom(c11));
    m.triangle(bottom(c00), bottom(c11), bottom(c01));
    // Walls on the dry sides, along the shore with the water on the left seen from above.
    const std::array<std::pair<Corner, Corner>, 4> sides = {
        {{c01, c11}, {c11, c10}, {c10, c00}, {c00, c01}}};
    const std::array<bool, 4> dry = {!m.wet(c, r + 1), !m.wet(c + 1, r), !m.wet(c, r - 1),
                                     !m.wet(c - 1, r)};
    for (size_t s = 0; s < 4; ++s) {
      if (!dry[s]) continue;
      const auto [a, b] = sides[s];
      m.triangle(bottom(a), bottom(b), top(b));
      m.triangle(bottom(a), top(b), top(a));
    }
  }
  return m.take();
}

}  // namespace maquette::deform
