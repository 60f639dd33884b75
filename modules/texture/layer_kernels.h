// The per-pixel work of one layer along a row of the planes (surface.h), on blocks of 8
// consecutive pixels: the constraint product and the blend. Two implementations with the same
// bits: plain C++ and AVX2 (8 pixels per instruction, table pairs loaded one by one), chosen at run
// time (also the table coordinates of a row). No fused multiply-add and the same operation order on
// both paths (tested).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "surface.h"

namespace maquette::texture {

inline constexpr int kBlock = 8;  // pixels of a block; rows are padded to whole blocks

// A constraint table as the kernels read it: entry i holds values i and i + 1 of the padded
// table (surface.h), so that a lookup reads one pair (one 64-bit load).
using PairTable = std::array<float, 2 * (kBins + 1)>;
PairTable pair_table(const PaddedTable& t);

// One constraint of a layer along the row: its table and the pixels' coordinates in it, or no
// coordinates: those of the current height, computed here as
// table_coordinate(height * scale + offset).
struct ConstraintRow {
  const float* pairs = nullptr;  // a PairTable
  const float* coordinate = nullptr;
};

struct ConstrainRow {
  const float* parent = nullptr;  // the parent's coverage (the root: 1 where the height is valid)
  std::span<const ConstraintRow> constraints;
  const float* height = nullptr;
  float height_scale = 1, height_offset = 0;
  float* product = nullptr;  // out: [parent > 0] times the product of the constraints
};

struct BlendRow {
  float bias = 1, noise_scale = 0, roughness_m = 0;
  std::array<float, 3> colour{};
  int layer = 0;  // what `dominant` gets where C >= 0.5 (texture.procedural: the layer's class)
  const float* parent = nullptr;   // as in ConstrainRow
  const float* product = nullptr;  // ConstrainRow::product
  const float* noise = nullptr;    // the layer's noise, or nullptr: none (0)
  float* coverage = nullptr;       // out: C = clamp((b + s N) product) parent
  std::array<float*, 3> rgb{};     // in and out, one row per channel
  float* height = nullptr;         // in and out: H + C B N
  int* dominant = nullptr;         // out: `layer` where C >= 0.5
};

struct LayerKernels {
  // out[c] = table_coordinate(values[c] * scale + offset) for c < n (surface.h).
  void (*coordinates)(const float* values, size_t n, float scale, float offset, float* out);
  // The product over the blocks listed (block b: pixels 8b .. 8b + 7); writes the blocks where
  // some product is > 0 to `kept` (may be `blocks`) and returns their number.
  size_t (*constrain)(const ConstrainRow& row, const uint16_t* blocks, size_t n, uint16_t* kept);
  // Coverage, colour, height and dominant layer over the blocks listed.
  void (*blend)(const BlendRow& row, const uint16_t* blocks, size_t n);
};

const LayerKernels& plain_kernels();
const LayerKernels* avx2_kernels();  // nullptr when the CPU has no AVX2
const LayerKernels& fastest_kernels();

}  // namespace maquette::texture
