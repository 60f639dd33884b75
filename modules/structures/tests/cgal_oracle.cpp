#include "cgal_oracle.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>

namespace maquette::structures {

namespace PMP = CGAL::Polygon_mesh_processing;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;

CgalVerdict cgal_verdict(const std::vector<double>& positions,
                         const std::vector<uint32_t>& indices) {
  // Vertices at one position are one point (val3dity's view: a mesh whose corners are split
  // for flat normals is still closed).
  std::vector<Kernel::Point_3> points;
  std::map<std::array<double, 3>, std::size_t> point_of;
  std::vector<std::size_t> welded;
  for (size_t v = 0; v < positions.size(); v += 3) {
    const auto [at, added] = point_of.emplace(
        std::array<double, 3>{positions[v], positions[v + 1], positions[v + 2]}, points.size());
    if (added) points.emplace_back(positions[v], positions[v + 1], positions[v + 2]);
    welded.push_back(at->second);
  }
  std::vector<std::vector<std::size_t>> triangles;
  for (size_t t = 0; t < indices.size(); t += 3)
    triangles.push_back({welded[indices[t]], welded[indices[t + 1]], welded[indices[t + 2]]});
  CgalVerdict v;
  v.polygon_mesh = PMP::is_polygon_soup_a_polygon_mesh(triangles);
  if (!v.polygon_mesh) return v;
  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(points, triangles, mesh);
  v.closed = CGAL::is_closed(mesh);
  if (!v.closed) return v;
  v.self_intersects = PMP::does_self_intersect(mesh);
  if (v.self_intersects) return v;
  v.outward = PMP::is_outward_oriented(mesh);
  v.volume = CGAL::to_double(PMP::volume(mesh));
  return v;
}

void expect_valid_solid(const std::vector<double>& positions, const std::vector<uint32_t>& indices,
                        double volume, double relative) {
  const CgalVerdict v = cgal_verdict(positions, indices);
  EXPECT_TRUE(v.polygon_mesh);
  EXPECT_TRUE(v.closed);
  EXPECT_FALSE(v.self_intersects);
  EXPECT_TRUE(v.outward);
  EXPECT_NEAR(v.volume, volume, relative * volume);
}

double cgal_area(const std::vector<std::vector<std::array<double, 2>>>& rings) {
  double area = 0;
  for (size_t k = 0; k < rings.size(); ++k) {
    CGAL::Polygon_2<Kernel> polygon;
    for (const auto& p : rings[k]) polygon.push_back(Kernel::Point_2(p[0], p[1]));
    if (polygon.size() > 1 && polygon[0] == polygon[polygon.size() - 1])
      polygon.erase(polygon.vertices_end() - 1);
    const double a = std::abs(CGAL::to_double(polygon.area()));
    area += k == 0 ? a : -a;
  }
  return area;
}

}  // namespace maquette::structures
