// Coarser levels of a mesh layer of solids (gltf/mesh_simplify.h): LoD1 buildings, prisms on
// footprints of 8 to 48 corners, 3 to 25 m tall, whose walls the level's error bound (up to half
// a sample: 17.6 m at level 11) could fold onto their roofs. Every object of every level, decoded
// from its stored GLB, is a closed, outward solid by CGAL's polygon mesh processing (the oracle
// of the structures tests; GPL, in this test binary only): a view from afar never sees through a
// roof. Shared vertices (welded) and corners split for facet normals (what structures.buildings
// writes) both: each level up simplifies both (facet normals' corners welded, within an eighth
// of the sample, the normals made again: every corner's normal its face's within 2 degrees).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

#include "../store/store_test_util.h"
#include "content/closed_solid.h"
#include "content/content_blob.h"
#include "content/content_overviews.h"
#include "content/facet_normals.h"
#include "gltf/mesh_glb.h"
#include "lod_fixture.h"
#include "tests/cgal_oracle.h"

namespace maquette::test {
namespace {

constexpr int kBuildingsPerCell = 12;  // 192 over the 16 cells

// A prism on a star-shaped footprint around (x, y): `corners` points at radii within
// [0.6, 1] * radius, the roof and floor fans around their centres; vertices shared.
MeshObject prism(std::mt19937_64& random, float x, float y, float radius, float height,
                 int corners) {
  std::uniform_real_distribution<float> reach(0.6f, 1);
  MeshObject o;
  const auto point = [&o](float px, float py, float pz) {
    for (float v : {px, py, pz}) o.positions.push_back(v);
  };
  point(x, y, 0);       // 0: floor centre
  point(x, y, height);  // 1: roof centre
  for (int i = 0; i < corners; ++i) {
    const double angle = 2 * M_PI * i / corners;
    const float r = radius * reach(random);
    const float px = x + r * float(std::cos(angle)), py = y + r * float(std::sin(angle));
    point(px, py, 0);       // 2 + 2i: floor corner
    point(px, py, height);  // 3 + 2i: roof corner
  }
  for (int i = 0; i < corners; ++i) {
    const uint32_t b0 = 2 + 2 * uint32_t(i), t0 = b0 + 1;
    const uint32_t b1 = 2 + 2 * uint32_t((i + 1) % corners), t1 = b1 + 1;
    // Counter-clockwise seen from outside: the ring turns counter-clockwise seen from above.
    for (uint32_t v : {1u, t0, t1, 0u, b1, b0, b0, b1, t1, b0, t1, t0}) o.indices.push_back(v);
  }
  return o;
}

MeshContent cell_buildings(CellId cell, bool facet_normals) {
  std::mt19937_64 random(cell.id());
  std::uniform_real_distribution<float> xy(-140, 140), radius(6, 40), height(3, 25);
  std::uniform_int_distribution<int> corners(8, 48);
  MeshContent c;
  c.origin = base_origin(cell);
  for (int i = 0; i < kBuildingsPerCell; ++i) {
    const float x = xy(random), y = xy(random), r = radius(random), h = height(random);
    MeshObject o = prism(random, x, y, r, h, corners(random));
    if (facet_normals) o = with_facet_normals(o);
    o.provenance = {
        cell.id() * 100 + uint64_t(i), i, "test.buildings", {{"corners", o.indices.size() / 12}}};
    c.objects.push_back(std::move(o));
  }
  return c;
}

// A unit cube at `at` (corners shared), counter-clockwise seen from outside.
MeshObject cube(std::array<float, 3> at) {
  MeshObject o;
  for (int v = 0; v < 8; ++v)
    for (int k = 0; k < 3; ++k) o.positions.push_back(at[size_t(k)] + float((v >> k) & 1));
  // Corner v is at x = bit 0, y = bit 1, z = bit 2.
  o.indices = {0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4,
               2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5};
  return o;
}

TEST(ClosedSolid, CubeClosedOutwardAndWhatBreaksIt) {
  const MeshObject box = cube({0, 0, 0});
  EXPECT_TRUE(is_closed_outward(box));
  EXPECT_FALSE(has_crossing_triangles(box));
  MeshObject inside_out = box;
  for (size_t t = 0; t < inside_out.indices.size(); t += 3)
    std::swap(inside_out.indices[t + 1], inside_out.indices[t + 2]);
  EXPECT_FALSE(is_closed_outward(inside_out));  // closed, negative volume
  MeshObject holed = box;
  holed.indices.resize(holed.indices.size() - 3);  // a triangle of a side gone
  EXPECT_FALSE(is_closed_outward(holed));
  EXPECT_FALSE(is_closed_outward(MeshObject{}));
  // Corners split per face (as for facet normals): still closed, as one point per position.
  MeshObject split;
  for (uint32_t i : box.indices) {
    split.indices.push_back(uint32_t(split.positions.size() / 3));
    split.positions.insert(split.positions.end(), &box.positions[3 * i], &box.positions[3 * i + 3]);
  }
  EXPECT_TRUE(is_closed_outward(split));
  // Two cubes as one object, the second through the first's corner (off the diagonals of its
  // faces): closed, outward, crossing; apart, they do not cross.
  for (const std::array<float, 3> at : {std::array<float, 3>{0.5f, 0.3f, 0.1f}, {2, 2, 2}}) {
    MeshObject two = box;
    const MeshObject other = cube(at);
    for (uint32_t i : other.indices) two.indices.push_back(i + 8);
    two.positions.insert(two.positions.end(), other.positions.begin(), other.positions.end());
    EXPECT_TRUE(is_closed_outward(two));
    EXPECT_EQ(has_crossing_triangles(two), at[0] < 1) << at[0];
  }
  // A fin (a triangle and its reverse) on the cube: not closed; without it, the cube's triangles.
  MeshObject finned = box;
  finned.positions.insert(finned.positions.end(), {0.5f, 0.5f, 3});
  finned.indices.insert(finned.indices.begin() + 6, {4, 5, 8});
  finned.indices.insert(finned.indices.end(), {5, 4, 8});
  EXPECT_FALSE(is_closed_outward(finned));
  EXPECT_EQ(without_fins(finned), box.indices);
}

// Every corner of every triangle of `o` at least 10 cm high carries the normal of its face within
// 2 degrees (the GLB's quantized normals; the simplified solid's facet normals are made again
// for its faces).
void expect_facet_normals(const MeshObject& o, int level) {
  ASSERT_EQ(o.normals.size(), o.positions.size());
  size_t bad = 0;
  for (size_t t = 0; t < o.indices.size(); t += 3) {
    std::array<std::array<double, 3>, 3> p;
    for (size_t k = 0; k < 3; ++k)
      for (size_t i = 0; i < 3; ++i) p[k][i] = o.positions[3 * o.indices[t + k] + i];
    const std::array<double, 3> a{p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2]},
        b{p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2]};
    const std::array<double, 3> n{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                                  a[0] * b[1] - a[1] * b[0]};
    const double length = std::hypot(n[0], n[1], n[2]);
    // A triangle under 10 cm high: the GLB's 1 mm positions turn its face by more than the
    // tolerance.
    const double longest = std::max({std::hypot(a[0], a[1], a[2]), std::hypot(b[0], b[1], b[2]),
                                     std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2])});
    if (length / longest < 0.1) continue;
    for (size_t k = 0; k < 3; ++k) {
      const float* m = &o.normals[3 * o.indices[t + k]];
      bad += (m[0] * n[0] + m[1] * n[1] + m[2] * n[2]) / length < std::cos(2 * M_PI / 180);
    }
  }
  EXPECT_EQ(bad, 0u) << "object " << o.provenance.object_id << " at level " << level;
}

void check_levels(bool facet_normals) {
  TempDir dir;
  auto store = content_store(dir.file("a.mqs"), "buildings", LayerKind::Mesh);
  {
    Store::Batch batch(*store);
    for (CellId cell : base_cells())
      batch.put_content("buildings", cell, mesh_content_blob(cell_buildings(cell, facet_normals)));
    batch.commit();
  }
  update_content_overviews(*store, "buildings");
  size_t base_triangles = 0;
  for (CellId cell : base_cells())
    for (const MeshObject& o : cell_buildings(cell, facet_normals).objects)
      base_triangles += o.indices.size() / 3;
  int levels = 0;
  size_t previous = base_triangles;
  for (int level = kBaseLevel - 1; level >= kBaseLevel - 5; --level) {
    size_t objects = 0, triangles = 0, solids = 0;
    for (CellId cell : store->content_cells("buildings", level)) {
      const std::string blob = *store->get_content("buildings", cell);
      const ContentEnvelope e = read_content_envelope(blob, cell.ToText());
      for (const MeshObject& o : decode_mesh_glb(content_payload(blob), e.origin, "").objects) {
        ++objects;
        triangles += o.indices.size() / 3;
        const std::vector<double> positions(o.positions.begin(), o.positions.end());
        const structures::CgalVerdict v = structures::cgal_verdict(positions, o.indices);
        const bool solid = v.polygon_mesh && v.closed && !v.self_intersects && v.outward;
        solids += solid;
        EXPECT_TRUE(solid) << "object " << o.provenance.object_id << " at level " << level
                           << ": polygon mesh " << v.polygon_mesh << ", closed " << v.closed
                           << ", self-intersecting " << v.self_intersects << ", outward "
                           << v.outward;
        EXPECT_GT(v.volume, 0);
        if (facet_normals) expect_facet_normals(o, level);
      }
    }
    if (objects == 0) continue;
    ++levels;
    std::printf("facet normals %d, level %d: %zu objects, %zu solids, %zu triangles of %zu\n",
                int(facet_normals), level, objects, solids, triangles, base_triangles);
    // Each level up simplifies further (corners split or not), to under half of the base's by
    // level 11 (within an eighth of the sample, split corners go slower).
    EXPECT_LT(triangles, previous) << level;
    if (level == kBaseLevel - 3) {
      EXPECT_LT(2 * triangles, base_triangles);
    }
    previous = triangles;
  }
  EXPECT_EQ(levels, 5);
}

TEST(SolidLod, SharedVerticesEveryLevelsObjectAClosedOutwardSolid) { check_levels(false); }

TEST(SolidLod, FacetNormalsEveryLevelsObjectAClosedOutwardSolid) { check_levels(true); }

}  // namespace
}  // namespace maquette::test
