// How inpaint() and clone() treat the values of a layer other than imagery (inpaint.h
// LayerValues): land-cover classes as one channel per class (one-hot), so that patch distances
// count mismatched classes and a vote is a tally of classes, never an average of their codes; a
// DEM's heights as a smooth trend plus the detail that patches copy, so that a fill follows the
// terrain's slope around the hole instead of pasting patches of other heights.
#pragma once

#include <cstdint>
#include <vector>

#include "nearest_field.h"

namespace maquette::synthesis {

// A class raster as one channel per class.
struct ClassChannels {
  std::vector<float> classes;  // the class codes, ascending: channel k is classes[k]
  PatchImage one_hot;          // 1 in the channel of the pixel's class; NaN where it has none
};

// The channels of the classes of `labels` (1 channel, NaN: nodata) found where `hole` is zero;
// pixels in the hole, and any class found only there, get no channel (all zeros). Throws
// maquette::Error when `labels` has another channel count than 1 or no class outside the hole.
ClassChannels class_channels(const PatchImage& labels, const std::vector<uint8_t>& hole);

// Each pixel's class: the code of its largest channel (ties to the lower code), NaN where its
// channels are. Classes are codes, never mixed: one_hot's channels are classes.size().
PatchImage class_labels(const PatchImage& one_hot, const std::vector<float>& classes);

// In place: each pixel's channels set to 1 in the largest (ties to the lower channel), 0 in the
// others (NaN kept): a vote's weighted class shares to its mode.
void snap_to_mode(float* channels, int count);

// The smooth trend under a height raster (1 channel) whose `unknown` pixels (the hole, nodata)
// have no value: its masked Gaussian pyramid's level `levels - 1` (levels >= 2), unknown pixels
// there filled by diffusion from the known ones, then upsampled bilinearly level by level back to
// the full size. Known heights minus the trend are the detail finer than 2^(levels - 1) samples.
PatchImage height_trend(const PatchImage& heights, const std::vector<uint8_t>& unknown, int levels);

}  // namespace maquette::synthesis
