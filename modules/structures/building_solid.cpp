#include "building_solid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <utility>

namespace maquette::structures {
namespace {

using Vec3 = std::array<double, 3>;

Vec3 vertex(const std::vector<double>& positions, uint32_t i) {
  return {positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]};
}

Vec3 minus(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// Every directed edge once, and its reverse once.
std::string orientation_problem(const std::vector<uint32_t>& indices) {
  std::vector<std::pair<uint32_t, uint32_t>> edges;
  edges.reserve(indices.size());
  for (size_t t = 0; t < indices.size(); t += 3)
    for (size_t k = 0; k < 3; ++k) edges.emplace_back(indices[t + k], indices[t + (k + 1) % 3]);
  std::sort(edges.begin(), edges.end());
  for (size_t i = 0; i < edges.size(); ++i) {
    const auto [a, b] = edges[i];
    if (i + 1 < edges.size() && edges[i + 1] == edges[i])
      return "edge " + std::to_string(a) + "-" + std::to_string(b) +
             " is used twice in one direction (not consistently oriented)";
    if (!std::binary_search(edges.begin(), edges.end(), std::make_pair(b, a)))
      return "edge " + std::to_string(a) + "-" + std::to_string(b) +
             " has no opposite edge (not closed)";
  }
  return {};
}

// The largest distance of a face's vertices from the plane of its largest triangle.
double planarity(const Solid& s, const SolidFace& face) {
  Vec3 normal{}, origin{};
  double largest = -1;
  for (uint32_t t = face.first; t < face.first + face.count; ++t) {
    const Vec3 a = vertex(s.positions, s.indices[3 * t]);
    const Vec3 n = cross(minus(vertex(s.positions, s.indices[3 * t + 1]), a),
                         minus(vertex(s.positions, s.indices[3 * t + 2]), a));
    const double length = std::sqrt(dot(n, n));
    if (length > largest) {
      largest = length;
      normal = {n[0] / length, n[1] / length, n[2] / length};
      origin = a;
    }
  }
  double worst = 0;
  for (uint32_t k = 3 * face.first; k < 3 * (face.first + face.count); ++k)
    worst =
        std::max(worst, std::abs(dot(minus(vertex(s.positions, s.indices[k]), origin), normal)));
  return worst;
}

}  // namespace

Solid extrude(const RoofSurface& roof) {
  Solid s;
  const uint32_t n = uint32_t(roof.points.size());
  s.positions.reserve(6 * size_t(n));
  for (const PlanePoint2& p : roof.points) s.positions.insert(s.positions.end(), {p[0], p[1], 0});
  for (uint32_t k = 0; k < n; ++k)
    s.positions.insert(s.positions.end(), {roof.points[k][0], roof.points[k][1], roof.heights[k]});

  size_t roof_size = 0;
  for (const std::vector<uint32_t>& face : roof.faces) roof_size += face.size();
  s.indices.reserve(2 * roof_size + 6 * size_t(n));
  for (const std::vector<uint32_t>& face : roof.faces)  // the floor, facing down
    for (size_t t = 0; t < face.size(); t += 3)
      s.indices.insert(s.indices.end(), {face[t], face[t + 2], face[t + 1]});
  s.faces.push_back({0, uint32_t(roof_size / 3)});
  for (const std::vector<uint32_t>& face : roof.faces) {
    s.faces.push_back({uint32_t(s.indices.size() / 3), uint32_t(face.size() / 3)});
    for (const uint32_t i : face) s.indices.push_back(n + i);
  }

  // Walls: the ring's interior is on the left of each edge, so (i, j, top j) faces right: out.
  for (const std::vector<uint32_t>& ring : roof.outline)
    for (size_t k = 0; k < ring.size(); ++k) {
      const uint32_t i = ring[k], j = ring[(k + 1) % ring.size()];
      s.faces.push_back({uint32_t(s.indices.size() / 3), 2});
      s.indices.insert(s.indices.end(), {i, j, n + j, i, n + j, n + i});
    }
  return s;
}

Solid extrude(const Footprint& footprint, double height) {
  return extrude(roof_surface(footprint, {RoofPlane{0, 0, height}}));
}

double mesh_volume(const std::vector<double>& positions, const std::vector<uint32_t>& indices) {
  double six = 0;
  for (size_t t = 0; t < indices.size(); t += 3)
    six += dot(vertex(positions, indices[t]),
               cross(vertex(positions, indices[t + 1]), vertex(positions, indices[t + 2])));
  return six / 6;
}

std::string solid_problem(const Solid& s, double expected_volume) {
  if (std::string problem = orientation_problem(s.indices); !problem.empty()) return problem;
  for (size_t t = 0; t < s.indices.size(); t += 3) {
    const std::array<Vec3, 3> p = {vertex(s.positions, s.indices[t]),
                                   vertex(s.positions, s.indices[t + 1]),
                                   vertex(s.positions, s.indices[t + 2])};
    const std::array<Vec3, 3> edges = {minus(p[1], p[0]), minus(p[2], p[1]), minus(p[0], p[2])};
    const Vec3 n = cross(edges[0], minus(p[2], p[0]));
    const double area = std::sqrt(dot(n, n)) / 2;
    const double longest_squared =
        std::max({dot(edges[0], edges[0]), dot(edges[1], edges[1]), dot(edges[2], edges[2])});
    if (!(area > kSliverRatio * longest_squared)) {  // also a triangle of coincident points
      std::ostringstream m;
      m.precision(6);
      m << "triangle " << t / 3 << " is a sliver: area " << area << " m2 for a longest edge of "
        << std::sqrt(longest_squared) << " m (at most " << kSliverRatio << " x its square)";
      return m.str();
    }
  }
  for (size_t f = 0; f < s.faces.size(); ++f)
    if (const double d = planarity(s, s.faces[f]); d > kPlanarityM)
      return "face " + std::to_string(f) + " is not planar: a vertex " + std::to_string(d) +
             " m off its plane";
  const double volume = mesh_volume(s.positions, s.indices);
  if (!(volume > 0)) return "the shell faces inwards (volume " + std::to_string(volume) + " m3)";
  if (std::abs(volume - expected_volume) > 1e-9 * expected_volume) {
    std::ostringstream m;
    m.precision(15);
    m << "the volume " << volume << " m3 differs from the expected " << expected_volume
      << " m3 by more than 1e-9";
    return m.str();
  }
  return {};
}

}  // namespace maquette::structures
