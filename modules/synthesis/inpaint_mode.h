// The weighted mode of a pixel's votes (inpaint.h: the finest level's last maximization step):
// Wexler, Shechtman and Irani's mean-shift ("Space-time completion of video", PAMI 2007, §3.2).
// Where the patches covering a pixel disagree, the votes' mean blurs them; the mode takes the
// value most of them agree on.
#pragma once

#include <cstddef>

namespace maquette::synthesis {

// The votes' bandwidth for their mode: the kernel's variance over the votes' weighted variance
// about their mean. Relative, so the same for colours and heights in metres.
inline constexpr double kModeBandwidth = 0.25;
// Mean-shift steps at most, and the step (squared, over the kernel's variance) that ends them.
inline constexpr int kModeSteps = 10;
inline constexpr double kModeSettled = 1e-4;

// The weighted mode of `count` votes (`values`: `channels` each; `weights`, positive) nearest
// their weighted mean, by mean-shift from that mean with a Gaussian kernel of variance
// kModeBandwidth times the votes' weighted variance about it (the distance over all channels at
// once: a vector, not a mode per channel). `mode`: in, the votes' weighted mean; out, the mode,
// unchanged when the votes agree (one vote gives itself). `next`: room for `channels`. A vote of
// weight k counts as k votes of weight 1. Precondition: count >= 1.
void mean_shift_mode(const float* const* values, const double* weights, size_t count, int channels,
                     double* mode, double* next);

}  // namespace maquette::synthesis
