#include "line_samples.h"

#include <cmath>
#include <cstddef>

#include "three_point_quadratic.h"

namespace maquette::deform {
namespace {

using Sample = std::array<double, 2>;

}  // namespace

bool line_samples(const MosaicFrame& frame, std::span<const EastNorth2> points,
                  std::span<Sample> out) {
  const size_t count = points.size();
  if (count < 5) {
    for (size_t j = 0; j < count; ++j) out[j] = frame.local_sample(points[j]);
    return false;
  }
  const size_t last = count - 1, middle = last / 2, quarter = last / 4;
  const Sample origin = frame.origin();
  // The face pixel of point j, its sample coordinates kept in out[j]. Sample coordinates are
  // face pixels less the origin, without rounding, and so back.
  const auto pixel = [&](size_t j) {
    out[j] = frame.local_sample(points[j]);
    return Sample{out[j][0] + origin[0], out[j][1] + origin[1]};
  };
  // Through indices 0, middle and last (pixel(0) computed first: out[0] is filled).
  const Sample f0 = pixel(0);
  const ThreePointQuadratic quadratic{double(middle), double(last), f0, pixel(middle), pixel(last)};
  bool smooth = true;
  for (const size_t j : {quarter, last - quarter}) {
    const Sample e = pixel(j), q = quadratic(double(j));
    // NaN (no place) is not smooth.
    smooth = smooth && std::abs(e[0] - q[0]) <= kLineTolerance &&
             std::abs(e[1] - q[1]) <= kLineTolerance;
  }
  for (size_t j = 1; j < last; ++j) {
    if (j == middle || j == quarter || j == last - quarter) continue;
    if (smooth) {
      const Sample q = quadratic(double(j));
      out[j] = {q[0] - origin[0], q[1] - origin[1]};
    } else {
      out[j] = frame.local_sample(points[j]);
    }
  }
  return smooth;
}

}  // namespace maquette::deform
