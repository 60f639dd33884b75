// Evaluation of a surface-layer model (paper 4.2, Eq. 1 and 2) over the pixels of a tile:
// depth-first over the layers, coverage C = clamp((b + s N) prod F_i) C_parent goes only to a
// layer's children, while colour and height go on to the next layer evaluated:
//   RGB = (1 - C) RGB_in + C RGB_layer,   H' = H + C B N.
// The displacement map D of Eq. 2 is the layer's own noise N.
#pragma once

#include <vector>

#include "field.h"
#include "model.h"

namespace maquette::texture {

struct SurfaceInputs {
  Plane height;  // metres, with any ring
  Plane slope;   // degrees, same size and ring
  // Per model quantity: its plane (same size and ring), or nullptr for "height" (the current,
  // displaced height) and "slope".
  std::vector<const Plane*> quantities;
  const std::vector<Vec3d>* position = nullptr;  // per pixel of the planes (ring included)
};

struct Surface {
  std::vector<float> rgb;  // 3 per pixel of the planes, 0..255; NaN where the height is NaN
  Plane height;            // displaced height
  Plane dominant_class;    // class of the last layer with coverage >= 0.5 (NaN: none)
};

// Constraint table lookup: linear between bin centres, clamped at the ends.
float lookup(const Table& t, float unit);

Surface evaluate(const Model& model, const SurfaceInputs& in);

// Unit normals (x along columns, y up the rows, z up) of the interior from heights with ring >= 1.
std::vector<float> normals(const Plane& height, double pixel_m);

}  // namespace maquette::texture
