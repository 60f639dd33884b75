#include "render/rasterizer.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/round_half_away.h"

namespace maquette {
namespace {

constexpr int kSubpixelBits = 4;  // vertices snapped to 1/16 pixel
constexpr int64_t kOne = int64_t(1) << kSubpixelBits;
constexpr double kMaxPixels = double(1 << 22);
constexpr int kBandRows = 8;

// No member initialisers: a plan's FreshArray of them is written whole by its tasks (no serial
// zeroing first); ScreenVertex{} is the undrawable one. 16 bytes: x and y within +-2^26 (kMaxPixels
// times kOne), widened to 64 bits in the edge functions.
struct ScreenVertex {
  int32_t x, y;  // 1/16 pixels
  double inv_z;  // 1 / camera-frame z; 0: not drawable
};

// A piece of a mesh triangle cut by the near plane: its corners on screen, and their barycentric
// weights in the mesh triangle (between its vertices' unit vectors where the near plane cut it).
struct ClippedTriangle {
  uint32_t triangle = 0;
  ScreenVertex v[3];
  std::array<double, 3> weights[3];
};

// Twice the signed area of (a, b, p) in 1/256 square pixels: positive when p is left of a -> b
// in picture coordinates (y down), i.e. clockwise on the screen.
int64_t edge(const ScreenVertex& a, const ScreenVertex& b, int64_t px, int64_t py) {
  return (int64_t(b.x) - a.x) * (py - a.y) - (int64_t(b.y) - a.y) * (px - a.x);
}

// The top-left rule for a triangle of positive area (edge() > 0 inside, clockwise on the
// screen): a top edge is horizontal and goes right (the inside below it), a left edge goes up.
bool top_left(const ScreenVertex& a, const ScreenVertex& b) {
  return (a.y == b.y && b.x > a.x) || b.y < a.y;
}

// The screen vertex of a camera-frame point at least `near` in front; inv_z 0 when too far off
// the picture for the integer edge functions.
inline ScreenVertex to_screen(const PinholeCamera& camera, const Vec3d& v) {
  const auto p = camera.to_pixel(v);
  if (!(std::abs(p[0]) < kMaxPixels && std::abs(p[1]) < kMaxPixels)) return {};
  return {int32_t(round_half_away(p[0] * kOne)), int32_t(round_half_away(p[1] * kOne)), 1 / v[2]};
}

// The pixels [first, last] whose centre (pixel + 0.5) lies within [lo, hi] (1/16 pixels), within
// [0, size).
inline std::pair<int64_t, int64_t> centre_span(int64_t lo, int64_t hi, int size) {
  const int64_t first = (lo - kOne / 2 + kOne - 1) >> kSubpixelBits;
  const int64_t last = (hi - kOne / 2) >> kSubpixelBits;
  return {std::max<int64_t>(first, 0), std::min<int64_t>(last, size - 1)};
}

// Rows [first, last] whose centre (row + 0.5) may be inside a triangle, within the picture.
inline std::pair<int64_t, int64_t> row_span(const ScreenVertex& a, const ScreenVertex& b,
                                            const ScreenVertex& c, int height) {
  return centre_span(std::min(a.y, std::min(b.y, c.y)), std::max(a.y, std::max(b.y, c.y)), height);
}

// Columns [first, last] whose centre (column + 0.5) may be inside a triangle, within the picture.
inline std::pair<int64_t, int64_t> column_span(const ScreenVertex& a, const ScreenVertex& b,
                                               const ScreenVertex& c, int width) {
  return centre_span(std::min(a.x, std::min(b.x, c.x)), std::max(a.x, std::max(b.x, c.x)), width);
}

// The nearest a pixel drawn from corners whose largest 1/z is `max_inv_z` can be: the nearest
// corner's depth less a margin far above the rounding of draw's perspective-correct depth. Both
// draw's test and a block's bound use it, so the bound is never farther than a depth draw writes.
inline double nearest_depth(double max_inv_z) { return (1 - 1e-12) / max_inv_z; }

// Draws triangle (v0, v1, v2), a piece of mesh triangle `t`, into rows [row0, row1); `weights`:
// its corners' barycentric weights in `t`, or nullptr for `t` itself (unit weights: the weights
// of the pixel's 2nd and 3rd corner are then the pixel's, the same bits as summing with zeros).
// Most triangles cover no pixel centre (smaller than a pixel): they leave before the edge set-up.
void draw(const ScreenVertex& v0, const ScreenVertex& v1, const ScreenVertex& v2,
          const std::array<double, 3>* weights, uint32_t t, int row0, int row1, Fragments& f) {
  auto [first, last] = row_span(v0, v1, v2, row1);
  first = std::max<int64_t>(first, row0);
  if (first > last) return;
  const auto [c0, c1] = column_span(v0, v1, v2, f.width);
  if (c0 > c1) return;
  int64_t area = edge(v0, v1, v2.x, v2.y);
  if (area == 0) return;
  // Clockwise on the screen: corner k is the given corner at[k] (the 2nd and 3rd swapped when
  // the given order is anticlockwise; a swap, so the given corner k is also at[k]).
  const bool swapped = area < 0;
  const int at[3] = {0, swapped ? 2 : 1, swapped ? 1 : 2};
  const ScreenVertex* given[3] = {&v0, &v1, &v2};
  const ScreenVertex* v[3] = {given[at[0]], given[at[1]], given[at[2]]};
  area = std::abs(area);
  const bool tl0 = top_left(*v[1], *v[2]), tl1 = top_left(*v[2], *v[0]),
             tl2 = top_left(*v[0], *v[1]);
  // The edge functions at the row's first centre, stepped along it by exact integer increments.
  const int64_t step[3] = {-(int64_t(v[2]->y) - v[1]->y) * kOne,
                           -(int64_t(v[0]->y) - v[2]->y) * kOne,
                           -(int64_t(v[1]->y) - v[0]->y) * kOne};
  // The nearest a pixel of the triangle can be: a pixel already nearer is kept without it.
  const double nearest = nearest_depth(std::max({v[0]->inv_z, v[1]->inv_z, v[2]->inv_z}));
  for (int64_t r = first; r <= last; ++r) {
    const int64_t py = r * kOne + kOne / 2, px0 = c0 * kOne + kOne / 2;
    int64_t e[3] = {edge(*v[1], *v[2], px0, py), edge(*v[2], *v[0], px0, py),
                    edge(*v[0], *v[1], px0, py)};
    // A row meets the (convex) triangle in one run of pixels: the first pixel past it ends the row.
    bool entered = false;
    for (int64_t c = c0; c <= c1; ++c, e[0] += step[0], e[1] += step[1], e[2] += step[2]) {
      if (e[0] < 0 || e[1] < 0 || e[2] < 0 || (e[0] == 0 && !tl0) || (e[1] == 0 && !tl1) ||
          (e[2] == 0 && !tl2)) {
        if (entered) break;
        continue;
      }
      entered = true;
      const size_t i = size_t(r - f.first_row) * size_t(f.width) + size_t(c);
      if (nearest > f.depth[i]) continue;
      // Screen-space weights, then perspective-correct ones through 1/z.
      double w[3], inv_z = 0;
      for (int k = 0; k < 3; ++k) {
        w[k] = double(e[k]) / double(area) * v[k]->inv_z;
        inv_z += w[k];
      }
      const double z = 1 / inv_z;
      // The nearer wins; on equal depth the lower triangle index, whatever the drawing order.
      if (z > f.depth[i] || (z == f.depth[i] && t >= f.triangle[i])) continue;
      double b1 = w[at[1]], b2 = w[at[2]];
      if (weights) {
        b1 = b2 = 0;
        for (int k = 0; k < 3; ++k) {
          b1 += w[k] * weights[at[k]][1];
          b2 += w[k] * weights[at[k]][2];
        }
      }
      f.depth[i] = z;
      f.triangle[i] = t;
      f.b1[i] = float(b1 / inv_z);
      f.b2[i] = float(b2 / inv_z);
    }
  }
}

// The pieces in front of the near plane of a mesh triangle with one or two corners behind it
// (Sutherland-Hodgman against z = near, in the camera frame), as a fan.
void clip(const PinholeCamera& camera, const Vec3d (&view)[3], uint32_t t, double near,
          std::vector<ClippedTriangle>& out) {
  std::vector<std::pair<Vec3d, std::array<double, 3>>> polygon;
  for (int k = 0; k < 3; ++k) {
    const Vec3d& a = view[k];
    const Vec3d& b = view[(k + 1) % 3];
    std::array<double, 3> wa{}, wb{};
    wa[size_t(k)] = 1;
    wb[size_t((k + 1) % 3)] = 1;
    if (a[2] >= near) polygon.emplace_back(a, wa);
    if ((a[2] >= near) != (b[2] >= near)) {
      const double s = (near - a[2]) / (b[2] - a[2]);
      Vec3d p;
      std::array<double, 3> wp;
      for (size_t j = 0; j < 3; ++j) {
        p[j] = a[j] + s * (b[j] - a[j]);
        wp[j] = wa[j] + s * (wb[j] - wa[j]);
      }
      p[2] = near;
      polygon.emplace_back(p, wp);
    }
  }
  std::vector<ScreenVertex> drawn;
  for (const auto& corner : polygon) {
    drawn.push_back(to_screen(camera, corner.first));
    if (drawn.back().inv_z == 0) return;
  }
  for (size_t k = 1; k + 1 < drawn.size(); ++k)
    out.push_back({t,
                   {drawn[0], drawn[k], drawn[k + 1]},
                   {polygon[0].second, polygon[k].second, polygon[k + 1].second}});
}

// A block of the mesh's consecutive triangles: the bounding box on screen (1/16 pixels; empty
// when none is drawable) and the nearest depth of those wholly in front of the near plane and
// drawable. No member initialisers: a plan's FreshArray of them is written whole by its tasks.
struct Block {
  int64_t x0, x1, y0, y1;
  double nearest;
};

// Whether every pixel of rows [row0, row1) whose centre lies within the bounding box [x0, x1] x
// [y0, y1] (1/16 pixels) is nearer than `nearest`: then a block of triangles none nearer than
// that writes none of them (draw keeps a pixel nearer than a triangle's nearest corner).
bool hidden(const Fragments& f, int row0, int row1, int64_t x0, int64_t x1, int64_t y0, int64_t y1,
            double nearest) {
  const auto [c0, c1] = centre_span(x0, x1, f.width);
  auto [r0, r1] = centre_span(y0, y1, row1);
  r0 = std::max<int64_t>(r0, row0);
  for (int64_t r = r0; r <= r1; ++r) {
    const double* d = &f.depth[size_t(r - f.first_row) * size_t(f.width)];
    for (int64_t c = c0; c <= c1; ++c)
      if (!(d[c] < nearest)) return false;
  }
  return true;
}

// The mesh's blocks (RenderMesh::block_first): block b is triangles [bounds[b], bounds[b + 1]).
std::vector<size_t> block_bounds(const RenderMesh& mesh) {
  std::vector<size_t> bounds;
  auto run = [&](size_t begin, size_t end) {
    for (size_t t = begin; t < end; t += kCullBlockTriangles) bounds.push_back(t);
  };
  size_t begin = 0;
  for (const uint32_t first : mesh.block_first) {
    if (first < begin || first > mesh.triangle_count())  // a precondition (rasterizer.h)
      throw std::logic_error("rasterize: block start " + std::to_string(first) + " after " +
                             std::to_string(begin) + " of " +
                             std::to_string(mesh.triangle_count()) + " triangles");
    run(begin, first);
    begin = first;
  }
  run(begin, mesh.triangle_count());
  bounds.push_back(mesh.triangle_count());
  return bounds;
}

}  // namespace

// The measured mesh (RasterPlan): its vertices on screen, its blocks and the pieces of the
// triangles the near plane cuts, sorted for drawing.
struct RasterPlan::Parts {
  const RenderMesh* mesh = nullptr;
  int width = 0, height = 0;
  FreshArray<ScreenVertex> screen;
  std::vector<size_t> bounds;
  FreshArray<Block> blocks;
  std::vector<ClippedTriangle> pieces;  // in triangle order
  std::vector<uint32_t> order;          // the blocks drawn, near to far
};

RasterPlan::RasterPlan(const RenderMesh& mesh, const PinholeCamera& camera, double near)
    : parts_(std::make_unique<Parts>()) {
  Parts& p = *parts_;
  p.mesh = &mesh;
  p.width = camera.spec().width;
  p.height = camera.spec().height;
  const size_t vertex_count = mesh.positions.size() / 3;
  auto view = [&](uint32_t v) {
    return camera.to_view({mesh.positions[3 * size_t(v)], mesh.positions[3 * size_t(v) + 1],
                           mesh.positions[3 * size_t(v) + 2]});
  };
  // Each vertex's place on screen when in front of the near plane, else undrawable (the camera
  // frame's points are found again for the few triangles with an undrawable corner). Sized, not
  // zeroed: the tasks write every vertex (no serial first touch of its pages).
  FreshArray<ScreenVertex>& screen = p.screen;
  screen.resize(vertex_count);
  tbb::parallel_for(size_t(0), vertex_count, [&](size_t i) {
    const Vec3d v = view(uint32_t(i));
    screen[i] = v[2] >= near ? to_screen(camera, v) : ScreenVertex{};
  });

  // The mesh's blocks (a terrain's patches of squares): each block's bounding box on screen and
  // nearest depth over its triangles wholly in front of the near plane and drawable (each block
  // written whole by its task), and the pieces of those the near plane cuts (each thread's own,
  // put in triangle order after).
  p.bounds = block_bounds(mesh);
  const std::vector<size_t>& bounds = p.bounds;
  FreshArray<Block>& blocks = p.blocks;
  blocks.resize(bounds.size() - 1);
  tbb::enumerable_thread_specific<std::vector<ClippedTriangle>> pieces;
  tbb::parallel_for(size_t(0), blocks.size(), [&](size_t b) {
    Block block{std::numeric_limits<int64_t>::max(), std::numeric_limits<int64_t>::min(),
                std::numeric_limits<int64_t>::max(), std::numeric_limits<int64_t>::min(), 0};
    double nearest_inv_z = 0;
    for (size_t t = bounds[b]; t < bounds[b + 1]; ++t) {
      const uint32_t* i = &mesh.indices[3 * t];
      const ScreenVertex* v[3] = {&screen[i[0]], &screen[i[1]], &screen[i[2]]};
      if (v[0]->inv_z != 0 && v[1]->inv_z != 0 && v[2]->inv_z != 0) {
        for (const ScreenVertex* c : v) {
          block.x0 = std::min<int64_t>(block.x0, c->x);
          block.x1 = std::max<int64_t>(block.x1, c->x);
          block.y0 = std::min<int64_t>(block.y0, c->y);
          block.y1 = std::max<int64_t>(block.y1, c->y);
          nearest_inv_z = std::max(nearest_inv_z, c->inv_z);
        }
        continue;
      }
      const Vec3d corners[3] = {view(i[0]), view(i[1]), view(i[2])};
      const int in_front =
          (corners[0][2] >= near) + (corners[1][2] >= near) + (corners[2][2] >= near);
      if (in_front == 1 || in_front == 2)  // 3: a corner too far off the picture
        clip(camera, corners, uint32_t(t), near, pieces.local());
    }
    // The nearest any of its pixels can be (infinite when none is drawable).
    block.nearest = nearest_depth(nearest_inv_z);
    blocks[b] = block;
  });

  // Near to far, each band's pieces of cut triangles (a triangle's in the order clip made them),
  // then its blocks by their nearest depth (the drawing order changes no pixel: the tie rule; the
  // order is a total one, so the parallel sort's result is the serial one's).
  for (const auto& local : pieces) p.pieces.insert(p.pieces.end(), local.begin(), local.end());
  std::stable_sort(
      p.pieces.begin(), p.pieces.end(),
      [](const ClippedTriangle& a, const ClippedTriangle& b) { return a.triangle < b.triangle; });
  for (size_t b = 0; b < blocks.size(); ++b)
    if (blocks[b].x0 <= blocks[b].x1) p.order.push_back(uint32_t(b));
  tbb::parallel_sort(p.order.begin(), p.order.end(), [&](uint32_t a, uint32_t b) {
    return blocks[a].nearest < blocks[b].nearest ||
           (blocks[a].nearest == blocks[b].nearest && a < b);
  });
}

RasterPlan::~RasterPlan() = default;

Fragments rasterize(const RenderMesh& mesh, const PinholeCamera& camera, double near, int first_row,
                    int rows) {
  Fragments f;
  rasterize(RasterPlan(mesh, camera, near), first_row, rows, f);
  return f;
}

void rasterize(const RasterPlan& plan, int first_row, int rows, Fragments& f) {
  const RasterPlan::Parts& p = *plan.parts_;
  const RenderMesh& mesh = *p.mesh;
  const std::vector<size_t>& bounds = p.bounds;
  const FreshArray<Block>& blocks = p.blocks;
  const FreshArray<ScreenVertex>& screen = p.screen;
  const int w = p.width, h = p.height;
  const int top = first_row, bottom = rows < 0 ? h : std::min(h, first_row + rows);
  // The pieces and blocks binned by the rows their bounding boxes meet, in the plan's order.
  const int bands = (bottom - top + kBandRows - 1) / kBandRows;
  std::vector<std::vector<const ClippedTriangle*>> band_pieces(static_cast<size_t>(bands));
  std::vector<std::vector<uint32_t>> band_blocks(static_cast<size_t>(bands));
  // The bands [first, last] (from `top`) holding the picture's `rows` [r0, r1] whose centres a
  // bounding box meets (centre_span), none when no pixel centre is within it (`columns` none).
  using Span = std::pair<int64_t, int64_t>;
  auto band_span = [&](Span rows, Span columns) {
    const int64_t first = std::max<int64_t>(rows.first, top) - top;
    const int64_t last = std::min<int64_t>(rows.second, bottom - 1) - top;
    if (first > last || columns.first > columns.second) return Span{1, 0};
    return Span{first / kBandRows, last / kBandRows};
  };
  for (const ClippedTriangle& c : p.pieces) {
    const auto [first, last] =
        band_span(row_span(c.v[0], c.v[1], c.v[2], h), column_span(c.v[0], c.v[1], c.v[2], w));
    for (int64_t band = first; band <= last; ++band) band_pieces[size_t(band)].push_back(&c);
  }
  for (const uint32_t b : p.order) {
    const Block& block = blocks[b];
    const auto [first, last] =
        band_span(centre_span(block.y0, block.y1, h), centre_span(block.x0, block.x1, w));
    for (int64_t band = first; band <= last; ++band) band_blocks[size_t(band)].push_back(b);
  }

  f.width = w;
  f.height = bottom - top;
  f.first_row = top;
  const size_t n = size_t(w) * size_t(f.height);
  // Each band clears its own rows before drawing them: fresh pages touched once, while in cache
  // (an earlier strip's arrays are resized within their capacity: no page given twice).
  resize_fresh(f.triangle, n);
  resize_fresh(f.depth, n);
  resize_fresh(f.b1, n);
  resize_fresh(f.b2, n);
  std::vector<size_t> culled(size_t(bands), 0);
  tbb::parallel_for(0, bands, [&](int band) {
    const int row0 = top + band * kBandRows, row1 = std::min(bottom, row0 + kBandRows);
    const size_t first = size_t(row0 - top) * size_t(w), count = size_t(row1 - row0) * size_t(w);
    std::fill_n(f.triangle.begin() + std::ptrdiff_t(first), count, Fragments::kSky);
    std::fill_n(f.depth.begin() + std::ptrdiff_t(first), count,
                std::numeric_limits<double>::infinity());
    std::fill_n(f.b1.begin() + std::ptrdiff_t(first), count, 0.0f);
    std::fill_n(f.b2.begin() + std::ptrdiff_t(first), count, 0.0f);
    for (const ClippedTriangle* c : band_pieces[size_t(band)]) {
      draw(c->v[0], c->v[1], c->v[2], c->weights, c->triangle, row0, row1, f);
    }
    for (const uint32_t b : band_blocks[size_t(band)]) {
      const Block& block = blocks[b];
      if (hidden(f, row0, row1, block.x0, block.x1, block.y0, block.y1, block.nearest)) {
        ++culled[size_t(band)];
        continue;
      }
      for (size_t t = bounds[b]; t < bounds[b + 1]; ++t) {
        const uint32_t* i = &mesh.indices[3 * t];
        const ScreenVertex &v0 = screen[i[0]], &v1 = screen[i[1]], &v2 = screen[i[2]];
        if (v0.inv_z != 0 && v1.inv_z != 0 && v2.inv_z != 0)
          draw(v0, v1, v2, nullptr, uint32_t(t), row0, row1, f);
      }
    }
  });
  f.culled_blocks = std::accumulate(culled.begin(), culled.end(), size_t(0));
}

}  // namespace maquette
