// Which exemplar regions D_spread may prefer (synthesis.h). D_spread gives each 16 x 16 block of
// the output its own preferred regions of 8 x 8 exemplar pixels; with a strong w_spread a block
// takes most of its pixels from them, so a block that prefers a pale patch of the painting (a
// sunlit field among the shrubs) paints a pale blotch where its class shows no such thing as a
// whole. With SynthesisParams::spread_typical below 1 a region is preferred only where it is
// typical of the class: its pixels of the class have a mean lightness whose quantile among the
// class's lies within the central spread_typical of them. A region atypical of the class is
// then copied where its colours fit, never because a block drew it.
#pragma once

#include <cstdint>
#include <vector>

#include "exemplar_pyramid.h"

namespace maquette::synthesis {

inline constexpr int kSpreadRegionShift = 3;  // D_spread's exemplar regions: 8 x 8 pixels

// One value per pixel of `level`: for an allowed pixel, the quantile within its label
// (class_quantiles, light_guide.h: mid-ranks over the label's allowed pixels, each counting the
// mean of its region) of the mean lightness (Rec. 601 luma of rgb) of its region's allowed pixels
// of its label, in 255ths (round(255 q): a byte, so that the synthesis reads it from a small array
// for each candidate); 128 for an excluded pixel (never a candidate). Regions are the pixels of
// equal (x >> kSpreadRegionShift, y >> kSpreadRegionShift), as D_spread's. A function of the
// level's colours, labels and exclusions alone.
std::vector<uint8_t> region_quantiles(const ExemplarLevel& level);

// Whether a region of quantile `q` (region_quantiles, in 255ths) lies within the central `share`
// of its class: (1 - share) / 2 <= q / 255 <= (1 + share) / 2. With share 1 every region does.
constexpr bool typical_region(uint8_t q, double share) {
  return double(q) / 255 >= (1 - share) / 2 && double(q) / 255 <= (1 + share) / 2;
}

}  // namespace maquette::synthesis
