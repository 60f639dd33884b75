#include "water_body.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "core/error.h"
#include "core/parallel_chunks.h"

namespace maquette::deform {
namespace {

// Pixel rows per parallel task (the level's boundary, the fill's runs): the split does not change
// any result.
constexpr int kStripRows = 16;
// Wet runs per parallel task when the lake's pixels are listed.
constexpr size_t kRunsPerTask = 512;

// f(row_begin, row_end) for the strips of kStripRows rows of `basin`, in parallel (TBB); the
// strips' own results are then combined in row order by the caller.
template <typename F>
void by_strips(const BasinRaster& basin, const F& f) {
  parallel_chunks(size_t(basin.height), kStripRows,
                  [&](size_t first, size_t last) { f(int(first), int(last)); });
}

// A run of consecutive pixels below the level in one row: columns [col0, col1).
struct Run {
  int32_t row = 0, col0 = 0, col1 = 0;
  bool outside = false;  // one of its pixels lies outside the polygon
};

// The runs of pixels below `level` of rows [row_begin, row_end), in row-major order, and the
// strip's lowest inside pixel with a known height (the first among equals; -1: none).
struct StripRuns {
  std::vector<Run> runs;
  int64_t lowest = -1;
};

StripRuns strip_runs(const BasinRaster& b, double level, int row_begin, int row_end) {
  StripRuns out;
  for (int row = row_begin; row < row_end; ++row) {
    const size_t base = size_t(row) * size_t(b.width);
    const float* terrain = b.terrain.data() + base;
    const uint8_t* inside = b.inside.data() + base;
    for (int col = 0; col < b.width; ++col) {
      const float t = terrain[col];
      if (inside[col] && !std::isnan(t) && (out.lowest < 0 || t < b.terrain[size_t(out.lowest)]))
        out.lowest = int64_t(base) + col;
      if (!(t < level)) continue;  // NaN: dry
      if (out.runs.empty() || out.runs.back().row != row || out.runs.back().col1 != col)
        out.runs.push_back({row, col, col, false});
      Run& run = out.runs.back();
      run.col1 = col + 1;
      run.outside = run.outside || !inside[col];
    }
  }
  return out;
}

// Union-find over the runs: each set's root its lowest run.
struct RunSets {
  explicit RunSets(size_t n) : parent(n) {
    for (size_t k = 0; k < n; ++k) parent[k] = uint32_t(k);
  }
  uint32_t find(uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(uint32_t a, uint32_t b) {
    a = find(a), b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
  std::vector<uint32_t> parent;
};

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
  if (basin.width <= 0 || basin.height <= 0)
    throw Error("no terrain height known on the stroke's boundary (an empty raster)");
  // The boundary's known heights in row-major order, by strips of rows.
  std::vector<std::vector<float>> strips(size_t(basin.height + kStripRows - 1) / kStripRows);
  by_strips(basin, [&](int row_begin, int row_end) {
    std::vector<float>& heights = strips[size_t(row_begin / kStripRows)];
    const int w = basin.width;
    for (int row = row_begin; row < row_end; ++row) {
      const auto line = [&](int r) {
        return r < 0 || r >= basin.height ? nullptr : basin.inside.data() + size_t(r) * size_t(w);
      };
      const uint8_t *up = line(row - 1), *mid = line(row), *down = line(row + 1);
      const float* terrain = basin.terrain.data() + size_t(row) * size_t(w);
      for (int col = 0; col < w; ++col) {
        if (!mid[col] || std::isnan(terrain[col])) continue;
        // Inside with all 8 neighbours inside: not on the boundary.
        const bool interior =
            up && down && col > 0 && col + 1 < w &&
            ((up[col - 1] != 0) & (up[col] != 0) & (up[col + 1] != 0) & (mid[col - 1] != 0) &
             (mid[col + 1] != 0) & (down[col - 1] != 0) & (down[col] != 0) & (down[col + 1] != 0));
        if (!interior) heights.push_back(terrain[col]);
      }
    }
  });
  std::vector<float> heights;
  for (const std::vector<float>& strip : strips)
    heights.insert(heights.end(), strip.begin(), strip.end());
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

namespace {

// Where the lake's water crosses the stroke: the first outside pixel of the lake's runs, in
// row-major order, with an 8-neighbour inside the polygon below the level (that neighbour is in
// the lake too, so such a pixel exists when the lake has an outside pixel).
int64_t crossing(const BasinRaster& b, double level, const std::vector<Run>& runs,
                 const std::vector<size_t>& lake_runs) {
  const auto wet_inside = [&](int row, int col) {
    if (row < 0 || row >= b.height || col < 0 || col >= b.width) return false;
    const size_t at = size_t(row) * size_t(b.width) + size_t(col);
    return b.inside[at] && b.terrain[at] < level;
  };
  for (const size_t k : lake_runs) {
    const Run& run = runs[k];
    if (!run.outside) continue;
    for (int col = run.col0; col < run.col1; ++col) {
      if (b.inside[size_t(run.row) * size_t(b.width) + size_t(col)]) continue;
      for (int dr = -1; dr <= 1; ++dr)
        for (int dc = -1; dc <= 1; ++dc)
          if (wet_inside(run.row + dr, col + dc)) return int64_t(run.row) * b.width + col;
    }
  }
  throw std::logic_error("fill_basin: a leaking lake without a crossing of its stroke");
}

}  // namespace

WaterBody fill_basin(const BasinRaster& basin, double level) {
  WaterBody body;
  body.level = level;
  if (basin.width <= 0 || basin.height <= 0) return body;
  // Each strip's runs below the level and lowest inside pixel; then in row order.
  std::vector<StripRuns> strips(size_t(basin.height + kStripRows - 1) / kStripRows);
  by_strips(basin, [&](int row_begin, int row_end) {
    strips[size_t(row_begin / kStripRows)] = strip_runs(basin, level, row_begin, row_end);
  });
  std::vector<Run> runs;
  for (const StripRuns& strip : strips) {
    if (strip.lowest >= 0 &&
        (body.seed < 0 || basin.terrain[size_t(strip.lowest)] < basin.terrain[size_t(body.seed)]))
      body.seed = strip.lowest;
    runs.insert(runs.end(), strip.runs.begin(), strip.runs.end());
  }
  if (body.seed < 0 || !(basin.terrain[size_t(body.seed)] < level)) return body;

  // The runs' 8-connected sets: a run touches a run of the next row whose columns overlap its
  // own widened by one. Each row's runs against the next row's, in one sweep.
  RunSets sets(runs.size());
  size_t seed_run = 0;
  const int seed_row = int(body.seed / basin.width), seed_col = int(body.seed % basin.width);
  for (size_t i = 0, j = 0; i < runs.size(); ++i) {
    const Run& a = runs[i];
    if (a.row == seed_row && a.col0 <= seed_col && seed_col < a.col1) seed_run = i;
    while (j < runs.size() &&
           (runs[j].row <= a.row || (runs[j].row == a.row + 1 && runs[j].col1 < a.col0)))
      ++j;
    for (size_t k = j; k < runs.size() && runs[k].row == a.row + 1 && runs[k].col0 <= a.col1; ++k)
      sets.unite(uint32_t(i), uint32_t(k));
  }
  // The lake: the seed's set, its runs in row-major order. A run with a pixel outside the polygon
  // is a leak.
  const uint32_t lake = sets.find(uint32_t(seed_run));
  std::vector<size_t> wet_runs;
  std::vector<size_t> first{0};  // each wet run's first place in body.wet
  bool leaks = false;
  for (size_t k = 0; k < runs.size(); ++k) {
    if (sets.find(uint32_t(k)) != lake) continue;
    leaks = leaks || runs[k].outside;
    wet_runs.push_back(k);
    first.push_back(first.back() + size_t(runs[k].col1 - runs[k].col0));
  }
  if (leaks)
    return WaterBody{level, body.seed, {}, {}, 0, 0, crossing(basin, level, runs, wet_runs)};
  body.wet.resize(first.back());
  body.depth.resize(first.back());
  parallel_chunks(wet_runs.size(), kRunsPerTask, [&](size_t begin, size_t end) {
    for (size_t w = begin; w < end; ++w) {
      const Run& run = runs[wet_runs[w]];
      const int64_t base = int64_t(run.row) * basin.width;
      for (int col = run.col0; col < run.col1; ++col) {
        const size_t at = first[w] + size_t(col - run.col0);
        body.wet[at] = base + col;
        body.depth[at] = float(level - double(basin.terrain[size_t(base + col)]));
      }
    }
  });
  double volume = 0;  // summed in row-major order: the same bits for any threads
  for (const float d : body.depth) volume += double(d);
  body.area_m2 = double(body.wet.size()) * basin.pixel_area_m2;
  body.volume_m3 = volume * basin.pixel_area_m2;
  return body;
}

}  // namespace maquette::deform
