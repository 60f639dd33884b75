// The synthesis's last step at the finest level (synthesis.h): a vote among the sources that the
// overlapping patches propose for each pixel. ebsynth's coherence comes from votes of overlapping
// patches; here the vote picks a source, it does not average colours, so the output stays a copy.
//
// For each pixel p of `out`, the patches of side 2 radius + 1 around it propose S(p + d) - d (the
// state's exemplar pixel at p + d, shifted back by d), each kept when it lies inside the exemplar,
// is allowed and has p's target label (any label when p's is kUnknownLabel). p takes the kept
// proposal whose colour is nearest (squared RGB distance) the kept proposals' mean colour, counted
// with their multiplicity; on ties the first in row-major order of d; when none is kept, its own
// source S(p). A pixel with a depth break (across_depth_break) between it and any pixel of its
// window keeps S(p): the vote would join patches across a silhouette.
#pragma once

#include <cstdint>
#include <vector>

#include "exemplar_pyramid.h"
#include "synthesis.h"

namespace maquette::synthesis {

// Whether depths `a` and `b` (metres from the eye; infinity: the sky; NaN: unknown) lie on either
// side of a depth break: one of the two sky, or the farther beyond `ratio` times the nearer.
// Unknown depths break nothing.
bool across_depth_break(float a, float b, double ratio);

// Rasters over rectangles of global pixels, row-major.
struct VoteInputs {
  PixelRect state_rect;                // covers `out` grown by radius
  const std::vector<int32_t>& state;   // exemplar pixel y * width + x
  PixelRect guide_rect;                // covers `out` grown by radius
  const std::vector<uint8_t>& labels;  // target labels (painting classes)
  const std::vector<float>& depth;     // depth from the eye, or empty: no breaks
  double depth_break = 1.05;           // the ratio that breaks
};

// The voted exemplar pixel of each pixel of `out`, row-major. Preconditions: radius >= 0, the
// rectangles cover `out` grown by radius, the state's pixels are the level's.
std::vector<int32_t> vote(const ExemplarLevel& e, const VoteInputs& in, int radius,
                          const PixelRect& out);

}  // namespace maquette::synthesis
