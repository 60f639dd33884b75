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
//
// The histogram balance (Kaspar et al. 2015's histogram-preserving vote, made a property of the
// exemplar): nearest the mean favours a class's middle tones, so its histogram narrows. With
// `balance` > 0 and the level's colour excess measured (ExemplarLevel::colour_excess: how much
// more often the synthesis of the exemplar's own labels shows each pixel's colour than the
// exemplar has it, exemplar_usage.h), a proposal's squared distance to the mean, plus
// kBalanceFloor, is multiplied by its colour excess to the power `balance`: colours the vote
// over-shows must lie nearer the mean to win, the under-shown ones win from farther. A function
// of the exemplar and the window's state alone, as before. The excess is measured once per
// exemplar with the default SynthesisParams (vote radius 1, no balance; transfer_exemplar.cpp),
// whatever the step's own radius: with radius 2 it under-states the wider vote's narrowing.
#pragma once

#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "exemplar_pyramid.h"
#include "synthesis.h"

namespace maquette::synthesis {

// Whether depths `a` and `b` (metres from the eye; infinity: the sky; NaN: unknown) lie on either
// side of a depth break: one of the two sky, or the farther beyond `ratio` times the nearer.
// Unknown depths break nothing.
bool across_depth_break(float a, float b, double ratio);

// The squared difference of a target guide at `i` and exemplar pixel `c`'s value (0 when either
// has none, or the target's is NaN): the correction's and the patch passes' guide terms. Inline:
// they call it for every candidate.
inline double guide_mismatch(const std::vector<float>& target, std::size_t i,
                             const std::vector<float>& exemplar, int32_t c) {
  if (target.empty() || exemplar.empty() || std::isnan(target[i])) return 0;
  return std::pow(double(target[i]) - double(exemplar[std::size_t(c)]), 2);
}

// Whether a depth break lies between pixel (col, row) and any pixel within `radius` (Chebyshev)
// of it, `depth` holding the depths over `rect`, row-major (empty: no breaks). Precondition: the
// window lies in `rect`.
bool depth_break_within(const std::vector<float>& depth, const PixelRect& rect, int64_t col,
                        int64_t row, int radius, double ratio);

// Added to a proposal's squared distance (RGB 0..1) before the balance's factor: a proposal at
// the mean itself is still weighed by its excess.
inline constexpr double kBalanceFloor = 1e-4;

// std::pow(excess, balance) of colour excesses, memoised: an excess takes few values (one per
// label and colour bin, exemplar_usage.h) and pow is costly. Bit for bit std::pow's.
class ExcessPower {
 public:
  explicit ExcessPower(double balance) : balance_(balance) {}

  double operator()(float excess) {
    const uint32_t bits = std::bit_cast<uint32_t>(excess);
    Slot& slot = slots_[(bits * 0x9e3779b1u) >> (32 - kSlotBits)];
    if (!slot.set || slot.bits != bits) slot = {bits, true, std::pow(double(excess), balance_)};
    return slot.value;
  }

 private:
  static constexpr int kSlotBits = 10;
  struct Slot {
    uint32_t bits = 0;
    bool set = false;
    double value = 0;
  };
  double balance_;
  std::array<Slot, std::size_t(1) << kSlotBits> slots_{};
};

// Rasters over rectangles of global pixels, row-major.
struct VoteInputs {
  PixelRect state_rect;                // covers `out` grown by radius
  const std::vector<int32_t>& state;   // exemplar pixel y * width + x
  PixelRect guide_rect;                // covers `out` grown by radius
  const std::vector<uint8_t>& labels;  // target labels (painting classes)
  const std::vector<float>& depth;     // depth from the eye, or empty: no breaks
  double depth_break = 1.05;           // the ratio that breaks
  double balance = 0;                  // the colour excess's exponent (0: no balance)
};

// The voted exemplar pixel of each pixel of `out`, row-major. Preconditions: radius >= 0, the
// rectangles cover `out` grown by radius, the state's pixels are the level's.
std::vector<int32_t> vote(const ExemplarLevel& e, const VoteInputs& in, int radius,
                          const PixelRect& out);

}  // namespace maquette::synthesis
