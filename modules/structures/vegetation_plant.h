// What structures.vegetation makes of each placed plant: its look drawn from the step's params
// (a prototype by weight, a scale and a heading uniform in their ranges), from a hash of the seed,
// the stroke and the plant's position in the stroke's plane (so the same plant whatever cell
// makes it), and what the rasters under it give: the base height (the DEM, bilinear) and the
// colour (the orthophoto's mean over the 3 x 3 pixels around it).
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/grid.h"
#include "core/tile.h"

namespace maquette::structures {

struct VegetationParams {
  bool random = false;  // "placement": "random" (vegetation_random.h), else "poisson"
  uint64_t seed = 0;
  std::vector<std::string> prototypes;
  std::vector<double> cumulative_weight;  // of prototypes, increasing to the total
  double scale_min = 1, scale_max = 1;
  double heading_min_deg = 0, heading_max_deg = 0;
};

// From the step's validated params (the operator's schema, defaults filled in). Throws
// maquette::Error naming the field and value at fault: no prototype, weights summing to 0, more
// than 65,535 prototypes, a range that is not [min, max] with min <= max, a scale <= 0.
VegetationParams vegetation_params(const nlohmann::json& params);

struct PlantLook {
  uint64_t id = 0;  // unique within the layer, from the stroke and the position
  uint16_t prototype = 0;
  float scale = 1;
  double heading_rad = 0;  // about the vertical, counter-clockwise seen from above
};

PlantLook plant_look(const VegetationParams& params, int64_t feature_id, PlanePoint at);

// Samples of a tile at fractional pixel coordinates (col, row of pixel centres, halo >= 1): the
// bilinear height is core/tile_bilinear.h's bilinear().
// RGBA8 (R in the low byte, alpha 255): the mean of the first three channels over the 3 x 3
// pixels around (col, row) rounded, clamped to 0..255; NaN samples are left out (none: white).
// (col, row) beyond the tile is taken to its nearest pixel. Precondition: t.halo() >= 1.
uint32_t neighbourhood_colour(const Tile<float>& t, int col, int row);

}  // namespace maquette::structures
