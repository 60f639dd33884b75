// The terrain's slope under a region of a height raster, and the slope-aware resize of the clone
// brush (paper 002 §6): a texture moved from ground of one slope to ground of another keeps its
// ground size when, seen from above, it is stretched by 1 / cos(from) along the source's slope
// direction and shrunk by cos(to) along the destination's. The grid's samples need not be square
// on the ground (rHEALPix's are not: at the equator 38 m east by 32 m north at level 18), so the
// slopes and the resize are worked out in ground metres, through each place's `SampleFrame`.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace maquette::synthesis {

// Ground metres (east, south) of one sample step along the columns, {east, south}, then along
// the rows: the local Jacobian of samples to a tangent plane, x east and y south like the image.
struct SampleFrame {
  std::array<double, 2> column{1, 0}, row{0, 1};
};

struct GroundSlope {
  double slope_deg = 0;   // angle of the mean gradient from the horizontal
  double aspect_deg = 0;  // its direction on the ground, clockwise from east (south is 90)
};

// The mean gradient (central differences, metres of height per sample step along columns, rows)
// of `heights` (width * height, NaN unknown) over the samples of `region` (non-zero, width *
// height) shifted by (dx, dy) samples whose four neighbours are known and in the raster. Throws
// maquette::Error naming `what` when no such sample exists, or for sizes that do not match.
std::array<double, 2> region_gradient(const std::vector<float>& heights, int width, int height,
                                      const std::vector<uint8_t>& region, int dx, int dy,
                                      const char* what);

// The ground slope of a gradient per sample step at a place of frame `frame`.
GroundSlope ground_slope(std::array<double, 2> gradient, const SampleFrame& frame);

// The linear map of sample offsets (clone.h CloneParams::linear) taking a texture from ground of
// slope `from` (frame `from_frame`) to ground of slope `to` (frame `to_frame`): into ground
// metres, foreshortening(from.slope, 0, from.aspect), foreshortening(0, to.slope, to.aspect),
// back into samples.
std::array<double, 4> slope_resize(GroundSlope from, const SampleFrame& from_frame, GroundSlope to,
                                   const SampleFrame& to_frame);

}  // namespace maquette::synthesis
