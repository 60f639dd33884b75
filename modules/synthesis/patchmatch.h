// PatchMatch (Barnes, Shechtman, Finkelstein and Goldman, "PatchMatch: a randomized correspondence
// algorithm for structural image editing", SIGGRAPH 2009): random initial matches, propagation of
// good matches to the next pixel (their match shifted by one), and a random search around the best
// match in windows halving from the reference image's size to one pixel.
//
// Deterministic for any thread count: every random draw is a hash of (query centre, level, pass,
// draw, seed), and the query centres are cut into fixed 64 x 64 tiles of the query image: a pass
// scans each tile in order (forward on even passes, propagating from the left and upper
// neighbours; backward on odd ones, from the right and lower), reading the neighbours in its own
// tile as this pass left them and those of other tiles as the pass before left them, so the tiles
// can run in parallel in any order. Information crosses a tile edge once per pass instead of
// sweeping the whole image as the sequential algorithm does; tiles are large enough that the
// random search, not the propagation across tiles, dominates convergence.
#pragma once

#include "nearest_field.h"

namespace maquette::synthesis {

class PatchMatch final : public NearestFieldSearch {
 public:
  void improve(const PatchImage& query, const PatchImage& reference, const PatchCentres& references,
               const FieldSearchParams& params, NearestField& field) const override;
};

}  // namespace maquette::synthesis
