#include "water_mesh.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "core/error.h"

namespace maquette::deform {
namespace {

using Corner = std::pair<int64_t, int64_t>;  // (col, row) of the corner lattice

constexpr uint32_t kNone = UINT32_MAX;
// A vertex of the block before (on the block's first corner line): kForeign | its index in the
// block's list of them, until the blocks are joined.
constexpr uint32_t kForeign = 0x80000000u;
// Pixel rows per block: the unit of parallel work and of the vertices' numbering, fixed so that
// the mesh does not depend on the threads.
constexpr int64_t kBlockRows = 64;

// The lake's pixels as a raster, and the corner lattice of their bounding box.
struct WetRaster {
  WetRaster(const BasinRaster& basin, const WaterBody& body)
      : width(basin.width), height(basin.height) {
    wet.assign(size_t(width) * size_t(height), 0);
    col0 = width, row0 = height;
    for (const int64_t i : body.wet) {
      wet[size_t(i)] = 1;
      col0 = std::min(col0, i % width), col1 = std::max(col1, i % width + 1);
      row0 = std::min(row0, i / width), row1 = std::max(row1, i / width + 1);
    }
  }
  bool at(int64_t col, int64_t row) const {
    return col >= 0 && row >= 0 && col < width && row < height &&
           wet[size_t(row) * size_t(width) + size_t(col)];
  }

  int64_t width = 0, height = 0;
  std::vector<uint8_t> wet;
  int64_t col0 = 0, row0 = 0, col1 = 0, row1 = 0;  // the wet pixels' box: col1, row1 one past
};

// The vertices and triangles of the pixel rows [row_begin, row_end) of a lake, numbered in the
// order of first use, in dense tables over the block's corner lines. Where only two diagonal
// pixels around a corner are wet (the lake touches itself there, 8-connected), each of them gets
// its own vertices at the corner, so that every edge stays in two triangles. The pixel a corner
// is used for is its quadrant: 0 (col - 1, row - 1), 1 (col, row - 1), 2 (col - 1, row), 3 (col,
// row). A vertex on the block's first corner line that the rows above use too (a wet pixel of
// the row above touches it) is the block before's: referred to as kForeign | k (foreign()[k]).
class Builder {
 public:
  Builder(const WaterBody& body, const WetRaster& wet, double bottom, int64_t row_begin,
          int64_t row_end)
      : body_(body),
        wet_(wet),
        bottom_height_(bottom),
        line0_(row_begin),
        corners_across_(wet.col1 - wet.col0 + 1) {
    top_.assign(size_t(corners_across_ * (row_end - row_begin + 1)), kNone);
    bottom_.assign(top_.size(), kNone);
  }

  bool wet(int64_t col, int64_t row) const { return wet_.at(col, row); }

  uint32_t top(Corner c, int quadrant) { return vertex(c, quadrant, true); }
  uint32_t bottom(Corner c, int quadrant) { return vertex(c, quadrant, false); }

  // The quadrant of corner p's vertex for a triangle whose other vertices are at a and b: where
  // the triangle's angle at p opens (the bisector of its two edges).
  static int opening(Corner p, Corner a, Corner b) {
    const double ac = double(a.first - p.first), ar = double(a.second - p.second);
    const double bc = double(b.first - p.first), br = double(b.second - p.second);
    const double la = std::hypot(ac, ar), lb = std::hypot(bc, br);
    const double dc = ac / la + bc / lb, dr = ar / la + br / lb;
    return (dr > 0 ? 2 : 0) + (dc > 0 ? 1 : 0);
  }

  // Triangle (a, b, c) of the top and its mirror on the bottom (facing down). The
  // vertices are asked in a fixed order (c, b, a: the order the mesh was first built in; then
  // the bottom's), which numbers them, not in a function call's unspecified order of arguments.
  void top_triangle(Corner a, Corner b, Corner c) {
    const int qc = opening(c, a, b), qb = opening(b, c, a), qa = opening(a, b, c);
    const uint32_t vc = top(c, qc), vb = top(b, qb), va = top(a, qa);
    triangle(va, vb, vc);
    const uint32_t bc = bottom(c, qc), bb = bottom(b, qb), ba = bottom(a, qa);
    triangle(ba, bc, bb);
  }

  void triangle(uint32_t a, uint32_t b, uint32_t c) {
    mesh_.indices.insert(mesh_.indices.end(), {a, b, c});
  }

  // The block's own vertex at corner c (its part: -1 unsplit, else its quadrant) on its last
  // corner line, which the block after refers to.
  uint32_t own(const Corner& c, int part, bool top) const {
    const uint32_t id = part < 0 ? (top ? top_ : bottom_)[slot(c)]
                                 : split_.at(std::tuple(c.first, c.second, part, top)).id;
    if (id == kNone) throw std::logic_error("lake_mesh: a corner the block before did not use");
    return id;
  }

  struct ForeignVertex {
    Corner corner;
    int part = -1;
    bool top = false;
  };
  const std::vector<ForeignVertex>& foreign() const { return foreign_; }
  LakeMesh& mesh() { return mesh_; }

 private:
  size_t slot(const Corner& c) const {
    return size_t((c.second - line0_) * corners_across_ + (c.first - wet_.col0));
  }

  bool quadrant_wet(Corner c, int q) const {
    return wet(c.first - 1 + (q & 1), c.second - 1 + (q >> 1));
  }

  bool touches_itself(Corner c) const {
    const bool w0 = quadrant_wet(c, 0), w1 = quadrant_wet(c, 1), w2 = quadrant_wet(c, 2),
               w3 = quadrant_wet(c, 3);
    return (w0 && w3 && !w1 && !w2) || (w1 && w2 && !w0 && !w3);
  }

  // Most uses find the corner's vertex made already: that look-up stays inline, the first use
  // is a call (kept out of line: inlined, now that it is short, it made the mesh ~20 % slower).
  uint32_t vertex(Corner c, int quadrant, bool top) {
    const uint32_t unsplit = (top ? top_ : bottom_)[slot(c)];  // set only when not split
    return unsplit != kNone ? unsplit : first_use(c, quadrant, top);
  }

  [[gnu::noinline]] uint32_t first_use(Corner c, int quadrant, bool top) {
    uint32_t& unsplit = (top ? top_ : bottom_)[slot(c)];
    const int part = touches_itself(c) ? quadrant : -1;
    uint32_t& id = part < 0 ? unsplit : split_[std::tuple(c.first, c.second, part, top)].id;
    if (id != kNone) return id;
    const bool above = part < 0 ? quadrant_wet(c, 0) || quadrant_wet(c, 1) : part < 2;
    if (c.second == line0_ && above) {  // the block before's
      id = kForeign | uint32_t(foreign_.size());
      foreign_.push_back({c, part, top});
      return id;
    }
    id = uint32_t(mesh_.vertices.size());
    const double height = top ? body_.level : bottom_height_;
    mesh_.vertices.push_back({double(c.first), double(c.second), height});
    return id;
  }

  // A corner used by one diagonal pixel of a self-touching corner: its own vertex, added on first
  // use (kNone until then).
  struct SplitId {
    uint32_t id = kNone;
  };

  const WaterBody& body_;
  const WetRaster& wet_;
  const double bottom_height_;              // lake_flat_bottom
  int64_t line0_ = 0, corners_across_ = 0;  // the block's first corner line; the lattice's width
  std::vector<uint32_t> top_, bottom_;      // by corner of the block's lines, when not split
  std::map<std::tuple<int64_t, int64_t, int, bool>, SplitId> split_;
  std::vector<ForeignVertex> foreign_;
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

// The triangles of the wet pixels body.wet[begin, end) (whole rows): the top strips of their
// runs (with the bottom's), then each pixel's walls.
void block_triangles(Builder& m, const BasinRaster& basin, const WaterBody& body, size_t begin,
                     size_t end) {
  // Top: one strip per wet run of a row (body.wet is sorted: runs are consecutive indices).
  for (size_t k = begin; k < end;) {
    size_t run_end = k + 1;
    while (run_end < end && body.wet[run_end] == body.wet[run_end - 1] + 1 &&
           body.wet[run_end] % basin.width != 0)
      ++run_end;
    const int64_t row = body.wet[k] / basin.width, col0 = body.wet[k] % basin.width;
    top_strip(m, row, col0, col0 + int64_t(run_end - k));
    k = run_end;
  }
  for (size_t k = begin; k < end; ++k) {
    const int64_t c = body.wet[k] % basin.width, r = body.wet[k] / basin.width;
    const Corner c00{c, r}, c10{c + 1, r}, c01{c, r + 1}, c11{c + 1, r + 1};
    // The pixel is quadrant 3 of its corner c00, 2 of c10, 1 of c01, 0 of c11.
    const auto quadrant = [&](Corner q) { return int(q.second == r) * 2 + int(q.first == c); };
    const auto top = [&](Corner q) { return m.top(q, quadrant(q)); };
    const auto bottom = [&](Corner q) { return m.bottom(q, quadrant(q)); };
    // Walls on the dry sides, along the shore with the water on the left seen from above.
    const std::array<std::pair<Corner, Corner>, 4> sides = {
        {{c01, c11}, {c11, c10}, {c10, c00}, {c00, c01}}};
    const std::array<bool, 4> dry = {!m.wet(c, r + 1), !m.wet(c + 1, r), !m.wet(c, r - 1),
                                     !m.wet(c - 1, r)};
    for (size_t s = 0; s < 4; ++s) {
      if (!dry[s]) continue;
      const auto [a, b] = sides[s];
      // The bottom's corners were made by the strips: looked up.
      const uint32_t top_b = top(b), top_a = top(a), bottom_a = bottom(a), bottom_b = bottom(b);
      m.triangle(bottom_a, bottom_b, top_b);
      m.triangle(bottom_a, top_b, top_a);
    }
  }
}

}  // namespace

double lake_flat_bottom(const BasinRaster& basin, const WaterBody& body) {
  float lowest = INFINITY;
  for (const int64_t i : body.wet) lowest = std::min(lowest, basin.terrain[size_t(i)]);
  return double(lowest) - 1;
}

LakeMesh lake_mesh(const BasinRaster& basin, const WaterBody& body, double bottom) {
  if (body.wet.empty()) throw Error("lake_mesh: an empty body");
  const WetRaster wet(basin, body);
  // Blocks of kBlockRows pixel rows from the lake's first row, built in parallel; then joined in
  // block order, each block's vertices after those of the blocks before, its references to the
  // block before's vertices resolved.
  const size_t blocks = size_t((wet.row1 - wet.row0 + kBlockRows - 1) / kBlockRows);
  std::vector<std::unique_ptr<Builder>> built(blocks);
  tbb::parallel_for(size_t(0), blocks, [&](size_t b) {
    const int64_t row_begin = wet.row0 + int64_t(b) * kBlockRows;
    const int64_t row_end = std::min(wet.row1, row_begin + kBlockRows);
    const auto first = [&](int64_t row) {
      return size_t(std::lower_bound(body.wet.begin(), body.wet.end(), row * basin.width) -
                    body.wet.begin());
    };
    built[b] = std::make_unique<Builder>(body, wet, bottom, row_begin, row_end);
    block_triangles(*built[b], basin, body, first(row_begin), first(row_end));
  });
  // Each block's place in the whole known, the blocks are copied there in parallel too.
  std::vector<uint32_t> offset(blocks + 1, 0);
  std::vector<size_t> index_offset(blocks + 1, 0);
  for (size_t b = 0; b < blocks; ++b) {
    offset[b + 1] = offset[b] + uint32_t(built[b]->mesh().vertices.size());
    index_offset[b + 1] = index_offset[b] + built[b]->mesh().indices.size();
  }
  LakeMesh mesh;
  mesh.vertices.resize(offset.back());
  mesh.indices.resize(index_offset.back());
  tbb::parallel_for(size_t(0), blocks, [&](size_t b) {
    const LakeMesh& part = built[b]->mesh();
    std::copy(part.vertices.begin(), part.vertices.end(), mesh.vertices.begin() + offset[b]);
    uint32_t* out = mesh.indices.data() + index_offset[b];
    for (const uint32_t i : part.indices) {
      if (i & kForeign) {
        const Builder::ForeignVertex& v = built[b]->foreign()[i & ~kForeign];
        *out++ = offset[b - 1] + built[b - 1]->own(v.corner, v.part, v.top);
      } else {
        *out++ = i + offset[b];
      }
    }
  });
  return mesh;
}

}  // namespace maquette::deform
