#include "render/progressive_bend.h"

#include <tbb/parallel_for.h>

#include <string>

#include "core/error.h"

namespace maquette {

void check_bend(const ProgressiveBend& bend) {
  if (!(bend.radius > 0))
    throw Error("--bend-radius " + std::to_string(bend.radius) + " must be positive");
  if (!(bend.start >= 0) || !std::isfinite(bend.start))
    throw Error("--bend-start " + std::to_string(bend.start) + " must be finite and >= 0");
}

void bend_positions(std::span<double> positions, const ProgressiveBend& bend) {
  if (!bend.bends()) return;
  tbb::parallel_for(size_t(0), positions.size() / 3, [&](size_t v) {
    double* p = &positions[3 * v];
    const double d = std::hypot(p[0], p[1]);
    if (!(d > bend.start)) return;
    const double theta = (d - bend.start) / bend.radius;
    const double rho = bend.radius - (p[2] - bend.base);
    const double scale = (bend.start + rho * std::sin(theta)) / d;
    p[0] *= scale;
    p[1] *= scale;
    p[2] = bend.base + bend.radius - rho * std::cos(theta);
  });
}

}  // namespace maquette
