#include "vegetation_random.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/splitmix64.h"
#include "roof_triangulation.h"

namespace maquette::structures {
namespace {

using Triangle = std::array<PlanePoint2, 3>;

double area(const Triangle& t) {
  return std::abs((t[1][0] - t[0][0]) * (t[2][1] - t[0][1]) -
                  (t[1][1] - t[0][1]) * (t[2][0] - t[0][0])) /
         2;
}

}  // namespace

std::vector<PlanePoint> random_placement(const Footprint& polygon, double spacing, uint64_t seed) {
  std::vector<PlanePoint2> points;  // numbered ring after ring, as the triangles' indices
  for (const PlaneRing& ring : polygon.rings) points.insert(points.end(), ring.begin(), ring.end());
  const std::vector<uint32_t> indices = triangulate_footprint(polygon);
  std::vector<Triangle> triangles;
  std::vector<double> cumulative;  // of the triangles' areas
  double total = 0;
  for (size_t k = 0; k + 2 < indices.size(); k += 3) {
    triangles.push_back({points[indices[k]], points[indices[k + 1]], points[indices[k + 2]]});
    cumulative.push_back(total += area(triangles.back()));
  }
  const auto count = size_t(std::llround(total / (spacing * spacing)));
  std::vector<PlanePoint> out;
  out.reserve(count);
  uint64_t state = splitmix64_mix(seed);
  for (size_t k = 0; k < count; ++k) {
    const double pick = unit_interval(splitmix64_next(state)) * total;
    const size_t i =
        size_t(std::upper_bound(cumulative.begin(), cumulative.end(), pick) - cumulative.begin());
    const Triangle& t = triangles[std::min(i, triangles.size() - 1)];
    // Uniform in the triangle: (u, v) in the unit square folded onto its lower half.
    double u = unit_interval(splitmix64_next(state)), v = unit_interval(splitmix64_next(state));
    if (u + v > 1) u = 1 - u, v = 1 - v;
    out.push_back({t[0][0] + u * (t[1][0] - t[0][0]) + v * (t[2][0] - t[0][0]),
                   t[0][1] + u * (t[1][1] - t[0][1]) + v * (t[2][1] - t[0][1])});
  }
  return out;
}

}  // namespace maquette::structures
