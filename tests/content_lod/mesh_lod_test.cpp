// Coarser levels of a mesh layer (content/content_overviews.h, gltf/mesh_simplify.h): about a
// quarter of the triangles per level, within the level's sample of the original surface
// (Hausdorff distance measured here, point to triangle), small objects dropped, textures halved,
// provenance kept, the same blobs for any order of cells and threads.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <random>

#include "../gltf_content/content_fixture.h"
#include "../store/store_test_util.h"
#include "content/content_blob.h"
#include "content/content_overviews.h"
#include "core/grid.h"
#include "gltf/mesh_glb.h"
#include "lod_fixture.h"
#include "run_cli.h"

namespace maquette::test {
namespace {

constexpr int kObjectsPerCell = 20;  // 320 objects over the 16 cells
constexpr int kTexture = 64;         // pixels across the base level's images

using Point = std::array<double, 3>;

Point vertex(const std::vector<float>& p, size_t v) {
  return {p[3 * v], p[3 * v + 1], p[3 * v + 2]};
}
Point sub(Point a, Point b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(Point a, Point b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Point add_scaled(Point a, Point d, double s) {
  return {a[0] + d[0] * s, a[1] + d[1] * s, a[2] + d[2] * s};
}

// A geodesic sphere: an octahedron whose triangles are split in four `splits` times, vertices
// pushed onto the sphere (8 * 4^splits triangles, each vertex shared by its triangles), with
// normals and spherical uvs.
MeshObject geodesic_sphere(std::array<float, 3> centre, float radius, int splits) {
  std::vector<Point> v{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  std::vector<uint32_t> idx{0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};
  for (int s = 0; s < splits; ++s) {
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> middle;
    const auto mid = [&](uint32_t a, uint32_t b) {
      const auto [it, added] = middle.try_emplace({std::min(a, b), std::max(a, b)}, 0);
      if (added) {
        Point m = add_scaled(v[a], v[b], 1);
        const double n = std::sqrt(dot(m, m));
        v.push_back({m[0] / n, m[1] / n, m[2] / n});
        it->second = uint32_t(v.size() - 1);
      }
      return it->second;
    };
    std::vector<uint32_t> next;
    for (size_t t = 0; t < idx.size(); t += 3) {
      const uint32_t a = idx[t], b = idx[t + 1], c = idx[t + 2];
      const uint32_t ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
      next.insert(next.end(), {a, ab, ca, ab, b, bc, ca, bc, c, ab, bc, ca});
    }
    idx = next;
  }
  MeshObject o;
  for (const Point& n : v) {
    for (int k = 0; k < 3; ++k) {
      o.positions.push_back(float(centre[size_t(k)] + radius * n[size_t(k)]));
      o.normals.push_back(float(n[size_t(k)]));
    }
    o.uvs.push_back(float(0.5 + std::atan2(n[1], n[0]) / (2 * M_PI)));
    o.uvs.push_back(float(std::acos(n[2]) / M_PI));
  }
  o.indices = idx;
  return o;
}

// The objects of one base cell: geodesic spheres (2048 triangles) of radii 2 to 14 m within
// 150 m of its centre, every other one textured, ids unique in the layer.
MeshContent cell_mesh(CellId cell) {
  std::mt19937_64 random(cell.id());
  std::uniform_real_distribution<float> xy(-150, 150), radius(2, 14);
  MeshContent c;
  c.origin = base_origin(cell);
  c.materials.push_back({"plaster", {0.8f, 0.7f, 0.6f, 1}, 0, 0.9f, "", "", false});
  c.materials.push_back(
      {"brick", {1, 1, 1, 1}, 0, 1, encoded_image("PNG", kTexture, kTexture), "image/png", false});
  for (int i = 0; i < kObjectsPerCell; ++i) {
    const float r = radius(random);
    MeshObject o = geodesic_sphere({xy(random), xy(random), r + 1}, r, 4);
    o.material = i % 2;
    o.provenance = {cell.id() * 100 + uint64_t(i), i, "test.domes", {{"r", r}}};
    c.objects.push_back(std::move(o));
  }
  return c;
}

void write_cells(Store& store, const std::vector<CellId>& cells) {
  Store::Batch batch(store);
  for (CellId cell : cells) batch.put_content("domes", cell, mesh_content_blob(cell_mesh(cell)));
  batch.commit();
}

MeshContent read(const Store& store, CellId cell) {
  const std::string blob = *store.get_content("domes", cell);
  const ContentEnvelope e = read_content_envelope(blob, cell.ToText());
  return decode_mesh_glb(content_payload(blob), e.origin, cell.ToText());
}

// Distance from p to triangle abc (closest point: Ericson, Real-Time Collision Detection 5.1.5).
double point_triangle(Point p, Point a, Point b, Point c) {
  const Point ab = sub(b, a), ac = sub(c, a), ap = sub(p, a);
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  Point q;
  if (d1 <= 0 && d2 <= 0) {
    q = a;
  } else {
    const Point bp = sub(p, b);
    const double d3 = dot(ab, bp), d4 = dot(ac, bp);
    const Point cp = sub(p, c);
    const double d5 = dot(ab, cp), d6 = dot(ac, cp);
    const double vc = d1 * d4 - d3 * d2, vb = d5 * d2 - d1 * d6, va = d3 * d6 - d5 * d4;
    if (d3 >= 0 && d4 <= d3)
      q = b;
    else if (d6 >= 0 && d5 <= d6)
      q = c;
    else if (vc <= 0 && d1 >= 0 && d3 <= 0)
      q = add_scaled(a, ab, d1 / (d1 - d3));
    else if (vb <= 0 && d2 >= 0 && d6 <= 0)
      q = add_scaled(a, ac, d2 / (d2 - d6));
    else if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)
      q = add_scaled(b, sub(c, b), (d4 - d3) / ((d4 - d3) + (d5 - d6)));
    else {
      const double denom = 1 / (va + vb + vc);
      q = add_scaled(add_scaled(a, ab, vb * denom), ac, vc * denom);
    }
  }
  const Point d = sub(p, q);
  return std::sqrt(dot(d, d));
}

// Points of a mesh's surface: its vertices and its triangles' centroids.
std::vector<Point> surface_points(const std::vector<Point>& v, const std::vector<uint32_t>& idx) {
  std::vector<Point> points = v;
  for (size_t t = 0; t + 2 < idx.size(); t += 3) {
    Point c{};
    for (int k = 0; k < 3; ++k) c = add_scaled(c, v[idx[t + k]], 1.0 / 3);
    points.push_back(c);
  }
  return points;
}

// The largest distance from a point of one mesh's surface to the other mesh, both ways.
double hausdorff(const std::vector<Point>& va, const std::vector<uint32_t>& ia,
                 const std::vector<Point>& vb, const std::vector<uint32_t>& ib) {
  const auto one_way = [](const std::vector<Point>& pts, const std::vector<Point>& v,
                          const std::vector<uint32_t>& idx) {
    double worst = 0;
    for (const Point& p : pts) {
      double best = INFINITY;
      for (size_t t = 0; t + 2 < idx.size(); t += 3)
        best = std::min(best, point_triangle(p, v[idx[t]], v[idx[t + 1]], v[idx[t + 2]]));
      worst = std::max(worst, best);
    }
    return worst;
  };
  return std::max(one_way(surface_points(va, ia), vb, ib), one_way(surface_points(vb, ib), va, ia));
}

double diagonal(const std::vector<Point>& v) {
  Point lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
  for (const Point& p : v)
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
  const Point d = sub(hi, lo);
  return std::sqrt(dot(d, d));
}

struct Original {
  EnuOrigin origin;
  MeshObject object;
};

std::map<uint64_t, Original> originals() {
  std::map<uint64_t, Original> all;
  for (CellId cell : base_cells()) {
    MeshContent c = cell_mesh(cell);
    for (MeshObject& o : c.objects) all[o.provenance.object_id] = {c.origin, std::move(o)};
  }
  return all;
}

TEST(MeshLod, QuarterTrianglesWithinTheSampleSmallObjectsDroppedTexturesHalved) {
  TempDir dir;
  auto store = content_store(dir.file("a.mqs"), "domes", LayerKind::Mesh);
  write_cells(*store, base_cells());
  update_content_overviews(*store, "domes");
  const auto all = originals();

  std::map<uint64_t, size_t> finer;       // triangles per object at the level below
  std::map<uint64_t, double> finer_size;  // their bounding boxes' diagonals there
  for (const auto& [id, o] : all) {
    finer[id] = o.object.indices.size() / 3;
    std::vector<Point> v;
    for (size_t i = 0; i < o.object.positions.size() / 3; ++i)
      v.push_back(vertex(o.object.positions, i));
    finer_size[id] = diagonal(v);
  }
  int levels_checked = 0;
  for (int level = kBaseLevel - 1; level >= 0; --level) {
    const double sample = default_grid().level_info(level, 1).cell_side_m / kContentSamples;
    std::map<uint64_t, size_t> here;
    std::map<uint64_t, double> here_size;
    size_t quartered = 0, quartered_below = 0;
    double worst_ratio_error = 0, worst_distance = 0;
    for (CellId cell : store->content_cells("domes", level)) {
      const MeshContent got = read(*store, cell);
      for (const MeshObject& o : got.objects) {
        const auto it = all.find(o.provenance.object_id);
        ASSERT_NE(it, all.end()) << o.provenance.object_id;
        EXPECT_EQ(o.provenance, it->second.object.provenance);
        here[o.provenance.object_id] = o.indices.size() / 3;
        // The original in this cell's frame (GeographicLib), and its distance to the result.
        std::vector<Point> original, simplified;
        for (size_t v = 0; v < it->second.object.positions.size() / 3; ++v)
          original.push_back(
              reframe(it->second.origin, got.origin, vertex(it->second.object.positions, v)));
        for (size_t v = 0; v < o.positions.size() / 3; ++v)
          simplified.push_back(vertex(o.positions, v));
        here_size[o.provenance.object_id] = diagonal(simplified);
        EXPECT_GE(finer_size[o.provenance.object_id], 0.99 * sample)
            << "an object smaller than the sample kept";
        const double d = hausdorff(original, it->second.object.indices, simplified, o.indices);
        worst_distance = std::max(worst_distance, d);
        EXPECT_LE(d, sample + 0.002) << "object " << o.provenance.object_id << " level " << level;
        // Textures: halved at every level above the base.
        ASSERT_GE(o.material, 0);
        const Material& m = got.materials[size_t(o.material)];
        if (it->second.object.material == 1) {
          const std::vector<uchar> bytes(m.image.begin(), m.image.end());
          const cv::Mat image = cv::imdecode(bytes, cv::IMREAD_UNCHANGED);
          EXPECT_EQ(image.cols, std::max(1, kTexture >> (kBaseLevel - level)));
          EXPECT_EQ(m.image_mime, "image/png");
        } else {
          EXPECT_TRUE(m.image.empty());
          EXPECT_EQ(m.name, "plaster");
        }
        if (finer[o.provenance.object_id] >= 64) {
          quartered += here[o.provenance.object_id];
          quartered_below += finer[o.provenance.object_id];
          const double ratio =
              double(here[o.provenance.object_id]) / double(finer[o.provenance.object_id]);
          worst_ratio_error = std::max(worst_ratio_error, std::abs(ratio - 0.25));
        }
      }
    }
    // Every object of the level below at least 2 % larger than the sample is kept (and none
    // smaller, above), its size measured there.
    for (const auto& [id, size] : finer_size)
      if (size > 1.02 * sample) {
        EXPECT_TRUE(here.contains(id)) << id << " level " << level;
      }
    if (quartered_below > 0) {
      ++levels_checked;
      // Each object's triangles: a quarter of the level below's, within 0.05.
      EXPECT_LE(worst_ratio_error, 0.05) << "level " << level;
      std::printf(
          "level %d: %zu objects, triangles %zu of %zu below (%.3f), worst %.3f m of "
          "%.2f m\n",
          level, here.size(), quartered, quartered_below,
          double(quartered) / double(quartered_below), worst_distance, sample);
    }
    finer = here;
    finer_size = here_size;
  }
  EXPECT_GE(levels_checked, 2);

  // `maquette info` counts the layer's level only, and lists the levels.
  const CliResult info = run_maquette("info --json " + dir.file("a.mqs"));
  ASSERT_EQ(info.exit_code, 0) << info.err;
  const auto j = nlohmann::json::parse(info.out);
  const auto& layer = j["layers"][0];
  EXPECT_EQ(layer["objects"], all.size());
  EXPECT_EQ(layer["triangles"], all.size() * 2048);
  EXPECT_EQ(layer["cells"], 16);
}

TEST(MeshLod, SameBlobsForAnyOrderOfCellsAndThreads) {
  TempDir dir;
  auto a = content_store(dir.file("a.mqs"), "domes", LayerKind::Mesh);
  write_cells(*a, base_cells());
  update_content_overviews(*a, "domes");

  const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
  auto b = content_store(dir.file("b.mqs"), "domes", LayerKind::Mesh);
  std::vector<CellId> cells = base_cells();
  std::reverse(cells.begin(), cells.end());
  write_cells(*b, {cells.begin(), cells.begin() + 7});
  update_content_overviews(*b, "domes");
  write_cells(*b, {cells.begin() + 7, cells.end()});
  update_content_overviews(*b, "domes");
  const auto blobs = overview_blobs(*a, "domes");
  EXPECT_GE(blobs.size(), 4u);
  EXPECT_TRUE(blobs == overview_blobs(*b, "domes"));
}

}  // namespace
}  // namespace maquette::test
