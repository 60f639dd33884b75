// Surface types in hue-saturation space (paper 5.2.1): near-grey pixels, whose hue is
// meaningless, get a user-defined hue; classes are boxes in hue-saturation(-value) or the
// nearest of given cluster centres (texture.classify, texture.fit's k-means).
#pragma once

#include <array>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <vector>

#include "colour.h"

namespace maquette::texture {

struct Box {
  int id = 0;
  std::array<double, 2> hue{0, 360}, saturation{0, 1}, value{0, 1};  // hue lo > hi wraps
};

struct Centre {
  int id = 0;
  double hue = 0, saturation = 0;
};

struct HsClassifier {
  double grey_threshold = 10;  // max(R,G,B) - min(R,G,B) at or below: grey
  double grey_hue = 300;       // hue given to grey pixels (purple: absent from landscapes)
  std::vector<Box> boxes;      // first match wins
  std::vector<Centre> centres;

  static HsClassifier from_params(const nlohmann::json& params);  // boxes/centres may be absent
  Hsv hsv(double r, double g, double b) const;                    // with the grey rule
  int classify(double r, double g, double b) const;               // -1: no class
};

// Schema properties of the grey rule's parameters, shared by the operators that read colours.
nlohmann::json grey_params_schema();

// Hue-saturation as a point of the colour wheel (saturation the radius).
std::array<double, 2> wheel(double hue, double saturation);

}  // namespace maquette::texture
