// Evaluation of a surface-layer model (paper 4.2, Eq. 1 and 2) over the pixels of a tile:
// depth-first over the layers, coverage C = clamp((b + s N) prod F_i) C_parent goes only to a
// layer's children, while colour and height go on to the next layer evaluated:
//   RGB = (1 - C) RGB_in + C RGB_layer,   H' = H + C B N.
// The displacement map D of Eq. 2 is the layer's own noise N. Evaluated a row at a time, layer by
// layer over the blocks of 8 pixels each layer can still cover (tables and noise only there;
// layer_kernels.h).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
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
  // Positions of the planes' pixels for the noise. With pixel_m > 0, the noise is cached on the
  // global lattice of lattice_noise.h (then `position` covers ring + kNoiseLatticeReach pixels
  // around the planes), the planes' pixel (0, 0) being global face pixel (col0, row0); with
  // pixel_m = 0 it is exact at every pixel.
  const PixelPositions* position = nullptr;
  int64_t col0 = 0, row0 = 0;
  double pixel_m = 0;
};

struct Surface {
  std::vector<float> rgb;  // 3 per pixel of the planes, 0..255; NaN where the height is NaN
  Plane height;            // displaced height
  Plane dominant_class;    // class of the last layer with coverage >= 0.5 (NaN: none)
};

// Constraint table lookup: linear between bin centres, clamped at the ends. In two steps: the
// coordinate in a table of a value scaled to [0, 1) (computed once per pixel and quantity, shared
// by the layers), and the lookup there. A NaN has coordinate kBins, where a padded table holds
// zeros: the lookup needs no branch.
using PaddedTable = std::array<float, kBins + 2>;  // a table and two zeros
inline float table_coordinate(float unit) {
  return std::isnan(unit) ? float(kBins) : std::clamp(unit * kBins - 0.5f, 0.0f, float(kBins - 1));
}
PaddedTable padded(const Table& t);
inline float lookup_at(const float* table, float coordinate) {
  const int i = int(coordinate);
  const float* b = table + i;
  return b[0] + (coordinate - float(i)) * (b[1] - b[0]);
}
inline float lookup_at(const PaddedTable& t, float coordinate) {
  return lookup_at(t.data(), coordinate);
}
inline float lookup(const Table& t, float unit) {
  return lookup_at(padded(t), table_coordinate(unit));
}

// Where evaluate writes, row-major with nothing between rows: rgb (3 per pixel) and classes over
// the tile and `ring` (<= the planes' ring) pixels around it, each may be nullptr (not wanted);
// the displaced height over all of the planes. Every pixel is written (NaN where missing).
struct SurfaceTargets {
  int ring = 0;
  float* rgb = nullptr;
  float* classes = nullptr;
  float* height = nullptr;
};
void evaluate(const Model& model, const SurfaceInputs& in, const SurfaceTargets& out);
// Every output over all of the planes.
Surface evaluate(const Model& model, const SurfaceInputs& in);

// Unit normals (x along columns, y up the rows, z up) of the interior from heights with ring >= 1,
// 3 per pixel into `out`.
void normals(const Plane& height, double pixel_m, float* out);

}  // namespace maquette::texture
