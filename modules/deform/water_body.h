// A body of water in a closed stroke (paper 002, section 4): the lake a basin holds below a
// level, on a raster of terrain heights. Pure computation on one raster (no grid, no store):
// deform.water hands it the region's mosaic and the stroke's pixels; the tests hand it GeoTIFFs
// that GRASS r.lake reads too.
//
// Contract:
// - `terrain` holds width x height heights (metres, row-major, NaN: nodata), `inside` as many
//   flags (non-zero: the pixel's centre lies inside the stroke's polygon); every pixel has the
//   area `pixel_area_m2` (rHEALPix pixels are equal-area).
// - The boundary is the inside pixels with an 8-neighbour outside the polygon or beyond the
//   raster. The level is `WaterLevel`'s: the lowest boundary height (the spill level, default), a
//   given height, or a percentile of the boundary heights (nearest rank). Nodata boundary pixels
//   do not count; a stroke with no known boundary height and no given level is an error.
// - The lake is GRASS r.lake's: the pixels with height < level 8-connected to the seed, the
//   lowest inside pixel (the first in row-major order among equals), through pixels < level.
//   Nodata pixels are dry and stop the water. When the seed is not below the level there is no
//   lake (an empty body).
// - A leak, the water reaching a pixel outside the polygon (a given level above the spill level),
//   is reported in `leak` (where the water crosses the stroke: the first outside pixel of the lake,
//   in row-major order, with an 8-neighbour inside the polygon below the level) and the lake is
//   not filled:
//   `wet` is then empty.
// How: the runs of pixels below the level, row by row, in parallel by strips of rows (TBB); the
// runs of neighbouring rows joined into 8-connected sets (union-find, one sweep); the seed's set is
// the lake. Its result does not depend on the order of that work: the same bits for any threads.
// Time linear in the pixels, memory in the runs and the lake. water_level also by strips.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace maquette::deform {

// How the level is chosen (the stroke's `level` and `level_rule` attributes).
struct WaterLevel {
  enum class Rule { Spill, Given, Percentile } rule = Rule::Spill;
  double value = 0;  // Given: the level (m); Percentile: the percentile in [0, 100]

  // From a stroke's attributes: `level` (number, metres) wins; else `level_rule`: "spill"
  // (default) or "percentile:P" with P in [0, 100]. Errors name `where`, the field and value.
  static WaterLevel from_attributes(const nlohmann::json& attributes, const std::string& where);
};

struct BasinRaster {
  int width = 0, height = 0;
  std::span<const float> terrain;   // width * height, NaN: nodata
  std::span<const uint8_t> inside;  // width * height, non-zero: inside the polygon
  double pixel_area_m2 = 0;
};

struct WaterBody {
  double level = 0;          // metres
  int64_t seed = -1;         // the lowest inside pixel (row-major index), -1: none known
  std::vector<int64_t> wet;  // the lake's pixels, sorted
  std::vector<float> depth;  // level - terrain, per wet pixel
  double area_m2 = 0, volume_m3 = 0;
  std::optional<int64_t> leak;  // where the water crosses the stroke (above)
};

// The level `rule` gives on `basin`'s boundary; throws when no boundary height is known (and the
// level is not given). Errors are maquette::Error.
double water_level(const BasinRaster& basin, const WaterLevel& rule);

// The lake of `basin` at `level` (see the contract above).
WaterBody fill_basin(const BasinRaster& basin, double level);

}  // namespace maquette::deform
