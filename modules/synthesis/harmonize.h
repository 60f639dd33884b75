// Per-label colour harmonization between several exemplars (issue 18: "several exemplars searched
// at once with per-label colour harmonization between them"): before the exemplars are searched
// as one, the colours of each further exemplar's pixels of a label are matched to the first
// exemplar's pixels of that label, in CIELAB (D65, texture/colour.h's conversion and its
// inverse), so that a class drawn from two paintings shows one palette.
#pragma once

#include <string>
#include <vector>

#include "exemplar.h"

namespace maquette::synthesis {

enum class Harmonization {
  None,       // the paintings' own colours
  Reinhard,   // Reinhard et al. 2001: each CIELAB channel's mean and standard deviation matched
  Histogram,  // each CIELAB channel's histogram matched (quantile to quantile)
};

// "none", "reinhard" or "histogram"; throws maquette::Error naming `where` otherwise.
Harmonization parse_harmonization(const std::string& name, const std::string& where);

// For each label, the allowed (not excluded) pixels of parts[1..] of that label take new
// colours so that their CIELAB statistics match those of parts[0]'s allowed pixels of the label:
//  - Reinhard: per channel v' = (v - mean_i) sd_0 / sd_i + mean_0 (sd_i = 0: the mean shifted
//    alone), population statistics over the label's allowed pixels of each part;
//  - Histogram: per channel, the pixel of rank r among the part's n pixels of the label (ties
//    by pixel index) takes the reference's value of rank floor((r + 0.5) n_0 / n) among its n_0
//    sorted values: the reference's empirical quantile.
// Then back to sRGB, clamped to 0..255 (a colour outside the gamut moves the statistics a
// little). parts[0], the excluded pixels, and the labels parts[0] has no allowed pixel of keep
// their colours; None changes nothing. Deterministic (no threads, no random state).
void harmonize(std::vector<Exemplar>& parts, Harmonization how);

}  // namespace maquette::synthesis
