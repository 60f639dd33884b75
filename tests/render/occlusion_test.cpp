// The rasterizer's occlusion culling (formats/render/rasterizer.h: the mesh's blocks of
// consecutive triangles left out whole when every pixel they could write is nearer) changes no
// bit: on hills seen from low down, where most triangles are hidden, the whole mesh's fragments
// are those of its blocks rasterized one at a time (nothing to hide them) and merged by the
// contract's rule, the nearer and on equal depth the lower triangle index; with the blocks the
// mesh says (a patch each) and without (kCullBlockTriangles consecutive ones). A strip of the
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
// along the last row and column: the triangle count is not a multiple of kCullBlockTriangles),
// each starting a block.
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
    for (int c0 = 0; c0 < kSquares; c0 += 4) {
      m.block_first.push_back(uint32_t(m.triangle_count()));
      for (int r = r0; r < std::min(kSquares, r0 + 4); ++r)
        for (int c = c0; c < std::min(kSquares, c0 + 4); ++c)
          m.indices.insert(m.indices.end(), {at(c, r), at(c + 1, r), at(c + 1, r + 1), at(c, r),
                                             at(c + 1, r + 1), at(c, r + 1)});
    }
  return m;
}

// The merge of `mesh`'s runs of triangles [bounds[k], bounds[k + 1]) each rasterized alone, by the
// contract's rule.
Fragments merged(const RenderMesh& mesh, const PinholeCamera& camera,
                 const std::vector<size_t>& bounds) {
  Fragments m;
  m.width = camera.spec().width;
  m.height = camera.spec().height;
  const size_t n = size_t(m.width) * size_t(m.height);
  m.triangle.assign(n, Fragments::kSky);
  m.depth.assign(n, INFINITY);
  m.b1.assign(n, 0);
  m.b2.assign(n, 0);
  for (size_t k = 0; k + 1 < bounds.size(); ++k) {
    RenderMesh run;
    run.positions = mesh.positions;
    run.indices.assign(mesh.indices.begin() + std::ptrdiff_t(3 * bounds[k]),
                       mesh.indices.begin() + std::ptrdiff_t(3 * bounds[k + 1]));
    const Fragments f = rasterize(run, camera);
    for (size_t i = 0; i < n; ++i) {
      if (f.triangle[i] == Fragments::kSky) continue;
      const uint32_t t = uint32_t(bounds[k]) + f.triangle[i];
      if (f.depth[i] < m.depth[i] || (f.depth[i] == m.depth[i] && t < m.triangle[i])) {
        m.triangle[i] = t;
        m.depth[i] = f.depth[i];
        m.b1[i] = f.b1[i];
        m.b2[i] = f.b2[i];
      }
    }
  }
  return m;
}

void expect_same(const Fragments& a, const Fragments& b) {
  const size_t n = a.triangle.size();
  ASSERT_EQ(n, b.triangle.size());
  EXPECT_TRUE(std::equal(a.triangle.begin(), a.triangle.end(), b.triangle.begin()));
  EXPECT_EQ(0, std::memcmp(a.depth.data(), b.depth.data(), n * sizeof(double)));
  EXPECT_EQ(0, std::memcmp(a.b1.data(), b.b1.data(), n * sizeof(float)));
  EXPECT_EQ(0, std::memcmp(a.b2.data(), b.b2.data(), n * sizeof(float)));
}

TEST(Occlusion, CulledBlocksChangeNoPixel) {
  // Low over the hills, looking level: fewer than half the triangles are seen.
  const PinholeCamera camera(CameraSpec{.eye = {-112.95, 37.25, 2000},
                                        .heading = 0,
                                        .pitch = -2,
                                        .fov = 60,
                                        .width = 320,
                                        .height = 200});
  const RenderMesh mesh = hills();
  const Fragments whole = rasterize(mesh, camera);
  const size_t n = whole.triangle.size();

  // The merge of the blocks drawn alone: the patches, and runs of kCullBlockTriangles (the last
  // shorter) for the same mesh without its blocks.
  std::vector<size_t> patches(mesh.block_first.begin(), mesh.block_first.end());
  patches.push_back(mesh.triangle_count());
  expect_same(merged(mesh, camera, patches), whole);
  RenderMesh runs = mesh;
  runs.block_first.clear();
  std::vector<size_t> bounds;
  for (size_t t = 0; t < runs.triangle_count(); t += kCullBlockTriangles) bounds.push_back(t);
  bounds.push_back(runs.triangle_count());
  expect_same(merged(runs, camera, bounds), rasterize(runs, camera));

  // The scene hides most of its triangles (what the culling is for) and shows terrain and sky.
  std::vector<bool> shown(mesh.triangle_count());
  size_t terrain = 0;
  for (const uint32_t t : whole.triangle)
    if (t != Fragments::kSky) shown[t] = true, ++terrain;
  const auto seen = size_t(std::count(shown.begin(), shown.end(), true));
  EXPECT_LT(seen, mesh.triangle_count() / 2) << seen << " of " << mesh.triangle_count();
  // And the occlusion test leaves blocks out (culling that never culls would pass the rest).
  EXPECT_GT(whole.culled_blocks, mesh.block_first.size() / 10)
      << whole.culled_blocks << " of " << mesh.block_first.size() << " blocks";
  EXPECT_GT(terrain, n / 4);
  EXPECT_LT(terrain, n - n / 10);

  // A strip of rows is those rows of the whole picture.
  const int first_row = 37, rows = 90;
  const Fragments strip = rasterize(mesh, camera, 1.0, first_row, rows);
  const size_t skip = size_t(first_row) * size_t(camera.spec().width), m = strip.triangle.size();
  ASSERT_EQ(size_t(rows) * size_t(camera.spec().width), m);
  EXPECT_TRUE(std::equal(strip.triangle.begin(), strip.triangle.end(),
                         whole.triangle.begin() + std::ptrdiff_t(skip)));
  EXPECT_EQ(0, std::memcmp(strip.depth.data(), &whole.depth[skip], m * sizeof(double)));
  EXPECT_EQ(0, std::memcmp(strip.b1.data(), &whole.b1[skip], m * sizeof(float)));
  EXPECT_EQ(0, std::memcmp(strip.b2.data(), &whole.b2[skip], m * sizeof(float)));

  // 1 and 2 threads: the same bits.
  Fragments one, two;
  tbb::task_arena(1).execute([&] { one = rasterize(mesh, camera); });
  tbb::task_arena(2).execute([&] { two = rasterize(mesh, camera); });
  expect_same(one, two);
  expect_same(one, whole);
}

}  // namespace
}  // namespace maquette
