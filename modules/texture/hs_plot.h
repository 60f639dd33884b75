// The hue-saturation density plot of texture.cluster as a PNG: a polar plot, hue the angle
// (0 degrees to the right, counter-clockwise, as on the colour wheel) and saturation the radius
// (0 at the centre, 1 at kPlotRadius of the side), each pixel grey by the log density of its
// histogram bin (log(1 + count) / log(1 + largest count): black empty, white densest), a rim
// of fully saturated hues outside saturation 1 as the legend of the angle, cluster centres
// marked by red crosses, transparent outside. Written through formats/image's PNG quicklook
// writer (GDAL MEM + PNG drivers).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "colour.h"

namespace maquette::texture {

inline constexpr int kPlotSize = 512;        // pixels a side
inline constexpr double kPlotRadius = 0.45;  // saturation 1, as a fraction of the side
inline constexpr std::array<uint8_t, 3> kCentreMark = {255, 0, 0};

// Pixel coordinates (column, row; fractional, pixel centres at .5) of a hue and saturation.
std::array<double, 2> plot_position(double hue, double saturation);

// `hs_counts`: kHueBins x kSatBins counts (hs_histogram.h). Throws maquette::Error naming the
// path when it cannot be written.
void write_hs_plot(const std::vector<uint64_t>& hs_counts, const std::vector<Hsv>& centres,
                   const std::string& path);

}  // namespace maquette::texture
