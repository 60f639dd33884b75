#include "vegetation_plant.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <numbers>

#include "core/error.h"
#include "core/splitmix64.h"

namespace maquette::structures {
namespace {

std::array<double, 2> range(const nlohmann::json& params, const char* field, double lowest) {
  const nlohmann::json& v = params.at(field);
  if (v.size() != 2 || !(v[0].get<double>() <= v[1].get<double>()) || v[0].get<double>() < lowest)
    throw Error(std::string("params.") + field + ": " + v.dump() + " is not [min, max] with " +
                "min <= max" + (lowest > -1e300 ? " and min > 0" : ""));
  return {v[0].get<double>(), v[1].get<double>()};
}

}  // namespace

VegetationParams vegetation_params(const nlohmann::json& params) {
  VegetationParams p;
  p.random = params.at("placement") == "random";
  p.seed = params.at("seed").get<uint64_t>();
  double total = 0;
  for (const nlohmann::json& prototype : params.at("prototypes")) {
    p.prototypes.push_back(prototype.at("name").get<std::string>());
    p.cumulative_weight.push_back(total += prototype.at("weight").get<double>());
  }
  if (p.prototypes.empty() || p.prototypes.size() > 65535 || !(total > 0))
    throw Error("params.prototypes: " + params.at("prototypes").dump() +
                " must list 1 to 65,535 prototypes with weights summing above 0");
  const auto scale = range(params, "scale", 1e-300);
  p.scale_min = scale[0], p.scale_max = scale[1];
  const auto heading = range(params, "heading_deg", -1e308);
  p.heading_min_deg = heading[0], p.heading_max_deg = heading[1];
  return p;
}

PlantLook plant_look(const VegetationParams& params, int64_t feature_id, PlanePoint at) {
  uint64_t state =
      splitmix64_mix(splitmix64_mix(splitmix64_mix(params.seed ^ uint64_t(feature_id)) ^
                                    std::bit_cast<uint64_t>(at.x)) ^
                     std::bit_cast<uint64_t>(at.y));
  PlantLook look;
  look.id = state;
  const double pick = unit_interval(splitmix64_next(state)) * params.cumulative_weight.back();
  look.prototype =
      uint16_t(std::min<size_t>(size_t(std::upper_bound(params.cumulative_weight.begin(),
                                                        params.cumulative_weight.end(), pick) -
                                       params.cumulative_weight.begin()),
                                params.prototypes.size() - 1));
  look.scale = float(params.scale_min +
                     unit_interval(splitmix64_next(state)) * (params.scale_max - params.scale_min));
  look.heading_rad =
      (params.heading_min_deg +
       unit_interval(splitmix64_next(state)) * (params.heading_max_deg - params.heading_min_deg)) *
      std::numbers::pi / 180;
  return look;
}

uint32_t neighbourhood_colour(const Tile<float>& t, int col, int row) {
  // A plant on the tile's edge (or owned within the edge's rounding margin) rounds to a pixel
  // just beyond it: its neighbourhood is that of the nearest pixel of the tile.
  col = std::clamp(col, 0, t.size() - 1);
  row = std::clamp(row, 0, t.size() - 1);
  std::array<double, 3> sum{};
  std::array<int, 3> count{};
  for (int r = row - 1; r <= row + 1; ++r)
    for (int c = col - 1; c <= col + 1; ++c)
      for (int k = 0; k < 3; ++k)
        if (const float v = t.at(c, r, k); std::isfinite(v))
          sum[size_t(k)] += v, ++count[size_t(k)];
  uint32_t rgba = 0xff000000u;
  for (size_t k = 0; k < 3; ++k) {
    const double mean = count[k] ? sum[k] / count[k] : 255;
    rgba |= uint32_t(std::clamp(std::lround(mean), 0L, 255L)) << (8 * k);
  }
  return rgba;
}

}  // namespace maquette::structures
