// Agreement statistics from a merged confusion count {"obs,pred": n} (pred -1: no class).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace maquette::texture {

// {"classes", "confusion" (rows observed, columns predicted, last column: none), "accuracy",
//  "producers_accuracy" {class: share of its observed pixels predicted as it}, "class_colours"
//  {class: image and texture mean RGB, their CIEDE2000, spreads and ratio, and the ratio of
//  spreads after the blur (with moments "image_blurred" and "texture_blurred")} (with moments),
//  "kappa" (Cohen's), "proportions" {class: {observed, predicted}}, "ciede2000_mean", "pixels"}.
// With "confusion_unfiltered" in `merged` (texture.assess's predicted classes before its
// majority filter), also "unfiltered": {"confusion", "accuracy", "kappa", "producers_accuracy"}.
nlohmann::json assessment(const nlohmann::json& merged);
std::string assessment_table(const nlohmann::json& report);

}  // namespace maquette::texture
