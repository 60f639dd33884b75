// Runs deform.features on a region mosaic as the runner would: the strokes on its "strokes" port,
// an all-NaN output DEM `refine` levels finer, `params` (energy weight 0.01, adaptive subdivision
// unless given); returns the output mosaic's DEM. The mosaic's outer sample on every side is the
// runner's halo (the operator's spec): not of the region, its output cut off by the runner.
#pragma once

#include <cmath>
#include <vector>

#include "../operators.h"
#include "runtime/operator.h"

namespace maquette::deform {

inline Tile<float> deform_run(Mosaic input, const std::vector<const VectorFeature*>& strokes,
                              int refine = 0, json params = {{"energy_weight", 0.01}}) {
  input.features["strokes"] = strokes;
  Mosaic output = input;
  output.features.clear();
  output.level += refine;
  output.layers.at("dem") = Tile<float>(input.layers.at("dem").size() << refine, 1, 0, NAN);
  params["subdivision"] = params.value("subdivision", "adaptive");
  const auto op = make_features();
  static_cast<const RegionOperator&>(*op).run({&default_grid(), &params, nullptr}, input, output);
  return output.layers.at("dem");
}

// The samples of `input`'s mosaic `refine` levels finer (the same place, 2^refine more a side):
// where deform_run's output lies.
inline Mosaic finer(const Mosaic& input, int refine) {
  Mosaic m;
  m.face = input.face;
  m.level = input.level + refine;
  m.origin_col = input.origin_col << refine;
  m.origin_row = input.origin_row << refine;
  return m;
}

}  // namespace maquette::deform
