#include "model_base.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

#include "core/error.h"

namespace maquette::structures {
namespace {

double cross(const Point2& o, const Point2& a, const Point2& b) {
  return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

// Andrew's monotone chain: the hull counter-clockwise, collinear points dropped.
Ring convex_hull(Ring points) {
  std::ranges::sort(points);
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (points.size() < 3) return points;
  Ring hull(2 * points.size());
  size_t k = 0;
  for (size_t i = 0; i < points.size(); ++i) {  // lower chain
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  for (size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {  // upper chain
    while (k >= lower && cross(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);  // the last point is the first
  return hull;
}

double ring_area(const Ring& ring) {
  double twice = 0;
  for (size_t i = 0; i < ring.size(); ++i)
    twice += cross({0, 0}, ring[i], ring[(i + 1) % ring.size()]);
  return twice / 2;
}

bool inside(const Ring& ring, const Point2& p) {
  bool in = false;
  for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++)
    if ((ring[i][1] > p[1]) != (ring[j][1] > p[1]) &&
        p[0] < ring[j][0] +
                   (p[1] - ring[j][1]) * (ring[i][0] - ring[j][0]) / (ring[i][1] - ring[j][1]))
      in = !in;
  return in;
}

// The outline of the model's floor: the boundary of its downward-facing triangles lying within
// kModelBaseHeightM of its lowest vertex (outward meshes: counter-clockwise seen from below),
// counter-clockwise seen from above; empty when the floor is not one polygon (holes allowed)
// whose boundary is a simple cycle: no floor faces, several pieces (legs), edges meeting
// at a point.
Ring floor_outline(const MeshContent& model, double lowest) {
  std::map<std::pair<Point2, Point2>, int> edges;  // directed, as the floor seen from above
  for (const MeshObject& object : model.objects)
    for (size_t t = 0; t + 2 < object.indices.size(); t += 3) {
      std::array<Point2, 3> corner;
      bool low = true;
      for (size_t k = 0; k < 3; ++k) {
        const size_t v = 3 * size_t(object.indices[t + k]);
        low = low && object.positions[v + 2] <= lowest + kModelBaseHeightM;
        corner[k] = {object.positions[v], object.positions[v + 1]};
      }
      // Seen from above a downward face turns clockwise; walls project to (almost) nothing.
      const double twice_area = cross(corner[0], corner[1], corner[2]);
      double longest = 0;
      for (size_t k = 0; k < 3; ++k)
        longest = std::max(longest, std::hypot(corner[(k + 1) % 3][0] - corner[k][0],
                                               corner[(k + 1) % 3][1] - corner[k][1]));
      if (!low || twice_area > -1e-6 * longest * longest) continue;
      for (size_t k = 0; k < 3; ++k) {  // reversed: counter-clockwise seen from above
        const std::pair<Point2, Point2> e{corner[(k + 1) % 3], corner[k]};
        const auto twin = edges.find({e.second, e.first});
        if (twin != edges.end() && --twin->second == 0)
          edges.erase(twin);  // inside the floor
        else if (twin == edges.end())
          ++edges[e];
      }
    }
  std::map<Point2, Point2> next;
  for (const auto& [e, count] : edges)
    if (count != 1 || !next.emplace(e.first, e.second).second) return {};  // a vertex met twice
  std::vector<Ring> loops;
  while (!next.empty()) {
    Ring loop{next.begin()->first};
    bool closed = false;
    for (auto at = next.find(loop.back()); at != next.end() && !closed;
         at = next.find(loop.back())) {
      const Point2 to = at->second;
      next.erase(at);
      closed = to == loop.front();
      if (!closed) loop.push_back(to);
    }
    if (!closed || loop.size() < 3) return {};
    loops.push_back(std::move(loop));
  }
  const auto outer = std::ranges::max_element(
      loops, [](const Ring& a, const Ring& b) { return ring_area(a) < ring_area(b); });
  if (outer == loops.end() || !(ring_area(*outer) > 0)) return {};
  for (const Ring& loop : loops)  // the others must be its holes
    if (&loop != &*outer && (ring_area(loop) > 0 || !inside(*outer, loop.front()))) return {};
  return *outer;
}

}  // namespace

Ring model_base(const MeshContent& model, const std::string& where) {
  double lowest = std::numeric_limits<double>::infinity();
  size_t vertices = 0;
  for (const MeshObject& object : model.objects)
    for (size_t i = 0; i + 2 < object.positions.size(); i += 3) {
      for (size_t k = 0; k < 3; ++k)
        if (!std::isfinite(object.positions[i + k]))
          throw Error(where + ": a vertex of the model is not finite");
      lowest = std::min(lowest, double(object.positions[i + 2]));
      ++vertices;
    }
  if (vertices == 0) throw Error(where + ": the model has no vertex");
  if (Ring outline = floor_outline(model, lowest); !outline.empty()) return outline;
  Ring base;
  for (const MeshObject& object : model.objects)
    for (size_t i = 0; i + 2 < object.positions.size(); i += 3)
      if (object.positions[i + 2] <= lowest + kModelBaseHeightM)
        base.push_back({object.positions[i], object.positions[i + 1]});
  Ring hull = convex_hull(std::move(base));
  if (hull.size() < 3)
    throw Error(where + ": the model's base (its vertices within " +
                std::to_string(int(kModelBaseHeightM * 100)) +
                " cm of its lowest) has no area: it stands on a point or an edge");
  return hull;
}

}  // namespace maquette::structures
