#include "line_samples.h"

#include <cmath>
#include <cstddef>

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
  const Sample f0 = pixel(0), f1 = pixel(middle), f2 = pixel(last);
  // Lagrange's quadratic through indices 0, middle and last.
  const double x1 = double(middle), x2 = double(last);
  const auto quadratic = [&](size_t index) {
    const double j = double(index);
    const double l0 = (j - x1) * (j - x2) / (x1 * x2), l1 = j * (j - x2) / (x1 * (x1 - x2)),
                 l2 = j * (j - x1) / (x2 * (x2 - x1));
    return Sample{l0 * f0[0] + l1 * f1[0] + l2 * f2[0], l0 * f0[1] + l1 * f1[1] + l2 * f2[1]};
  };
  bool smooth = true;
  for (const size_t j : {quarter, last - quarter}) {
    const Sample e = pixel(j), q = quadratic(j);
    // NaN (no place) is not smooth.
    smooth = smooth && std::abs(e[0] - q[0]) <= kLineTolerance &&
             std::abs(e[1] - q[1]) <= kLineTolerance;
  }
  for (size_t j = 1; j < last; ++j) {
    if (j == middle || j == quarter || j == last - quarter) continue;
    if (smooth) {
      const Sample q = quadratic(j);
      out[j] = {q[0] - origin[0], q[1] - origin[1]};
    } else {
      out[j] = frame.local_sample(points[j]);
    }
  }
  return smooth;
}

}  // namespace maquette::deform
