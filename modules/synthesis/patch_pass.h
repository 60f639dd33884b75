// The finest level's patch passes (synthesis.h), between its correction and its vote: each
// pixel p takes, among the sources the patches of side 2 kPatchPassRadius + 1 around it propose
// (S(p + d) - d: the copy of each neighbour continued), the one whose exemplar patch of that side
// is nearest (squared RGB distance, p's own pixel left out) the output's patch around p.
//
// The correction's cost compares 3 x 3 neighbourhoods through their PCA features; the
// coherence the issue measures (synthesis.assess) is the distance of each 5 x 5 output patch to
// its nearest exemplar patch, which is what ebsynth's search lowers. This pass is that search:
// its propagation (the copies under way), its random search only where the target's classes
// meet (below), and not its averaging vote: the output stays a copy, every pixel's colour its
// source's.
//
// Where the proposals kept disagree and the target's classes meet within p's window (a target
// label there other than p's: the copies of either side cannot both continue), `search` more
// places are drawn around p's own source, the j-th uniformly within kPatchSearchRadius >> j
// pixels in x and y (PatchMatch's random search, Barnes et al. 2009, ebsynth's too; hashed from
// the global pixel, the seed and `salt`, so a function of global pixel coordinates): an exemplar
// patch whose own edge fits the target's. And `edges` more are drawn from the exemplar's own
// edges between p's label and the other label most present in p's window (ties to the lower):
// its places of p's label with that label within kClassEdgeReach (class_edges.h), uniformly,
// hashed likewise: where the painting itself goes from one class to the other. Around the source
// the fitting edge is rarely within reach; on the benchmark's window these draws lower the
// coherence measure by 10-15 % (modules/synthesis/NOTES.md, "The painting's own class edges").
//
// With an altitude guide (the target's and the exemplar's), w_altitude times the squared
// difference of p's altitude and the candidate's, times (kSide^2 - 1) / 9 (the patch's pixels
// over the correction's 3 x 3 neighbourhood's, whose colour term w_altitude weighs there), is
// added to the candidate's cost: the passes keep the altitude fit the correction made.
//
// A proposal or draw is kept when its whole patch lies inside the exemplar, it is allowed and has
// p's target label (any when p's is kUnknownLabel); when none is kept, or a depth break lies
// between p and a pixel of its window (across_depth_break), or p's label is one of line_classes
// and holds fewer than a strict majority of its window's pixels (a road, a track: its best fit
// would be a patch of the fields around it, pale at the road's edge, and the road would fade), p
// keeps its source; when one is, it is taken. Ties go to the first proposal in row-major order of
// d, then to the draws in their order. With `balance` > 0 and the level's colour excess measured
// (the vote's histogram balance, vote.h), a proposal's distance plus the vote's floor for each of
// its pixels is multiplied by its colour excess to the power `balance`. Like the correction, each
// pass runs in the 2 x 2 sub-passes of Lefebvre & Hoppe (pixels of one parity of global column and
// row at a time), each reading the state within kPatchPassRadius: so each pixel's result is a
// function of global pixel coordinates and of the state within kPatchPassRadius times the
// sub-passes that follow.
#pragma once

#include <bitset>
#include <cstdint>
#include <span>
#include <vector>

#include "exemplar_pyramid.h"
#include "synthesis.h"

namespace maquette::synthesis {

inline constexpr int kPatchPassRadius = 2;     // patches of 5 x 5 pixels, synthesis.assess's
inline constexpr int kMaxPatchSearch = 4;      // places drawn per pixel, at most
inline constexpr int kPatchSearchRadius = 16;  // the first draw's; each next one's half
inline constexpr int kMaxPatchEdges = 4;       // places drawn from the class edges, at most

// Rasters over rectangles of global pixels, row-major.
struct PatchPassInputs {
  PixelRect guide_rect;                // covers every rectangle below grown by kPatchPassRadius
  const std::vector<uint8_t>& labels;  // target labels (painting classes)
  const std::vector<float>& depth;     // depth from the eye, or empty: no breaks
  const std::vector<float>& altitude;  // target altitude [0, 1] (NaN: none), or empty
  double depth_break = 1.05;           // the ratio that breaks
  double balance = 0;                  // the colour excess's exponent (0: no balance)
  int search = 0;                      // places drawn per pixel, 0 .. kMaxPatchSearch
  int edges = 0;                       // from the class edges, 0 .. kMaxPatchEdges
  double w_altitude = 0;               // the altitude mismatch's weight (synthesis.h's)
  uint64_t seed = 0;                   // of the draws
  int64_t col_period = 0;              // columns c and c + col_period are one place (0: none)
  std::bitset<256> line_classes{};     // labels whose thin pixels keep their source (above)
};

// One sub-pass: the pixels of `out` of parity (px, py) take their best proposal, the others keep
// their source; with `needed` (row-major over `out`; empty: every pixel) only those of its
// pixels that are non-zero (synthesis_plan.h). `salt` tells the sub-pass's draws from the
// others' (pixel_hash). Preconditions: `state` holds exemplar pixels y * width + x of the level
// over `state_rect`, which covers `out` grown by kPatchPassRadius; `needed` is empty or of out's
// size; in.search is 0 .. kMaxPatchSearch, in.edges 0 .. kMaxPatchEdges (with e.class_edges
// empty, not indexed, they draw nothing).
std::vector<int32_t> patch_sub_pass(const ExemplarLevel& e, const PatchPassInputs& in,
                                    const PixelRect& state_rect, const std::vector<int32_t>& state,
                                    const PixelRect& out, int px, int py, uint64_t salt,
                                    std::span<const uint8_t> needed = {});

}  // namespace maquette::synthesis
