// The colour histogram texture.cluster builds: hue x saturation bins ("hs"), hue x
// saturation x value ("hsv"), or CIELAB bins ("lab"), and its occupied bins as weighted points
// for the clustering: colour-wheel coordinates (s cos h, s sin h[, v]), or (a*, b*, w L*) / 100
// with the lightness weighted by w = kLabLightnessWeight.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "colour.h"

namespace maquette::texture {

inline constexpr int kHueBins = 72, kSatBins = 20, kValueBins = 10;  // 5 degrees, 0.05, 0.1

// CIELAB bins: L* 0..100 in steps of 5, a* and b* -60..60 in steps of 3 (values outside go to
// the end bins; Landsat's surface colours lie within +-40).
inline constexpr int kLightnessBins = 20, kChromaBins = 40;
inline constexpr double kChromaLimit = 60;
// Weight of L* against a* and b* in "lab" points: a surface type keeps its hue and chroma
// across lit and shaded slopes and sparser or denser cover, much less its lightness (Zion's red
// rock and white sandstone differ in a* and b*; its forest in shade and sun in L*).
inline constexpr double kLabLightnessWeight = 0.5;

enum class ColourSpace { Hs, Hsv, Lab };
ColourSpace parse_colour_space(const std::string& name);  // "hs", "hsv" or "lab"

int histogram_dims(ColourSpace space);  // 2, 3 or 3
int histogram_bins(ColourSpace space);  // 1440, 14400 or 32000

// Index of a colour in the histogram: (hue * kSatBins + saturation) [* kValueBins + value]
// ("hs", "hsv").
int colour_bin(const Hsv& x, ColourSpace space);
// Index of a CIELAB colour in the "lab" histogram: (L * kChromaBins + a) * kChromaBins + b.
int lab_bin(const Lab& lab);

// The hue x saturation counts (summed over value for "hsv"); not for "lab".
std::vector<uint64_t> hs_marginal(const std::vector<uint64_t>& histogram, ColourSpace space);

using Point = std::array<double, 3>;  // clustering coordinates; the third is 0 in "hs"
using Matrix = std::array<Point, 3>;  // symmetric; the leading dims x dims block is used

struct BinPoint {
  Point x;        // the bin centre
  double w;       // its pixel count
  Matrix spread;  // covariance of a uniform spread over the bin (a polar sector [x value
                  // range]): (0.05)^2 / 12 radially, (s 5 degrees)^2 / 12 along the hue,
                  // (0.1)^2 / 12 in value; "lab": (0.03)^2 / 12 in a* and b*, (w 0.05)^2 / 12
                  // in L*
  double volume;  // of the bin in the clustering coordinates
};

std::vector<BinPoint> occupied_bins(const std::vector<uint64_t>& histogram, ColourSpace space);
std::vector<BinPoint> all_bins(ColourSpace space);  // with w = 0

// Hue (degrees [0, 360)), saturation and value of a colour-wheel point ("hs", "hsv").
Hsv point_colour(const Point& p);
// The CIELAB colour of a "lab" point, and the point of a CIELAB colour.
Lab point_lab(const Point& p);
Point lab_point(const Lab& lab);

double squared_distance(const Point& a, const Point& b);

}  // namespace maquette::texture
