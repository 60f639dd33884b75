#include "water_body.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/error.h"

namespace maquette::deform {
namespace {

constexpr int kDc[8] = {-1, 0, 1, -1, 1, -1, 0, 1};
constexpr int kDr[8] = {-1, -1, -1, 0, 0, 1, 1, 1};

bool is_boundary(const BasinRaster& b, int col, int row) {
  for (int k = 0; k < 8; ++k) {
    const int c = col + kDc[k], r = row + kDr[k];
    if (c < 0 || r < 0 || c >= b.width || r >= b.height) return true;
    if (!b.inside[size_t(r) * size_t(b.width) + size_t(c)]) return true;
  }
  return false;
}

}  // namespace

WaterLevel WaterLevel::from_attributes(const nlohmann::json& attributes, const std::string& where) {
  const auto level = attributes.find("level");
  if (level != attributes.end() && !level->is_null()) {
    if (!level->is_number() || !std::isfinite(level->get<double>()))
      throw Error(where + ": field 'level' must be a number of metres, not " + level->dump());
    return {Rule::Given, level->get<double>()};
  }
  const auto rule = attributes.find("level_rule");
  if (rule == attributes.end() || rule->is_null()) return {};
  const std::string text = rule->is_string() ? rule->get<std::string>() : rule->dump();
  if (text == "spill") return {};
  const std::string prefix = "percentile:";
  if (text.rfind(prefix, 0) == 0) {
    try {
      size_t used = 0;
      const std::string number = text.substr(prefix.size());
      const double p = std::stod(number, &used);
      if (used == number.size() && p >= 0 && p <= 100) return {Rule::Percentile, p};
    } catch (const std::logic_error&) {
    }
  }
  throw Error(where + ": field 'level_rule' must be \"spill\" or \"percentile:P\" " +
              "with P in [0, 100], not " + rule->dump());
}

double water_level(const BasinRaster& basin, const WaterLevel& rule) {
  if (rule.rule == WaterLevel::Rule::Given) return rule.value;
  std::vector<float> heights;
  for (int row = 0; row < basin.height; ++row)
    for (int col = 0; col < basin.width; ++col) {
      const size_t i = size_t(row) * size_t(basin.width) + size_t(col);
      if (basin.inside[i] && !std::isnan(basin.terrain[i]) && is_boundary(basin, col, row))
        heights.push_back(basin.terrain[i]);
    }
  if (heights.empty())
    throw Error(
        "no terrain height known on the stroke's boundary (its pixels there are nodata, or it "
        "holds no pixel centre: draw it around the basin)");
  if (rule.rule == WaterLevel::Rule::Spill)
    return *std::min_element(heights.begin(), heights.end());
  // Nearest rank: the smallest height with at least P % of the boundary at or below it.
  const size_t rank = size_t(std::ceil(rule.value / 100 * double(heights.size())));
  const size_t k = std::clamp<size_t>(rank, 1, heights.size()) - 1;
  std::nth_element(heights.begin(), heights.begin() + ptrdiff_t(k), heights.end());
  return heights[k];
}

WaterBody fill_basin(const BasinRaster& basin, double level) {
  WaterBody body;
  body.level = level;
  const size_t n = size_t(basin.width) * size_t(basin.height);
  for (size_t i = 0; i < n; ++i)
    if (basin.inside[i] && !std::isnan(basin.terrain[i]) &&
        (body.seed < 0 || basin.terrain[i] < basin.terrain[size_t(body.seed)]))
      body.seed = int64_t(i);
  if (body.seed < 0 || !(basin.terrain[size_t(body.seed)] < level)) return body;

  std::vector<uint8_t> seen(n, 0);
  std::vector<int64_t> queue{body.seed};
  seen[size_t(body.seed)] = 1;
  for (size_t head = 0; head < queue.size(); ++head) {
    const int64_t i = queue[head];
    if (!basin.inside[size_t(i)]) {
      body.leak = i;
      return WaterBody{level, body.seed, {}, {}, 0, 0, i};
    }
    const int col = int(i % basin.width), row = int(i / basin.width);
    const bool interior = col > 0 && row > 0 && col + 1 < basin.width && row + 1 < basin.height;
    for (int k = 0; k < 8; ++k) {
      const int c = col + kDc[k], r = row + kDr[k];
      if (!interior && (c < 0 || r < 0 || c >= basin.width || r >= basin.height)) continue;
      const size_t j = size_t(r) * size_t(basin.width) + size_t(c);
      if (seen[j] || !(basin.terrain[j] < level)) continue;  // NaN: dry
      seen[j] = 1;
      queue.push_back(int64_t(j));
    }
  }
  // The wet pixels in row-major order: a pass over the seen flags (linear, where sorting the
  // fill's queue costs n log n).
  body.wet.reserve(queue.size());
  body.depth.reserve(queue.size());
  double volume = 0;
  for (size_t i = 0; i < n; ++i) {
    if (!seen[i]) continue;
    const float d = float(level - double(basin.terrain[i]));
    body.wet.push_back(int64_t(i));
    body.depth.push_back(d);
    volume += double(d);
  }
  body.area_m2 = double(body.wet.size()) * basin.pixel_area_m2;
  body.volume_m3 = volume * basin.pixel_area_m2;
  return body;
}

}  // namespace maquette::deform
