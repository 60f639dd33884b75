// Categorical rasters (the land cover) at levels finer than their own, without their pixels'
// squares: each target pixel takes the code of the input pixel at its centre displaced by a
// smooth warp, so a class border drawn by the codes becomes an irregular curve instead of a
// staircase of input pixels. No code is blended with another (a pixel reads exactly one code).
// The warp is a function of the position in global input pixels (two octaves of value noise on
// lattices of 2 and 1 input pixels, quintic fade), the same for every tile, thread and level: a
// pixel and its children read it at their own centres, and tiles meet without seams.
#pragma once

#include <array>
#include <cstdint>

#include "core/tile.h"
#include "field.h"

namespace maquette::texture {

// Largest displacement along either axis, in input pixels (the two octaves' amplitudes summed).
inline constexpr double kMaxCategoricalWarp = 0.75;

// Displacement (along columns, along rows) in input pixels at the point (x, y) in global input
// pixels (pixel i spans [i, i + 1)); continuous with continuous first derivatives, each
// component within kMaxCategoricalWarp.
std::array<double, 2> categorical_warp(double x, double y);

// `tile` (halo >= kInputHalo; its pixel (0, 0) is global input pixel (col0, row0)) at the target
// pixels of a tile `refine` levels finer, with `ring` (<= 2) extra pixels: each target pixel
// takes the input pixel containing its centre displaced by categorical_warp.
void nearest_warped(const Tile<float>& tile, int64_t col0, int64_t row0, int refine, int ring,
                    Plane& out);

}  // namespace maquette::texture
