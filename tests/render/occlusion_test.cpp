// The rasterizer's occlusion culling (formats/render/rasterizer.h: blocks of kCullBlockTriangles
// consecutive triangles left out whole when every pixel they could write is nearer) changes no
// bit: on hills seen from low down, where most triangles are hidden, the whole mesh's fragments
// are those of its blocks rasterized one at a time (nothing to hide them) and merged by the
// contract's rule, the nearer and on equal depth the lower triangle index. A strip of the
// picture is those rows of it, and 1 and 2 threads give the same bits (bands of many blocks).
#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "render/rasterizer.h"

namespace maquette {
namespace {

// A height field of kSquares x kSquares squares 20 m apart (ridges up to 300 m across the view),
// in front of an eye 250 m up, its triangles in patches of 4 x 4 squares (2 squares wide or tall
// along the last row and column: the triangle count is not a multiple of kCullBlockTriangles).
constexpr int kSquares = 98;

RenderMesh hills() {
  RenderMesh m;
  for (int r = 0; r <= kSquares; ++r)
    for (int c = 0; c <= kSquares; ++c) {
      const double x = 20.0 * (c - kSquares / 2), y = 200 + 20.0 * r;
      const double z = 150 * std::sin(y / 230) * std::cos(x / 400) + 150 * std::sin(y / 97) - 250;
      m.positions.insert(m.positions.end(), {x, y, z});
    }
  auto at = [](int c, int r) { return uint32_t(r * (kSquares + 1) + c); };
  for (int r0 = 0; r0 < kSquares; r0 += 4)
    for (int c0 = 0; c0 < kSquares; c0 += 4)
      for (int r = r0; r < std::min(kSquares, r0 + 4); ++r)
        for (int c = c0; c < std::min(kSquares, c0 + 4); ++c)
          m.indices.insert(m.indices.end(), {at(c, r), at(c + 1, r), at(c + 1, r + 1), at(c, r),
                                             at(c + 1, r + 1), at(c, r + 1)});
  return m;
}

TEST(Occlusion, CulledBlocksChangeNoPixel) {
  CameraSpec spec;
  spec.eye = {-112.95, 37.25, 2000};
  spec.heading = 0;
  spec.pitch = -2;
  spec.fov = 60;
  spec.width = 320;
  spec.height = 200;
  const PinholeCamera camera(spec);
  const RenderMesh mesh = hills();
  const Fragments whole = rasterize(mesh, camera);

  // The merge of the blocks drawn alone.
  const size_t n = whole.triangle.size();
  std::vector<uint32_t> triangle(n, Fragments::kSky);
  std::vector<double> depth(n, INFINITY);
  std::vector<float> b1(n, 0), b2(n, 0);
  for (size_t first = 0; first < mesh.triangle_count(); first += kCullBlockTriangles) {
    RenderMesh block;
    block.positions = mesh.positions;
    const size_t end = std::min(mesh.triangle_count(), first + kCullBlockTriangles);
    block.indices.assign(mesh.indices.begin() + std::ptrdiff_t(3 * first),
                         mesh.indices.begin() + std::ptrdiff_t(3 * end));
    const Fragments f = rasterize(block, camera);
    for (size_t i = 0; i < n; ++i) {
      if (f.triangle[i] == Fragments::kSky) continue;
      const uint32_t t = uint32_t(first) + f.triangle[i];
      if (f.depth[i] < depth[i] || (f.depth[i] == depth[i] && t < triangle[i])) {
        triangle[i] = t;
        depth[i] = f.depth[i];
        b1[i] = f.b1[i];
        b2[i] = f.b2[i];
      }
    }
  }
  EXPECT_TRUE(std::equal(triangle.begin(), triangle.end(), whole.triangle.begin()));
  EXPECT_EQ(0, std::memcmp(depth.data(), whole.depth.data(), n * sizeof(double)));
  EXPECT_EQ(0, std::memcmp(b1.data(), whole.b1.data(), n * sizeof(float)));
  EXPECT_EQ(0, std::memcmp(b2.data(), whole.b2.data(), n * sizeof(float)));

  // The scene hides most of its triangles (what the culling is for) and shows terrain and sky.
  std::vector<bool> shown(mesh.triangle_count());
  size_t terrain = 0;
  for (const uint32_t t : whole.triangle)
    if (t != Fragments::kSky) shown[t] = true, ++terrain;
  const auto seen = size_t(std::count(shown.begin(), shown.end(), true));
  EXPECT_LT(seen, mesh.triangle_count() / 2) << seen << " of " << mesh.triangle_count();
  EXPECT_GT(terrain, n / 4);
  EXPECT_LT(terrain, n - n / 10);

  // A strip of rows is those rows of the whole picture.
  const int first_row = 37, rows = 90;
  const Fragments strip = rasterize(mesh, camera, 1.0, first_row, rows);
  const size_t skip = size_t(first_row) * size_t(spec.width), m = strip.triangle.size();
  ASSERT_EQ(size_t(rows) * size_t(spec.width), m);
  EXPECT_TRUE(std::equal(strip.triangle.begin(), strip.triangle.end(),
                         whole.triangle.begin() + std::ptrdiff_t(skip)));
  EXPECT_EQ(0, std::memcmp(strip.depth.data(), &whole.depth[skip], m * sizeof(double)));
  EXPECT_EQ(0, std::memcmp(strip.b1.data(), &whole.b1[skip], m * sizeof(float)));
  EXPECT_EQ(0, std::memcmp(strip.b2.data(), &whole.b2[skip], m * sizeof(float)));

  // 1 and 2 threads: the same bits.
  Fragments one, two;
  tbb::task_arena(1).execute([&] { one = rasterize(mesh, camera); });
  tbb::task_arena(2).execute([&] { two = rasterize(mesh, camera); });
  EXPECT_TRUE(std::equal(one.triangle.begin(), one.triangle.end(), two.triangle.begin()));
  EXPECT_EQ(0, std::memcmp(one.depth.data(), two.depth.data(), n * sizeof(double)));
  EXPECT_EQ(0, std::memcmp(one.b1.data(), two.b1.data(), n * sizeof(float)));
  EXPECT_EQ(0, std::memcmp(one.b2.data(), two.b2.data(), n * sizeof(float)));
  EXPECT_TRUE(std::equal(one.triangle.begin(), one.triangle.end(), whole.triangle.begin()));
}

}  // namespace
}  // namespace maquette
