// The colour histogram texture.cluster builds: hue x saturation bins ("hs"), or hue x
// saturation x value ("hsv"), and its occupied bins as weighted points of colour-wheel
// coordinates (s cos h, s sin h[, v]) for the clustering.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "colour.h"

namespace maquette::texture {

inline constexpr int kHueBins = 72, kSatBins = 20, kValueBins = 10;  // 5 degrees, 0.05, 0.1

enum class ColourSpace { Hs, Hsv };
ColourSpace parse_colour_space(const std::string& name);  // "hs" or "hsv"

int histogram_dims(ColourSpace space);  // 2 or 3
int histogram_bins(ColourSpace space);  // 1440 or 14400

// Index of a colour in the histogram: (hue * kSatBins + saturation) [* kValueBins + value].
int colour_bin(const Hsv& x, ColourSpace space);

// The hue x saturation counts (summed over value for "hsv").
std::vector<uint64_t> hs_marginal(const std::vector<uint64_t>& histogram, ColourSpace space);

using Point = std::array<double, 3>;  // colour-wheel coordinates; the third is 0 in "hs"
using Matrix = std::array<Point, 3>;  // symmetric; the leading dims x dims block is used

struct BinPoint {
  Point x;        // the bin centre
  double w;       // its pixel count
  Matrix spread;  // covariance of a uniform spread over the bin (a polar sector [x value
                  // range]): (0.05)^2 / 12 radially, (s 5 degrees)^2 / 12 along the hue,
                  // (0.1)^2 / 12 in value
  double volume;  // of the bin in colour-wheel coordinates
};

std::vector<BinPoint> occupied_bins(const std::vector<uint64_t>& histogram, ColourSpace space);
std::vector<BinPoint> all_bins(ColourSpace space);  // with w = 0

// Hue (degrees [0, 360)), saturation and value of a colour-wheel point.
Hsv point_colour(const Point& p);

double squared_distance(const Point& a, const Point& b);

}  // namespace maquette::texture
