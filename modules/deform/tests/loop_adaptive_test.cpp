// Adaptive Loop subdivision: a conforming surface (no T-junction, no crack), neighbours at most
// one level apart, the same vertices as uniform Loop subdivision where refined, and a small
// fraction of the uniform triangle count for a 1 km feature on a 10 km region.
#include "../loop_adaptive.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <set>

#include "../loop_grid.h"
#include "../loop_marking.h"
#include "../loop_subdivision.h"

namespace maquette::deform {
namespace {

RegularHeightField rolling_terrain(int columns, int rows, double spacing) {
  RegularHeightField field{columns, rows, spacing, spacing, {}};
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < columns; ++c) {
      const double x = c * spacing;
      const double y = r * spacing;
      field.heights.push_back(1500.0 + 80.0 * std::sin(x / 700.0) * std::cos(y / 450.0) + 0.02 * x);
    }
  }
  return field;
}

// Checks, with no help from the subdivision's own bookkeeping, that the triangles form one
// oriented disc: every edge in one triangle (border) or two running along it in opposite
// directions, the border one closed loop, Euler characteristic V - E + F = 1, no two vertices at
// one place. A T-junction or a crack would open a hole: a second border loop.
void expect_conforming_disc(const TriangleMesh& mesh) {
  std::map<std::pair<int, int>, int> directed;  // (from, to) -> count
  for (const auto& t : mesh.triangles) {
    for (std::size_t i = 0; i < 3; ++i) ++directed[{t[i], t[(i + 1) % 3]}];
  }
  std::map<int, int> border_next;
  std::size_t edges = 0;
  for (const auto& [edge, count] : directed) {
    ASSERT_EQ(count, 1) << "edge " << edge.first << "-" << edge.second << " repeated";
    const bool paired = directed.contains({edge.second, edge.first});
    if (!paired || edge.first < edge.second) ++edges;
    if (!paired) {
      ASSERT_FALSE(border_next.contains(edge.first)) << "vertex " << edge.first;
      border_next[edge.first] = edge.second;
    }
  }
  std::set<int> used;
  for (const auto& t : mesh.triangles) used.insert(t.begin(), t.end());
  EXPECT_EQ(static_cast<long>(used.size()) - static_cast<long>(edges) +
                static_cast<long>(mesh.triangles.size()),
            1);
  std::size_t loop_length = 0;
  for (int v = border_next.begin()->first;;) {
    ++loop_length;
    ASSERT_TRUE(border_next.contains(v));
    v = border_next.at(v);
    if (v == border_next.begin()->first) break;
    ASSERT_LE(loop_length, border_next.size());
  }
  EXPECT_EQ(loop_length, border_next.size()) << "more than one border loop: a hole";
  std::vector<std::array<double, 3>> points;
  for (const int v : used) {
    points.push_back({mesh.vertices(v, 0), mesh.vertices(v, 1), mesh.vertices(v, 2)});
  }
  std::sort(points.begin(), points.end());
  EXPECT_EQ(std::adjacent_find(points.begin(), points.end()), points.end())
      << "two vertices at one place";
}

void expect_levels_one_apart(const TriangleMesh& mesh, const std::vector<int>& levels) {
  std::map<std::pair<int, int>, int> level_of_edge;
  int largest_gap = 0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (std::size_t i = 0; i < 3; ++i) {
      const int a = mesh.triangles[t][i];
      const int b = mesh.triangles[t][(i + 1) % 3];
      const auto other = level_of_edge.find({b, a});
      if (other != level_of_edge.end()) {
        largest_gap = std::max(largest_gap, std::abs(other->second - levels[t]));
      }
      level_of_edge[{a, b}] = levels[t];
    }
  }
  EXPECT_LE(largest_gap, 1);
}

struct Feature {
  TriangleMesh base;
  std::vector<bool> marked;
};

// A straight 1 km feature (a river, say) centred at `centre` (by default the region's middle),
// triangles within `band` metres of it marked.
Feature one_km_feature(const RegularHeightField& field, double band,
                       std::optional<Eigen::Vector2d> centre = std::nullopt) {
  Feature feature{height_field_mesh(field), {}};
  const Eigen::Vector2d middle = centre.value_or(Eigen::Vector2d(
      0.5 * (field.columns - 1) * field.spacing_x, -0.5 * (field.rows - 1) * field.spacing_y));
  const Eigen::Vector2d half(0.5 * 1000.0 * std::cos(0.4), 0.5 * 1000.0 * std::sin(0.4));
  const std::vector<Eigen::Vector2d> line{middle - half, middle + half};
  feature.marked = triangles_near_polyline(feature.base, line, band);
  // A feature off the region would leave every comparison trivially true.
  EXPECT_GT(std::count(feature.marked.begin(), feature.marked.end(), true), 100);
  return feature;
}

// Subdivides `feature` adaptively and uniformly 3 levels and compares them level by level.
void expect_conforming_and_equal_to_uniform(const Feature& feature, int columns, int rows) {
  const int levels = 3;
  const AdaptiveLoop adaptive = adaptive_loop_subdivide(feature.base, feature.marked, levels);
  ASSERT_EQ(adaptive.meshes.size(), static_cast<std::size_t>(levels + 1));
  TriangleMesh uniform = feature.base;
  GridNodes uniform_nodes = height_field_nodes(columns, rows);
  GridNodes adaptive_nodes = uniform_nodes;
  for (int level = 1; level <= levels; ++level) {
    LoopLevel uniform_level = loop_subdivide(uniform);
    uniform = std::move(uniform_level.mesh);
    uniform_nodes = finer_nodes(uniform_nodes, uniform_level.new_vertex_ends);
    adaptive_nodes =
        finer_nodes(adaptive_nodes, adaptive.new_vertex_ends[static_cast<std::size_t>(level - 1)]);
    const TriangleMesh& mesh = adaptive.meshes[static_cast<std::size_t>(level)];
    const auto& triangle_levels = adaptive.triangle_levels[static_cast<std::size_t>(level)];
    expect_conforming_disc(mesh);
    expect_levels_one_apart(mesh, triangle_levels);

    // Vertices of the finest triangles against the uniform mesh's vertex at the same node of
    // the level's grid (nodes from the topology: loop_grid.h).
    std::map<std::array<int, 2>, std::size_t> uniform_at;
    for (std::size_t v = 0; v < uniform_nodes.size(); ++v) uniform_at[uniform_nodes[v]] = v;
    ASSERT_EQ(uniform_at.size(), uniform_nodes.size());
    double largest = 0.0;
    std::size_t finest = 0;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      if (triangle_levels[t] != level) continue;
      ++finest;
      for (const int v : mesh.triangles[t]) {
        const auto found = uniform_at.find(adaptive_nodes[static_cast<std::size_t>(v)]);
        ASSERT_NE(found, uniform_at.end()) << "vertex " << v << " at level " << level;
        largest = std::max(largest, (mesh.vertices.row(v) -
                                     uniform.vertices.row(static_cast<Eigen::Index>(found->second)))
                                        .norm());
      }
    }
    const auto marked =
        static_cast<std::size_t>(std::count(feature.marked.begin(), feature.marked.end(), true));
    EXPECT_GE(finest, marked << (2 * level))
        << "the marked triangles are refined to level " << level;
    EXPECT_LE(largest, 1e-12) << "level " << level;
    std::printf(
        "level %d: %zu triangles (%zu of this level), uniform %zu, largest difference %.3g m\n",
        level, mesh.triangles.size(), finest, uniform.triangles.size(), largest);

    const auto& subdivision = adaptive.subdivisions[static_cast<std::size_t>(level - 1)];
    const Eigen::VectorXd row_sums = subdivision * Eigen::VectorXd::Ones(subdivision.cols());
    EXPECT_LE((row_sums.array() - 1.0).abs().maxCoeff(), 1e-15);
  }
}

TEST(AdaptiveLoop, ConformingAndEqualToUniformInsideTheRefinedZone) {
  // 1.5 km x 1.2 km at 30 m: the feature's band and its rings stay off the region's border.
  expect_conforming_and_equal_to_uniform(one_km_feature(rolling_terrain(51, 41, 30.0), 40.0), 51,
                                         41);
}

TEST(AdaptiveLoop, ConformingAndEqualToUniformAcrossTheBorder) {
  // The feature leaves the region through its west side, then through its south-west corner
  // (border masks, and the corner's vertices pulled off the grid, in the refined zone).
  expect_conforming_and_equal_to_uniform(
      one_km_feature(rolling_terrain(51, 41, 30.0), 40.0, Eigen::Vector2d(100.0, -600.0)), 51, 41);
  expect_conforming_and_equal_to_uniform(
      one_km_feature(rolling_terrain(51, 41, 30.0), 40.0, Eigen::Vector2d(0.0, -1199.0)), 51, 41);
}

TEST(AdaptiveLoop, OneKilometreFeatureOnTenKilometresKeepsFewTriangles) {
  // 10 km x 10 km at 30 m (SRTM's 1 arc-second), triangles within 60 m of the feature, 3 levels.
  const Feature feature = one_km_feature(rolling_terrain(335, 335, 30.0), 60.0);
  const int levels = 3;
  const AdaptiveLoop adaptive = adaptive_loop_subdivide(feature.base, feature.marked, levels);
  expect_conforming_disc(adaptive.meshes.back());
  expect_levels_one_apart(adaptive.meshes.back(), adaptive.triangle_levels.back());
  const double uniform = static_cast<double>(feature.base.triangles.size()) * (1 << (2 * levels));
  const double ratio = static_cast<double>(adaptive.meshes.back().triangles.size()) / uniform;
  std::printf("adaptive %zu triangles, uniform %.0f: %.2f %%\n",
              adaptive.meshes.back().triangles.size(), uniform, 100.0 * ratio);
  EXPECT_LE(ratio, 0.15);
}

TEST(AdaptiveLoop, KeptVerticesHaveIdentityRows) {
  const Feature feature = one_km_feature(rolling_terrain(51, 41, 30.0), 40.0);
  const AdaptiveLoop adaptive = adaptive_loop_subdivide(feature.base, feature.marked, 1);
  const SubdivisionMatrix& s = adaptive.subdivisions[0];
  // Far from the feature (the region's corner vertex 0) the row is the identity; on it, not.
  EXPECT_EQ(s.row(0).nonZeros(), 1);
  EXPECT_EQ(s.coeff(0, 0), 1.0);
  const auto marked = static_cast<std::size_t>(
      std::find(feature.marked.begin(), feature.marked.end(), true) - feature.marked.begin());
  const int on_feature = feature.base.triangles[marked][0];
  EXPECT_EQ(s.row(on_feature).nonZeros(), 7);  // valence 6 and itself
  EXPECT_GT(s.rows(), s.cols());
}

TEST(AdaptiveLoop, NothingMarkedKeepsTheBase) {
  const TriangleMesh base = height_field_mesh(rolling_terrain(9, 7, 30.0));
  const AdaptiveLoop adaptive =
      adaptive_loop_subdivide(base, std::vector<bool>(base.triangles.size(), false), 2);
  for (const TriangleMesh& mesh : adaptive.meshes) {
    EXPECT_EQ(mesh.triangles, base.triangles);
    EXPECT_EQ(mesh.vertices, base.vertices);
  }
  for (const SubdivisionMatrix& s : adaptive.subdivisions) {
    EXPECT_EQ(Eigen::MatrixXd(s), Eigen::MatrixXd::Identity(s.rows(), s.cols()));
  }
}

TEST(AdaptiveLoop, RefusesBadInput) {
  const Feature feature = one_km_feature(rolling_terrain(51, 41, 30.0), 40.0);
  EXPECT_THROW(adaptive_loop_subdivide(feature.base, feature.marked, 0), std::invalid_argument);
  EXPECT_THROW(adaptive_loop_subdivide(feature.base, std::vector<bool>(3, true), 1),
               std::invalid_argument);
}

}  // namespace
}  // namespace maquette::deform
