// Prior-aware biases for a fitted model (texture.fit's `calibrate`). The paper's sequential
// overwrite lets a layer win wherever its constraint product clears its threshold, whatever its
// class's share of the land: rare classes overwrite far more than their area. Here each level-1
// layer's bias b is chosen, from the last evaluated to the second, so that on a sample of the
// fitting pixels the pixels it would dominate (b * prod F >= 0.5, not taken by a later layer)
// are as many as the pixels observed of its class; the first layer's class takes the rest (it
// is the root's class). The model form is unchanged: texture.procedural evaluates it as is.
#pragma once

#include <cstdint>
#include <vector>

#include "model.h"

namespace maquette::texture {

// A fitting pixel: its class and, per model quantity, its bin (0..255).
struct Sample {
  int class_id = 0;
  std::vector<uint8_t> bins;
};

inline constexpr float kMaxBias = 1e6;  // odds tables scaled to 1 make small products

// Sets the biases of the level-1 layers (children of the root) of `model`.
void calibrate_biases(Model& model, const std::vector<Sample>& samples);

// Raises each constrained level-1 layer's tables to the power `power` and its bias b to
// 0.5 (2 b)^power: the pixels where b P >= 0.5 (P the product of the tables) are the same
// (noise aside), so is the dominant class, but below that the coverage falls off as P^power
// instead of linearly, so a class's colour bleeds less into the land of the others (odds tables
// are never 0: every layer partly covered every pixel, pulling each class's colour toward the
// mean of all).
// The power is lowered for a layer whose bias would exceed kMaxSharpenedBias.
inline constexpr double kMaxSharpenedBias = 1e30;
void sharpen_coverage(Model& model, double power);

}  // namespace maquette::texture
