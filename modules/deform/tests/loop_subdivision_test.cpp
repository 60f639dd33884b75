// Uniform Loop subdivision against OpenMesh's LoopT (the oracle: an independent implementation
// on a half-edge mesh), on a height field with border and on a closed mesh, 1 to 3 levels.
#include "../loop_subdivision.h"

#include <gtest/gtest.h>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/LoopT.hh>
#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <utility>

#include "../loop_grid.h"

namespace maquette::deform {
namespace {

struct DoubleTraits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using OpenMeshSurface = OpenMesh::TriMesh_ArrayKernelT<DoubleTraits>;

OpenMeshSurface to_openmesh(const TriangleMesh& mesh) {
  OpenMeshSurface om;
  std::vector<OpenMeshSurface::VertexHandle> handles;
  for (Eigen::Index v = 0; v < mesh.vertices.rows(); ++v) {
    handles.push_back(om.add_vertex(
        OpenMesh::Vec3d(mesh.vertices(v, 0), mesh.vertices(v, 1), mesh.vertices(v, 2))));
  }
  for (const auto& t : mesh.triangles) {
    om.add_face(handles[static_cast<std::size_t>(t[0])], handles[static_cast<std::size_t>(t[1])],
                handles[static_cast<std::size_t>(t[2])]);
  }
  return om;
}

std::vector<std::array<int, 3>> triangles_of(const OpenMeshSurface& om) {
  std::vector<std::array<int, 3>> triangles;
  for (const auto face : om.faces()) {
    std::array<int, 3> t{};
    std::size_t i = 0;
    for (const auto v : om.fv_range(face)) t[i++] = v.idx();
    triangles.push_back(t);
  }
  return triangles;
}

// After one subdivision of a mesh of `old_count` vertices, each new vertex lies on an edge of
// the coarser mesh: its only neighbours among the old vertices are that edge's ends.
std::map<int, std::pair<int, int>> new_vertex_edges(
    const std::vector<std::array<int, 3>>& triangles, int old_count) {
  std::map<int, std::set<int>> old_neighbours;
  for (const auto& t : triangles) {
    for (std::size_t i = 0; i < 3; ++i) {
      const int v = t[i];
      for (const int w : {t[(i + 1) % 3], t[(i + 2) % 3]}) {
        if (v >= old_count && w < old_count) old_neighbours[v].insert(w);
      }
    }
  }
  std::map<int, std::pair<int, int>> edges;
  for (const auto& [v, ends] : old_neighbours) {
    EXPECT_EQ(ends.size(), 2u) << "new vertex " << v;
    edges[v] = {*ends.begin(), *ends.rbegin()};
  }
  return edges;
}

// Subdivides `base` `levels` times with loop_subdivide and with LoopT, pairing the vertices
// level by level (old vertices keep their index in both; new ones by their edge), and returns the
// largest distance between paired vertices. Also checks the triangles are the same.
double largest_difference_to_openmesh(const TriangleMesh& base, int levels) {
  OpenMeshSurface om = to_openmesh(base);
  OpenMesh::Subdivider::Uniform::LoopT<OpenMeshSurface, double> loop;
  TriangleMesh mine = base;
  std::vector<int> to_om(static_cast<std::size_t>(base.vertices.rows()));
  for (std::size_t v = 0; v < to_om.size(); ++v) to_om[v] = static_cast<int>(v);
  for (int level = 1; level <= levels; ++level) {
    const auto old_count = static_cast<int>(mine.vertices.rows());
    loop.attach(om);
    loop(1);
    loop.detach();
    LoopLevel fine = loop_subdivide(mine);
    EXPECT_EQ(fine.mesh.vertices.rows(), static_cast<Eigen::Index>(om.n_vertices()));
    EXPECT_EQ(fine.mesh.triangles.size(), om.n_faces());
    std::map<std::pair<int, int>, int> om_vertex_of_edge;
    for (const auto& [v, ends] : new_vertex_edges(triangles_of(om), old_count)) {
      om_vertex_of_edge[ends] = v;
    }
    to_om.resize(static_cast<std::size_t>(fine.mesh.vertices.rows()));
    for (const auto& [v, ends] : new_vertex_edges(fine.mesh.triangles, old_count)) {
      const int a = to_om[static_cast<std::size_t>(ends.first)];
      const int b = to_om[static_cast<std::size_t>(ends.second)];
      const auto found = om_vertex_of_edge.find({std::min(a, b), std::max(a, b)});
      EXPECT_NE(found, om_vertex_of_edge.end()) << "edge of new vertex " << v;
      if (found != om_vertex_of_edge.end()) to_om[static_cast<std::size_t>(v)] = found->second;
    }
    std::set<std::array<int, 3>> om_triangles;
    for (auto t : triangles_of(om)) {
      std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
      om_triangles.insert(t);
    }
    for (const auto& t : fine.mesh.triangles) {
      std::array<int, 3> mapped{};
      for (std::size_t i = 0; i < 3; ++i) mapped[i] = to_om[static_cast<std::size_t>(t[i])];
      std::rotate(mapped.begin(), std::min_element(mapped.begin(), mapped.end()), mapped.end());
      EXPECT_TRUE(om_triangles.contains(mapped)) << "level " << level;
    }
    mine = std::move(fine.mesh);
  }
  double largest = 0.0;
  for (Eigen::Index v = 0; v < mine.vertices.rows(); ++v) {
    const auto p = om.point(OpenMeshSurface::VertexHandle(to_om[static_cast<std::size_t>(v)]));
    largest =
        std::max(largest, (mine.vertices.row(v) - Eigen::RowVector3d(p[0], p[1], p[2])).norm());
  }
  return largest;
}

TriangleMesh sample_height_field() {
  RegularHeightField field{7, 5, 30.0, 20.0, {}};
  for (int r = 0; r < field.rows; ++r) {
    for (int c = 0; c < field.columns; ++c) {
      field.heights.push_back(1200.0 + 35.0 * std::sin(0.9 * c) * std::cos(1.3 * r) + 4.0 * c * r);
    }
  }
  return height_field_mesh(field);
}

// A cube, each face cut by a diagonal (valences 3 to 6), its corners moved off the cube.
TriangleMesh closed_mesh() {
  TriangleMesh mesh;
  mesh.vertices.resize(8, 3);
  for (int v = 0; v < 8; ++v) {
    mesh.vertices.row(v) << (v & 1) * 10.0 + 0.7 * std::sin(v), ((v >> 1) & 1) * 10.0 + 0.3 * v,
        ((v >> 2) & 1) * 10.0 - 0.5 * std::cos(2.0 * v);
  }
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    mesh.triangles.push_back({q[0], q[1], q[2]});
    mesh.triangles.push_back({q[0], q[2], q[3]});
  }
  return mesh;
}

TEST(LoopSubdivision, HeightFieldEqualsOpenMeshLoopT) {
  for (int levels = 1; levels <= 3; ++levels) {
    EXPECT_LE(largest_difference_to_openmesh(sample_height_field(), levels), 1e-9)
        << levels << " levels";
  }
}

TEST(LoopSubdivision, ClosedMeshEqualsOpenMeshLoopT) {
  for (int levels = 1; levels <= 3; ++levels) {
    EXPECT_LE(largest_difference_to_openmesh(closed_mesh(), levels), 1e-9) << levels << " levels";
  }
}

TEST(LoopSubdivision, MatrixRowsAreAffineCombinations) {
  const LoopLevel fine = loop_subdivide(sample_height_field());
  const Eigen::VectorXd row_sums =
      fine.subdivision * Eigen::VectorXd::Ones(fine.subdivision.cols());
  EXPECT_LE((row_sums.array() - 1.0).abs().maxCoeff(), 1e-15);
  EXPECT_EQ(fine.subdivision.rows(), fine.mesh.vertices.rows());
}

TEST(LoopSubdivision, HeightFieldTriangulation) {
  const TriangleMesh mesh = sample_height_field();
  ASSERT_EQ(mesh.vertices.rows(), 35);
  ASSERT_EQ(mesh.triangles.size(), 2u * 6 * 4);
  // Square (column 2, row 1): diagonal from (2, 1) to (3, 2), both triangles counter-clockwise.
  const std::size_t square = 2 * (1 * 6 + 2);
  EXPECT_EQ(mesh.triangles[square], (std::array<int, 3>{9, 17, 10}));
  EXPECT_EQ(mesh.triangles[square + 1], (std::array<int, 3>{9, 16, 17}));
  EXPECT_EQ(mesh.vertices.row(17), Eigen::RowVector3d(90.0, -40.0, mesh.vertices(17, 2)));
}

TEST(LoopSubdivision, HeightFieldVerticesOnTheFinerGrids) {
  // 7 x 5 samples, 30 m x 20 m; 3 levels: a 49 x 33 grid of 3.75 m x 2.5 m.
  TriangleMesh mesh = sample_height_field();
  GridNodes nodes = height_field_nodes(7, 5);
  for (int level = 1; level <= 3; ++level) {
    LoopLevel fine = loop_subdivide(mesh);
    nodes = finer_nodes(nodes, fine.new_vertex_ends);
    mesh = std::move(fine.mesh);
  }
  ASSERT_EQ(nodes.size(), 49u * 33u);
  std::set<std::array<int, 2>> distinct(nodes.begin(), nodes.end());
  EXPECT_EQ(distinct.size(), nodes.size());
  EXPECT_EQ(*distinct.begin(), (std::array<int, 2>{0, 0}));
  EXPECT_EQ(*distinct.rbegin(), (std::array<int, 2>{48, 32}));
  int exact = 0;
  for (std::size_t v = 0; v < nodes.size(); ++v) {
    const auto [c, r] = nodes[v];
    // More than two samples (16 nodes) from the nearest corner: exactly on the grid.
    if (std::min(c, 48 - c) <= 16 && std::min(r, 32 - r) <= 16) continue;
    ++exact;
    EXPECT_NEAR(mesh.vertices(static_cast<Eigen::Index>(v), 0), c * 3.75, 1e-9);
    EXPECT_NEAR(mesh.vertices(static_cast<Eigen::Index>(v), 1), -r * 2.5, 1e-9);
  }
  EXPECT_EQ(exact, 15 * 33);  // columns 17-31, all rows
  // The corner vertex is pulled inwards by the border masks (limit: (1/6, 1/6) of a sample).
  EXPECT_GT(mesh.vertices(0, 0), 4.0);
  EXPECT_LT(mesh.vertices(0, 1), -2.0);
}

TEST(LoopSubdivision, RefusesBadInput) {
  TriangleMesh non_manifold = closed_mesh();
  non_manifold.triangles.push_back({0, 2, 5});
  EXPECT_THROW(
      {
        try {
          loop_subdivide(non_manifold);
        } catch (const std::invalid_argument& e) {
          EXPECT_NE(std::string(e.what()).find("edge (0, 2)"), std::string::npos) << e.what();
          throw;
        }
      },
      std::invalid_argument);
  RegularHeightField field{3, 2, 10.0, 10.0, {1.0, 2.0, 3.0, 4.0, std::nan(""), 6.0}};
  EXPECT_THROW(height_field_mesh(field), std::invalid_argument);
  field.heights.pop_back();
  EXPECT_THROW(height_field_mesh(field), std::invalid_argument);
}

}  // namespace
}  // namespace maquette::deform
