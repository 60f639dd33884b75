// Surface types in hue-saturation space (paper 5.2.1): near-grey pixels, whose hue is
// meaningless, get a user-defined hue; classes are boxes in hue-saturation(-value), polygons
// drawn on the colour wheel (s cos h, s sin h), or the nearest of given cluster centres
// (texture.classify, from texture.cluster): nearest on the colour wheel, or in
// (s cos h, s sin h, v) when the centres give a value, or in texture.cluster's "lab" points
// (a*, b*, w L*) when they are CIELAB colours.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "colour.h"

namespace maquette::texture {

struct Box {
  int id = 0;
  std::array<double, 2> hue{0, 360}, saturation{0, 1}, value{0, 1};  // hue lo > hi wraps
};

// A class drawn on texture.cluster's density plot: vertices on the colour wheel, so a polygon
// may enclose the grey point (the origin) or span hue 0 without special cases.
struct Polygon {
  int id = 0;
  std::vector<std::array<double, 2>> vertices;  // wheel(hue, saturation)

  // Even-odd rule (parts of a self-intersecting polygon covered twice are outside), closed:
  // points on an edge or vertex are inside.
  bool contains(const std::array<double, 2>& point) const;
};

struct Centre {
  int id = 0;
  double hue = 0, saturation = 0;
  double value = NAN;      // NaN: not given (every centre gives it, or none)
  std::optional<Lab> lab;  // a CIELAB centre instead (every centre is, or none)
};

struct HsClassifier {
  double grey_threshold = 10;     // max(R,G,B) - min(R,G,B) at or below: grey
  double grey_hue = 300;          // hue given to grey pixels (purple: absent from landscapes)
  std::vector<Box> boxes;         // first match wins
  std::vector<Polygon> polygons;  // then the first polygon containing the pixel
  std::vector<Centre> centres;    // then the nearest centre

  // Boxes, polygons and centres may be absent; throws maquette::Error naming the field and value
  // for a polygon of fewer than 3 points, a point that is not [hue 0..360, saturation 0..1], or
  // points on one line, when only some centres give a value, a centre that gives neither hue
  // and saturation nor L, a and b, and when only some centres are CIELAB colours.
  static HsClassifier from_params(const nlohmann::json& params);
  Hsv hsv(double r, double g, double b) const;       // with the grey rule
  int classify(double r, double g, double b) const;  // -1: no class
};

// Schema properties of the grey rule's parameters, shared by the operators that read colours.
nlohmann::json grey_params_schema();

// Hue-saturation as a point of the colour wheel (saturation the radius).
std::array<double, 2> wheel(double hue, double saturation);

}  // namespace maquette::texture
