#include "render/rasterizer.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace maquette {
namespace {

constexpr int kSubpixelBits = 4;  // vertices snapped to 1/16 pixel
constexpr int64_t kOne = int64_t(1) << kSubpixelBits;
constexpr double kMaxPixels = double(1 << 22);
constexpr int kBandRows = 8;

struct ScreenVertex {
  int64_t x = 0, y = 0;  // 1/16 pixels
  double inv_z = 0;      // 1 / camera-frame z; 0: not drawable
};

// Twice the signed area of (a, b, p) in 1/256 square pixels: positive when p is left of a -> b
// in picture coordinates (y down), i.e. clockwise on the screen.
int64_t edge(const ScreenVertex& a, const ScreenVertex& b, int64_t px, int64_t py) {
  return (b.x - a.x) * (py - a.y) - (b.y - a.y) * (px - a.x);
}

// The top-left rule for a triangle of positive area (edge() > 0 inside, clockwise on the
// screen): a top edge is horizontal and goes right (the inside below it), a left edge goes up.
bool top_left(const ScreenVertex& a, const ScreenVertex& b) {
  return (a.y == b.y && b.x > a.x) || b.y < a.y;
}

}  // namespace

Fragments rasterize(const RenderMesh& mesh, const PinholeCamera& camera, double near) {
  const int w = camera.spec().width, h = camera.spec().height;
  const size_t vertex_count = mesh.positions.size() / 3;
  std::vector<ScreenVertex> screen(vertex_count);
  tbb::parallel_for(size_t(0), vertex_count, [&](size_t i) {
    const Vec3d v = camera.to_view(
        {mesh.positions[3 * i], mesh.positions[3 * i + 1], mesh.positions[3 * i + 2]});
    if (!(v[2] >= near)) return;
    const auto p = camera.to_pixel(v);
    if (!(std::abs(p[0]) < kMaxPixels && std::abs(p[1]) < kMaxPixels)) return;
    screen[i] = {std::llround(p[0] * kOne), std::llround(p[1] * kOne), 1 / v[2]};
  });

  // Triangles by the bands of rows their bounding boxes meet, in index order.
  const int bands = (h + kBandRows - 1) / kBandRows;
  std::vector<std::vector<uint32_t>> band_triangles(static_cast<size_t>(bands));
  for (size_t t = 0; t < mesh.triangle_count(); ++t) {
    const auto& a = screen[mesh.indices[3 * t]];
    const auto& b = screen[mesh.indices[3 * t + 1]];
    const auto& c = screen[mesh.indices[3 * t + 2]];
    if (a.inv_z == 0 || b.inv_z == 0 || c.inv_z == 0) continue;
    // Rows whose centre (row + 0.5) may be inside.
    const int64_t top = (std::min({a.y, b.y, c.y}) - kOne / 2 + kOne - 1) >> kSubpixelBits;
    const int64_t bottom = (std::max({a.y, b.y, c.y}) - kOne / 2) >> kSubpixelBits;
    const int64_t first = std::max<int64_t>(top, 0), last = std::min<int64_t>(bottom, h - 1);
    for (int64_t band = first / kBandRows; band <= last / kBandRows && first <= last; ++band)
      band_triangles[size_t(band)].push_back(uint32_t(t));
  }

  Fragments f;
  f.width = w;
  f.height = h;
  const size_t n = size_t(w) * size_t(h);
  f.triangle.assign(n, Fragments::kSky);
  f.depth.assign(n, std::numeric_limits<double>::infinity());
  f.b1.assign(n, 0);
  f.b2.assign(n, 0);
  tbb::parallel_for(0, bands, [&](int band) {
    const int row0 = band * kBandRows, row1 = std::min(h, row0 + kBandRows);
    for (const uint32_t t : band_triangles[size_t(band)]) {
      ScreenVertex v[3] = {screen[mesh.indices[3 * t]], screen[mesh.indices[3 * t + 1]],
                           screen[mesh.indices[3 * t + 2]]};
      int64_t area = edge(v[0], v[1], v[2].x, v[2].y);
      if (area == 0) continue;
      bool swapped = area < 0;  // keeps b1, b2 naming the triangle's own 2nd and 3rd vertex
      if (swapped) {
        std::swap(v[1], v[2]);
        area = -area;
      }
      const bool tl0 = top_left(v[1], v[2]), tl1 = top_left(v[2], v[0]), tl2 = top_left(v[0], v[1]);
      const int64_t xmin = std::min({v[0].x, v[1].x, v[2].x}),
                    xmax = std::max({v[0].x, v[1].x, v[2].x});
      const int64_t ymin = std::min({v[0].y, v[1].y, v[2].y}),
                    ymax = std::max({v[0].y, v[1].y, v[2].y});
      const int64_t c0 = std::max<int64_t>(0, (xmin - kOne / 2 + kOne - 1) >> kSubpixelBits);
      const int64_t c1 = std::min<int64_t>(w - 1, (xmax - kOne / 2) >> kSubpixelBits);
      const int64_t r0 = std::max<int64_t>(row0, (ymin - kOne / 2 + kOne - 1) >> kSubpixelBits);
      const int64_t r1 = std::min<int64_t>(row1 - 1, (ymax - kOne / 2) >> kSubpixelBits);
      for (int64_t r = r0; r <= r1; ++r) {
        const int64_t py = r * kOne + kOne / 2;
        for (int64_t c = c0; c <= c1; ++c) {
          const int64_t px = c * kOne + kOne / 2;
          const int64_t e0 = edge(v[1], v[2], px, py), e1 = edge(v[2], v[0], px, py),
                        e2 = edge(v[0], v[1], px, py);
          if (e0 < 0 || e1 < 0 || e2 < 0) continue;
          if ((e0 == 0 && !tl0) || (e1 == 0 && !tl1) || (e2 == 0 && !tl2)) continue;
          // Screen-space weights, then perspective-correct ones through 1/z.
          const double w0 = double(e0) / double(area) * v[0].inv_z,
                       w1 = double(e1) / double(area) * v[1].inv_z,
                       w2 = double(e2) / double(area) * v[2].inv_z;
          const double inv_z = w0 + w1 + w2;
          const double z = 1 / inv_z;
          const size_t i = size_t(r) * size_t(w) + size_t(c);
          if (!(z < f.depth[i])) continue;  // equal depth: the lower index, drawn first, stays
          f.depth[i] = z;
          f.triangle[i] = t;
          f.b1[i] = float((swapped ? w2 : w1) / inv_z);
          f.b2[i] = float((swapped ? w1 : w2) / inv_z);
        }
      }
    }
  });
  return f;
}

}  // namespace maquette
