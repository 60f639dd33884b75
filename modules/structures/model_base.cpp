#include "model_base.h"

#include <algorithm>
#include <cmath>
#include <limits>

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
