// The Zion example (examples/texture-zion.json) through the real program on
// ../shared/data/zion: its ingest and terrain steps, its classify and fit steps on the western
// half of the cells, its procedural and assess steps on the eastern half. Held-out Cohen's kappa
// 0.652 >= 0.6 (issue 5), with every choice of the example made on the western cells alone (a
// north/south cross-validation inside them, modules/texture/README.md "Zion"); the same model
// and assessment with 1 and 2 threads, and the texture two levels finer than the DEM without
// seams between tiles. Skipped when the data is absent.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <string>

#include "core/tile.h"
#include "run_cli.h"
#include "store/store.h"

namespace maquette::test {
namespace {

using json = nlohmann::json;

const std::string kZion = std::string(MAQUETTE_SHARED_DIR) + "/data/zion";

// The cell columns of the example's region split at -113.027 (a cell border at levels 10 and
// 11): the bboxes stop short of it so that no cell is in both halves.
const json kWest = {{"bbox", {-113.24, 37.13, -113.04, 37.51}}};
const json kEast = {{"bbox", {-113.02, 37.13, -112.85, 37.51}}};

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The example's steps of the given operators on `region`, with the store in `dir` and the
// ingest sources in kZion.
std::string pipeline(const std::string& dir, const json& region,
                     const std::vector<std::string>& ops) {
  json p = json::parse(slurp(std::string(MAQUETTE_SOURCE_DIR) + "/examples/texture-zion.json"));
  p["store"] = dir + "/zion.mqt";
  p["region"] = region;
  json steps = json::array();
  for (json s : p["steps"]) {
    if (std::find(ops.begin(), ops.end(), s["op"].get<std::string>()) == ops.end()) continue;
    if (s["op"] == "ingest")
      for (json& source : s["params"]["sources"])
        source = kZion + "/" + std::filesystem::path(source.get<std::string>()).filename().string();
    steps.push_back(s);
  }
  p["steps"] = steps;
  const std::string path = dir + "/" + std::to_string(ops.size()) + ".json";
  std::ofstream(path) << p.dump(1);
  return path;
}

struct Outcome {
  std::string dir;           // holding zion.mqt
  std::string model, table;  // model artifact, assessment table
  double kappa = -1;
};

// Ingest and the hillshade (the example's steps, whole region), fit west, render and assess east,
// with `threads` workers.
Outcome fit_and_assess(int threads) {
  const std::string dir = temp_dir();
  const std::string t = " --threads " + std::to_string(threads) + " ";
  const json whole = json::parse(
      slurp(std::string(MAQUETTE_SOURCE_DIR) + "/examples/texture-zion.json"))["region"];
  const CliResult ingest =
      run_maquette("-q run" + t + pipeline(dir, whole, {"ingest", "terrain.derive"}));
  EXPECT_EQ(ingest.exit_code, 0) << ingest.err;
  const CliResult fit =
      run_maquette("-q run" + t + pipeline(dir, kWest, {"texture.classify", "texture.fit"}));
  EXPECT_EQ(fit.exit_code, 0) << fit.err;
  const CliResult assess = run_maquette(
      "-q run" + t +
      pipeline(dir, kEast, {"texture.classify", "texture.procedural", "texture.assess"}));
  EXPECT_EQ(assess.exit_code, 0) << assess.err;
  const auto store = Store::open(dir + "/zion.mqt", Store::Mode::ReadOnly);
  const auto model = store->get_artifact("model");
  Outcome o{dir, model ? std::string(model->text()) : std::string(), assess.out};
  std::smatch m;
  if (std::regex_search(o.table, m, std::regex("kappa (-?[0-9.]+)"))) o.kappa = std::stod(m[1]);
  return o;
}

// Sum of the channels of pixel (c, r).
double value(const Tile<float>& t, int c, int r) {
  double s = 0;
  for (int k = 0; k < t.channels(); ++k) s += t.at(c, r, k);
  return s;
}

// Across every border between horizontally adjacent tiles of `layer`, in a strip of 2 x 64
// columns around it, over the rows where the strip has data everywhere: the mean step between
// the two border columns is within the range of the mean steps between neighbouring columns
// inside the strip (a seam's gradient looks like any other).
void expect_seamless(const Store& store, const std::string& layer) {
  constexpr int kHalfStrip = 64;
  const std::optional<double> layer_nodata = store.require_layer(layer).nodata;
  const double* nodata = layer_nodata ? &*layer_nodata : nullptr;
  int borders = 0;
  for (const CellId a : store.tile_cells(layer)) {
    if (a.col() + 1 >= (1u << a.level())) continue;
    const CellId b = CellId::FromFaceColRow(a.face(), a.level(), a.col() + 1, a.row());
    if (!store.has_tile(layer, b)) continue;
    const Tile<float> ta = to_tile<float>(*store.get_tile(layer, a), nodata),
                      tb = to_tile<float>(*store.get_tile(layer, b), nodata);
    const int m = ta.size();
    // Strip column j in [0, 2 kHalfStrip): a's column m - kHalfStrip + j, then b's columns.
    const auto strip = [&](int j, int r) {
      return j < kHalfStrip ? value(ta, m - kHalfStrip + j, r) : value(tb, j - kHalfStrip, r);
    };
    std::vector<int> rows;
    for (int r = 0; r < m; ++r) {
      bool complete = true;
      for (int j = 0; j < 2 * kHalfStrip; ++j) complete = complete && std::isfinite(strip(j, r));
      if (complete) rows.push_back(r);
    }
    if (rows.size() < 64) continue;      // at the edge of the data
    const auto mean_step = [&](int j) {  // between strip columns j - 1 and j
      double sum = 0;
      for (int r : rows) sum += std::abs(strip(j, r) - strip(j - 1, r));
      return sum / double(rows.size());
    };
    double hi = 0;
    for (int j = 1; j < 2 * kHalfStrip; ++j)
      if (j != kHalfStrip) hi = std::max(hi, mean_step(j));
    EXPECT_GT(hi, 0) << a.ToText();
    EXPECT_LE(mean_step(kHalfStrip), hi)
        << "a seam between " << a.ToText() << " and " << b.ToText();
    ++borders;
  }
  EXPECT_GT(borders, 0) << "no adjacent tiles of " << layer << " with data";
}

TEST(Zion, HeldOutKappaAndDeterminism) {
  if (!std::filesystem::exists(kZion + "/srtm.tif"))
    GTEST_SKIP() << "../shared/data/zion is absent";
  const Outcome one = fit_and_assess(1);
  std::cout << one.table;
  EXPECT_NEAR(one.kappa, 0.652, 0.005) << one.table;  // measured 0.6517; the goal is 0.6
  const json model = json::parse(one.model);
  ASSERT_EQ(model["fitted_classes"].size(), 2u);  // dark and light, both fitted on the west
  const Outcome two = fit_and_assess(2);
  EXPECT_EQ(one.model, two.model);  // same bits
  EXPECT_EQ(one.table, two.table);  // same confusion matrix, kappa and colour difference

  const auto store = Store::open(two.dir + "/zion.mqt", Store::Mode::ReadOnly);
  ASSERT_EQ(store->require_layer("texture_fine").tile_size,
            store->require_layer("dem").tile_size * 4);  // two levels finer
  expect_seamless(*store, "texture_fine");
  expect_seamless(*store, "texture_height");
}

}  // namespace
}  // namespace maquette::test
