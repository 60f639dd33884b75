// Legends drawn into a white margin below a quicklook: a colour bar with values and units, or
// the class colours with their names.
#pragma once

#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "image/class_table.h"
#include "image/colour_ramp.h"
#include "image/rgba_image.h"

namespace maquette {

struct ColourBar {
  Ramp ramp = Ramp::Grey;
  double low = 0, high = 1;  // the values at the bar's ends (for stretched ramps: t = 0 and 1)
  std::string units;         // printed after the bar; may be empty
};
using ClassKey = std::vector<std::pair<Rgb, std::string>>;  // swatch colour, class name
using Legend = std::variant<ColourBar, ClassKey>;

// Adds the legend below the image, widening it (transparent to the right of the map) when the
// legend needs more room. The font's pixels grow with the image: 1 + width / 400, at most 4.
void add_legend(RgbaImage& image, const Legend& legend);

// Tick values for a bar from low to high: multiples of 1, 2 or 5 x 10^k, at most `max_ticks`.
std::vector<double> nice_ticks(double low, double high, int max_ticks);

}  // namespace maquette
