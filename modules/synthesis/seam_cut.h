// The minimum-error cut between two syntheses overlapping in a band along an edge (Efros &
// Freeman 2001, image quilting): B, continued from across the edge, and A, the face's own.
//
// The band holds `length` positions along the edge (global positions s_first + i) and `depth`
// pixels away from it (t = 0 beside the edge); error[t * length + i] >= 0 says how much A and B
// differ there. cut[i] in 1 .. depth - 1: the pixels t < cut[i] take B, the others A, so the
// pixel beside the edge always takes B. The cut is an 8-connected path (|cut[i + 1] - cut[i]| <= 1)
// pinned at depth / 2 at every global position that is a multiple of pin_period; between two pins
// it is the path of least total error of the pixel pairs it runs between (error at t - 1 plus
// error at t), found by dynamic programming, ties to the straight step (so with no error anywhere
// the cut runs straight at depth / 2), then -1, then +1. So the cut over
// a stretch between two pins depends on the errors there alone: every band whose ends are pins
// gives it the same cut (the tiling invariance the transfer needs).
#pragma once

#include <cstdint>
#include <vector>

namespace maquette::synthesis {

// Throws maquette::Error when depth < 3, pin_period < 1, s_first or length is not a multiple of
// pin_period, or error does not hold length * depth values.
std::vector<int> seam_cut(const std::vector<float>& error, int64_t s_first, int length, int depth,
                          int pin_period);

}  // namespace maquette::synthesis
