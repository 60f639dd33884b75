// Several exemplars searched at once as one: the paintings placed side by side in one exemplar,
// with an excluded gap between them wide enough that nothing of the synthesis reaches across it.
// So the candidates, the k-coherence search, the over-use measure and the vote work on it
// unchanged, and every output pixel still copies one pixel of one painting.
//
// Why the gap suffices (exemplar_pyramid.h, synthesis.h, exemplar_usage.h): a coarser level's
// pixel is excluded when any of its 2 x 2 children is, so the gap stays excluded at every level
// (kCombinedGap >> (kLevels - 1) = 8 pixels at the coarsest); excluded pixels are never
// candidates, nor drawn at random, nor voted for, and the k-coherence neighbours are searched
// among the allowed pixels alone. What reads across the gap are the colours: the pyramid's
// 5-tap blur (2 pixels a level: 14 finest pixels from the coarsest level) and the 3 x 3
// neighbourhoods of the PCA features (one pixel of a level: 8 finest pixels at the coarsest);
// the gap's pixels repeat the nearest painting's edge (the left half the left painting's, the
// right half the right one's), so both read only their own painting's edge, as a painting alone
// reads it clamped (up to the blur of the replicated edge at the coarser levels). Each painting
// starts at a multiple of 1 << (kLevels - 1) pixels, so the coarser levels decimate it on its own
// grid.
#pragma once

#include <vector>

#include "exemplar.h"

namespace maquette::synthesis {

// Pixels of gap between two exemplars side by side (finest level).
inline constexpr int kCombinedGap = 64;

// Where an exemplar lies in the combined one: columns [x0, x0 + width), rows [0, height).
struct Placement {
  int x0 = 0, width = 0, height = 0;
};

// The exemplars side by side, left to right in order, each at the first multiple of
// 1 << (kLevels - 1) at least kCombinedGap pixels right of the previous one's end; the combined
// height is the tallest one's. Pixels outside every exemplar are excluded, label 0, and take the
// colour (altitude, distance, light) of the nearest exemplar's pixel at their row clamped into it
// (the nearest in columns, ties to the left). Preconditions: at least one exemplar; either all of
// them have an altitude (a distance, a light) or none. A single exemplar is returned as it is.
Exemplar combine_exemplars(std::vector<Exemplar> parts, std::vector<Placement>& placement);

}  // namespace maquette::synthesis
