// The terrain's slope under a region of a height raster, and the slope-aware resize of the clone
// brush (paper 002 §6): a texture moved from ground of one slope to ground of another keeps its
// ground size when, seen from above, it is stretched by 1 / cos(from) along the source's slope
// direction and shrunk by cos(to) along the destination's.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace maquette::synthesis {

struct GroundSlope {
  double slope_deg = 0;   // angle of the mean gradient from the horizontal
  double aspect_deg = 0;  // its direction in the image (clockwise from the x axis, y down)
};

// The mean gradient (central differences) of `heights` (width * height metres, NaN unknown,
// square samples of `spacing_m` metres) over the samples of `region` (non-zero, width * height)
// shifted by (dx, dy) samples whose four neighbours are known and in the raster. Throws
// maquette::Error naming `what` when no such sample exists, or for sizes that do not match.
GroundSlope region_slope(const std::vector<float>& heights, int width, int height, double spacing_m,
                         const std::vector<uint8_t>& region, int dx, int dy, const char* what);

// The linear map (clone.h CloneParams::linear) taking a texture from ground of slope `from` to
// ground of slope `to`: foreshortening(from.slope, 0, from.aspect), then
// foreshortening(0, to.slope, to.aspect).
std::array<double, 4> slope_resize(GroundSlope from, GroundSlope to);

}  // namespace maquette::synthesis
