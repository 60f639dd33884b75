// How much the synthesis over-uses each pixel of an exemplar, measured once per exemplar: Kaspar
// et al. 2015's occurrence map (a penalty on each source by how often it is already used), made a
// property of the exemplar so that the synthesis stays a function of global pixel coordinates
// (a count over the output would make each pixel depend on every other, and on the window).
//
// The exemplar's own label map is synthesized with `params` (its excluded pixels' labels
// unknown; the usage penalty off, whatever params.w_usage): a synthesis without bias would copy
// each allowed pixel about once. Each allowed pixel of the finest level counts the output pixels
// of a known label copied from it; its usage is the mean count over the allowed pixels of its
// 3 x 3 neighbourhood, minus 1, at least 0 (0: used no more than its share). A coarser level's
// pixel takes the mean of its 2 x 2 children (clamped at the border). The same copy gives the
// finest level's colour excess (colour_excess_of_copy), which the vote's histogram balance reads
// (vote.h). The copy is synthesized in tiles in parallel, each with its halo: the same bits as one
// window and for any threads (synthesize's contract).
#pragma once

#include "exemplar_pyramid.h"
#include "synthesis.h"

namespace maquette::synthesis {

// Sets pyramid.levels[l].usage for every level and the finest level's colour_excess. Precondition:
// the pyramid has kLevels levels.
void measure_usage(ExemplarPyramid& pyramid, const SynthesisParams& params);

// What measure_usage copies: the exemplar's own labels as a target, its excluded pixels and a
// border of synthesis_halo() pixels around it unknown (kUnknownLabel), output pixels (0, 0) to
// (width, height) the exemplar's.
TargetGuides own_label_guides(const ExemplarLevel& finest);

// The finest level's usage from a copy of its own label map: `source` holds, for each pixel of
// the copy (the level's size, row-major), the level's pixel it copies. Each pixel counts the
// allowed pixels of the copy that copy it (the excluded ones are not counted); every pixel's
// usage is the mean count over the allowed pixels of its 3 x 3 neighbourhood (within the level),
// minus 1, at least 0; 0 when it has no allowed neighbour.
std::vector<float> usage_of_copy(const ExemplarLevel& finest, const std::vector<int32_t>& source);

// The colour excess's floor and clamp (colour_excess_of_copy).
inline constexpr double kExcessFloor = 0.002, kExcessClamp = 4;

// The finest level's colour excess from a copy of its own label map (`source` as for
// usage_of_copy): for each label, the share of the copy's allowed pixels of that label whose
// source's colour falls in each bin (histogram_bin: 8 x 8 x 8, as synthesis.assess's
// histograms), over the share of the level's allowed pixels of that label in the bin, each share
// plus kExcessFloor (bins that are nearly empty stay near 1), clamped to [1 / kExcessClamp,
// kExcessClamp]. Every allowed pixel takes the ratio of its own colour's bin under its label; an
// excluded pixel 1. Above 1: the synthesis shows the colour more often than the exemplar has it.
std::vector<float> colour_excess_of_copy(const ExemplarLevel& finest,
                                         const std::vector<int32_t>& source);

}  // namespace maquette::synthesis
