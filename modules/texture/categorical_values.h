// Categorical rasters (the land cover) at any level without their pixels' squares: a layer's
// table on a categorical quantity is read at the input pixels (one code, one value: no code is
// blended with another), and the logs of those values, not the codes, are interpolated by the
// cubic B-spline of every other quantity (prefiltered, so that it passes through them). A class
// border drawn by the codes becomes a smooth curve, and a lone pixel of another code a round
// patch instead of a square or a ragged island. The model is evaluated unchanged otherwise: the
// categorical quantity is replaced by one quantity per layer with a table on it, holding that
// layer's log values, read through a table of their exponentials.
#pragma once

#include <string>
#include <vector>

#include "core/tile.h"
#include "model.h"

namespace maquette::texture {

// `model` with its categorical quantity (if any) replaced: per layer with a table on it, a
// quantity named "<quantity>/<layer index>" of range [kLogFloor, 0] widened by half a bin at
// each end (so that the log value v has table coordinate 255 (1 - v / kLogFloor)) read through
// the table exp(kLogFloor (1 - i / 255)); `tables[k]` is the original table of the k-th quantity
// added, `source[k]` the name of its raster. Preconditions: at most one categorical quantity.
struct CategoricalSplit {
  Model model;
  std::vector<Table> tables;
  std::vector<std::string> source;
};
CategoricalSplit split_categorical(const Model& model);

// The log of the smallest value kept (about float's smallest normal): the tables' values span
// dozens of orders of magnitude (odds products, sharpened), so they are interpolated as logs.
inline constexpr double kLogFloor = -87;

// Input pixels beyond the B-spline's kInputHalo that the prefilter reads.
inline constexpr int kPrefilterReach = 3;

// The coefficients of the cubic B-spline that interpolates the logs of the table's values
// (floored at kLogFloor) at the pixels of `codes` (halo >= kInputHalo + kPrefilterReach; NaN
// spreads kPrefilterReach pixels), code c read at bin round(c) (the range [-0.5, 255.5]: a bin
// per code), clamped to 0..255: the logs prefiltered by the inverse of the B-spline's (1, 4, 1)
// / 6, so that the spline (field.h upsample) passes through them at the input pixels' centres
// (within 0.5 % of their spread) and the model reads at the input's own level what texture.fit
// fitted. The halo is kPrefilterReach smaller than `codes`'.
Tile<float> categorical_values(const Tile<float>& codes, const Table& table);

}  // namespace maquette::texture
