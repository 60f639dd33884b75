#include "stroke_constraints.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <span>

#include "core/error.h"
#include "line_samples.h"
#include "rmf.h"

namespace maquette::deform {
namespace {

// Locates points of one stroke on the mosaic, with the checks the least squares needs.
class Locator {
 public:
  Locator(const MosaicFrame& frame, const HeightField& field, std::string where)
      : frame_(frame), field_(field), where_(std::move(where)) {}

  SurfacePoint operator()(EastNorth2 p, const char* what) const {
    return at(p, frame_.local_sample(p), what);
  }

  // Every point located, in parallel (each on its own: the same results for any thread count);
  // a point that fails throws the error of the first such point in `points`' order, as locating
  // them one by one would.
  std::vector<SurfacePoint> all(const std::vector<EastNorth2>& points, const char* what) const {
    return located(points, 1, what);
  }

  // The same for points laid out as lines of `per_line` points equally spaced (the cross
  // sections), their sample coordinates by line_samples; a point that fails from those is
  // computed again, so that the errors are those of the points located one by one (a point
  // the quadratic places within kLineTolerance of the DEM's edge may pass where alone it would
  // not).
  std::vector<SurfacePoint> lines(const std::vector<EastNorth2>& points, size_t per_line,
                                  const char* what) const {
    return located(points, per_line, what);
  }

 private:
  using Sample = std::array<double, 2>;

  // The point p at sample coordinates s, checked.
  SurfacePoint at(EastNorth2 p, Sample s, const char* what) const {
    const auto [col, row] = s;
    // The triangle's vertices and their neighbours must lie in the mosaic (a point on a face
    // without a place in its unfolded plane lies off it).
    if (!(col >= 1 && row >= 1 && col < field_.width - 2 && row < field_.height - 2))
      throw Error(where_ + ": its " + what + " leaves the DEM (the step's region) at " +
                  lonlat_text(frame_.lonlat(p)));
    const SurfacePoint sp = locate(field_, col, row);
    for (const size_t v : sp.vertex) {
      const int c = int(v % size_t(field_.width)), r = int(v / size_t(field_.width));
      bool finite = std::isfinite(field_.z[v]);
      for (const auto& n : kNeighbours)
        finite = finite && std::isfinite(field_.z[field_.index(c + n[0], r + n[1])]);
      if (!finite)
        throw Error(where_ + ": its " + what + " crosses nodata at " +
                    lonlat_text(frame_.lonlat(p)));
    }
    return sp;
  }

  // The points of lines of `per_line` (all: 1) located, each line on its own in parallel.
  std::vector<SurfacePoint> located(const std::vector<EastNorth2>& points, size_t per_line,
                                    const char* what) const {
    std::vector<SurfacePoint> out(points.size());
    std::vector<char> failed(points.size(), 0);
    const auto line = [&](size_t begin, std::span<Sample> samples) {
      line_samples(frame_, std::span(points).subspan(begin, per_line), samples);
      for (size_t i = begin; i < begin + per_line; ++i) try {
          out[i] = at(points[i], samples[i - begin], what);
        } catch (const Error&) {
          try {
            out[i] = (*this)(points[i], what);
          } catch (const Error&) {
            failed[i] = 1;
          }
        }
    };
    tbb::parallel_for(tbb::blocked_range<size_t>(0, points.size() / per_line,
                                                 std::max<size_t>(1, 256 / per_line)),
                      [&](const tbb::blocked_range<size_t>& range) {
                        std::vector<Sample> samples(per_line);
                        for (size_t k = range.begin(); k < range.end(); ++k)
                          line(k * per_line, samples);
                      });
    const auto first = std::find(failed.begin(), failed.end(), 1);
    if (first != failed.end()) (*this)(points[size_t(first - failed.begin())], what);
    return out;
  }

  const MosaicFrame& frame_;
  const HeightField& field_;
  std::string where_;
};

}  // namespace

void add_stroke_constraints(const FeatureStroke& stroke, const MosaicFrame& frame,
                            const HeightField& field, double step_m, const std::string& where,
                            StrokeConstraints& out) {
  const std::string feature = where + ": feature " + std::to_string(stroke.id);
  const Locator locator(frame, field, feature);
  // The curve's vertices in metres (consecutive repeats dropped) with their Z and distance along.
  std::vector<EastNorth2> vertex;
  std::vector<double> vertex_z, along;
  for (size_t i = 0; i < stroke.curve.size(); ++i) {
    const EastNorth2 p = frame.local(stroke.curve[i]);
    if (!vertex.empty() && p == vertex.back()) continue;
    along.push_back(vertex.empty() ? 0
                                   : along.back() + std::hypot(p[0] - vertex.back()[0],
                                                               p[1] - vertex.back()[1]));
    vertex.push_back(p);
    vertex_z.push_back(stroke.z.empty() ? NAN : stroke.z[i]);
  }
  const double length = along.back();
  if (!stroke.profile.empty() &&
      (stroke.profile.front()[0] > 0.01 * length || stroke.profile.back()[0] < 0.99 * length))
    throw Error(feature + ": profile covers " + std::to_string(stroke.profile.front()[0]) + ".." +
                std::to_string(stroke.profile.back()[0]) + " m, the curve is " +
                std::to_string(length) + " m long");

  // The curve resampled every step_m at most, with elevations.
  const size_t n = size_t(std::ceil(length / step_m));
  std::vector<Vec3d> points(n + 1);
  std::vector<EastNorth2> horizontal(n + 1);
  std::vector<double> z(n + 1);
  size_t segment = 0;
  for (size_t k = 0; k <= n; ++k) {
    const double s = length * double(k) / double(n);
    while (segment + 2 < vertex.size() && along[segment + 1] < s) ++segment;
    const double t =
        std::clamp((s - along[segment]) / (along[segment + 1] - along[segment]), 0.0, 1.0);
    const EastNorth2 a = vertex[segment], b = vertex[segment + 1];
    points[k] = {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), 0};
    horizontal[k] = {points[k][0], points[k][1]};
    if (!stroke.z.empty())
      z[k] = vertex_z[segment] + t * (vertex_z[segment + 1] - vertex_z[segment]);
    else if (!stroke.profile.empty())
      z[k] = piecewise_linear(stroke.profile, s);
  }
  const std::vector<SurfacePoint> located = locator.all(horizontal, "control curve");
  for (size_t k = 0; k <= n; ++k) {
    if (stroke.z.empty() && stroke.profile.empty()) z[k] = height_at(field, located[k]);
    out.control.push_back({located[k], z[k], stroke.id});
  }

  // Frames along the horizontal trace; the reference starts on the right of the first tangent.
  std::vector<Vec3d> tangents(n + 1);
  for (size_t k = 0; k <= n; ++k) {
    const Vec3d& a = points[k == 0 ? 0 : k - 1];
    const Vec3d& b = points[k == n ? n : k + 1];
    const double norm = std::hypot(b[0] - a[0], b[1] - a[1]);
    tangents[k] = {(b[0] - a[0]) / norm, (b[1] - a[1]) / norm, 0};
  }
  const std::vector<Frame> frames =
      rotation_minimizing_frames(points, tangents, {tangents[0][1], -tangents[0][0], 0});

  const double o_min = stroke.cross_section.front()[0], o_max = stroke.cross_section.back()[0];
  // A triangle holding an end section's point reaches at most a sample's diagonal (3 steps of
  // half a sample) past the end.
  out.bands.push_back({vertex, o_min, o_max, 3 * step_m});
  const size_t m = size_t(std::ceil((o_max - o_min) / step_m));
  std::vector<EastNorth2> across;
  std::vector<double> across_z;
  across.reserve((n + 1) * (m + 1));
  across_z.reserve(across.capacity());
  for (size_t k = 0; k <= n; ++k) {
    const Vec3d& r = frames[k].reference;
    const double norm = std::hypot(r[0], r[1]);
    for (size_t j = 0; j <= m; ++j) {
      const double o = o_min + (o_max - o_min) * double(j) / double(m);
      across.push_back({points[k][0] + o * r[0] / norm, points[k][1] + o * r[1] / norm});
      across_z.push_back(z[k] + piecewise_linear(stroke.cross_section, o));
    }
  }
  const std::vector<SurfacePoint> across_located = locator.lines(across, m + 1, "cross section");
  for (size_t i = 0; i < across.size(); ++i)
    out.section.push_back({across_located[i], across_z[i], stroke.id});
}

}  // namespace maquette::deform
