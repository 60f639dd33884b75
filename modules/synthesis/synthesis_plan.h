// What each step of synthesize() (synthesis.h) computes: from the output window back to the
// coarsest level, the rectangle of global pixels each correction sub-pass, patch sub-pass and
// level's start state covers, so that a window computed with its halo equals the whole image
// cropped to it. Each rectangle is the next step's grown by what that step reads around a pixel:
// the finest level's vote kVoteRadius around the window, each patch sub-pass its state within
// kPatchPassRadius, each correction sub-pass its state within kPatchRadius, each pass its snapshot
// within kRepetitionRadius, each level its parent (the pixels of the next coarser level covering
// it).
//
// Given the output pixels the caller keeps (`wanted`), each rectangle also carries the pixels of
// it some kept pixel reads, through every later step: the wanted pixels dilated (Chebyshev) by the
// same reaches, and at a level's start their parents. A step need compute only those: every
// other pixel of its rectangle is read by no kept one, so the kept pixels' results are the same
// bits whether the others are computed or not (the synthesis is a function of each pixel's
// reach).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "patch_pass.h"
#include "synthesis.h"

namespace maquette::synthesis {

// A rectangle of global pixels of one level and the pixels of it a later step reads.
struct PixelMask {
  PixelRect rect;
  std::vector<uint8_t> bits;  // row-major over rect, 1: read; empty: every pixel

  bool has(int64_t col, int64_t row) const {
    return bits.empty() ||
           bits[size_t(row - rect.row0) * size_t(rect.width) + size_t(col - rect.col0)] != 0;
  }
};

// A correction or patch pass: the state it starts from (and its snapshot), each sub-pass's output.
struct PassPlan {
  PixelRect start;
  std::array<PixelMask, kSubPasses> outs{};
};

struct LevelPlan {
  PixelRect start;  // the upsampled (or initialized) state
  std::array<PassPlan, kPasses> passes{};
};

struct Plan {
  std::array<PassPlan, kMaxPatchPasses> patch_passes{};
  std::array<LevelPlan, kLevels> levels{};
};

// The plan of `out` with `patch_passes` patch passes (0 .. kMaxPatchPasses). `wanted`: non-zero
// for each pixel of `out` (row-major) whose result is kept; empty: every one (then every mask's
// bits are empty). Precondition: wanted is empty or of out's size.
Plan plan_levels(const PixelRect& out, int patch_passes, std::span<const uint8_t> wanted = {});

}  // namespace maquette::synthesis
