// Triangles near a polyline against a brute-force distance: dense barycentric samples of each
// triangle and of the segments.
#include "../loop_marking.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace maquette::deform {
namespace {

double sampled_distance(const TriangleMesh& mesh, const std::array<int, 3>& triangle,
                        const std::vector<Eigen::Vector2d>& line) {
  const int n = 60;
  double closest = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; i + j <= n; ++j) {
      const double u = double(i) / n;
      const double v = double(j) / n;
      const Eigen::Vector2d p =
          (1.0 - u - v) * mesh.vertices.row(triangle[0]).head<2>().transpose() +
          u * mesh.vertices.row(triangle[1]).head<2>().transpose() +
          v * mesh.vertices.row(triangle[2]).head<2>().transpose();
      for (std::size_t s = 0; s + 1 < line.size(); ++s) {
        for (int k = 0; k <= 4 * n; ++k) {
          const double w = double(k) / (4 * n);
          closest = std::min(closest, (p - ((1.0 - w) * line[s] + w * line[s + 1])).norm());
        }
      }
    }
  }
  return closest;
}

TEST(TrianglesNearPolyline, AgreesWithSampledDistance) {
  RegularHeightField field{9, 8, 10.0, 12.0, std::vector<double>(72, 100.0)};
  const TriangleMesh mesh = height_field_mesh(field);
  const std::vector<Eigen::Vector2d> line{{13.0, -17.0}, {41.0, -55.0}, {67.0, -50.0}};
  const double band = 6.0;
  const std::vector<bool> near = triangles_near_polyline(mesh, line, band);
  int marked = 0;
  int compared = 0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const double d = sampled_distance(mesh, mesh.triangles[t], line);
    // The samples are at most ~0.3 m apart: leave out triangles whose distance is that close to
    // the band.
    if (std::abs(d - band) < 0.5) continue;
    ++compared;
    EXPECT_EQ(near[t], d < band) << "triangle " << t << " at " << d << " m";
    marked += near[t];
  }
  EXPECT_GT(marked, 10);
  EXPECT_GT(compared, 100);
  EXPECT_THROW(triangles_near_polyline(mesh, std::vector<Eigen::Vector2d>(1), band),
               std::invalid_argument);
  EXPECT_THROW(triangles_near_polyline(mesh, line, -1.0), std::invalid_argument);
}

}  // namespace
}  // namespace maquette::deform
