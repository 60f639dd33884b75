// The Zion example (examples/texture-zion.json) through the real program on
// ../shared/data/zion: its ingest and terrain steps, its cluster, classify and fit steps on the
// western half of the cells, its procedural and assess steps on the eastern half. The scene is
// the Landsat bands calibrated to true colour (texture.calibrate). Gates of issue 14 on the
// eastern half: at least 4 surface types found by texture.cluster (CIELAB) and kept by the fit,
// on height, slope, the categorical NLCD land cover and the share of barren land around each
// pixel (texture.landcover_share); the blurred CIEDE2000 <= 6; each class's
// mean colour within CIEDE2000 5 of the scene's and its colour spread within 50-150 % of the
// scene's at its pixels, 50-170 % after a blur of 4 pixels (class colours from the pixels whose
// own colour class it is, lit: colour_min_incidence_cos); and, for the goals not met
// (modules/texture/NOTES.md), the measured values as floors against regressions: kappa (the
// predicted classes compared after the observed map's majority filter, and as rendered), the
// classes with a producer's accuracy of 0.5. The rest of the assessment printed. The same model and
// assessment with 1 and 2 threads, and the texture two levels finer than the DEM without seams
// between tiles, with detail finer than the DEM's and no dark blotches. Skipped when the data is
// absent.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "core/tile.h"
#include "run_cli.h"
#include "store/store.h"
#include "stored_layers.h"

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
  json report;               // the assessment artifact
};

// Ingest and the hillshade (the example's steps, whole region), fit west, render and assess east,
// with `threads` workers.
Outcome fit_and_assess(int threads) {
  const std::string dir = temp_dir();
  const std::string t = " --threads " + std::to_string(threads) + " ";
  const json whole = json::parse(
      slurp(std::string(MAQUETTE_SOURCE_DIR) + "/examples/texture-zion.json"))["region"];
  const CliResult ingest = run_maquette(
      "-q run" + t +
      pipeline(dir, whole,
               {"ingest", "texture.calibrate", "terrain.derive", "texture.landcover_share"}));
  EXPECT_EQ(ingest.exit_code, 0) << ingest.err;
  const CliResult fit = run_maquette(
      "-q run" + t + pipeline(dir, kWest, {"texture.cluster", "texture.classify", "texture.fit"}));
  EXPECT_EQ(fit.exit_code, 0) << fit.err;
  const CliResult assess = run_maquette(
      "-q run" + t +
      pipeline(dir, kEast, {"texture.classify", "texture.procedural", "texture.assess"}));
  EXPECT_EQ(assess.exit_code, 0) << assess.err;
  const auto store = Store::open(dir + "/zion.mqt", Store::Mode::ReadOnly);
  const auto model = store->get_artifact("model");
  const auto report = store->get_artifact("assessment");
  return {dir, model ? std::string(model->text()) : std::string(), assess.out,
          report ? json::parse(report->text()) : json()};
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
  int borders = 0;
  for (const CellId a : store.tile_cells(layer)) {
    if (a.col() + 1 >= (1u << a.level())) continue;
    const CellId b = CellId::FromFaceColRow(a.face(), a.level(), a.col() + 1, a.row());
    if (!store.has_tile(layer, b)) continue;
    const Tile<float> ta = float_tile(store, layer, a), tb = float_tile(store, layer, b);
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

// Per class of `classes` (a categorical layer), the spread (root mean of the channels'
// variances, as texture.assess's) of `imagery`'s pixels of that class, over every tile.
std::map<std::string, double> class_spreads(const Store& store, const std::string& imagery,
                                            const std::string& classes) {
  std::map<std::string, std::array<double, 7>> m;  // n, sums, squares
  for (const CellId cell : store.tile_cells(classes)) {
    const Tile<float> c = float_tile(store, classes, cell), t = float_tile(store, imagery, cell);
    for (int r = 0; r < c.size(); ++r)
      for (int col = 0; col < c.size(); ++col) {
        if (!std::isfinite(c.at(col, r)) || !std::isfinite(t.at(col, r, 0))) continue;
        auto& s = m[std::to_string(int(c.at(col, r)))];
        s[0] += 1;
        for (int k = 0; k < 3; ++k) s[size_t(1 + k)] += t.at(col, r, k);
        for (int k = 0; k < 3; ++k) s[size_t(4 + k)] += double(t.at(col, r, k)) * t.at(col, r, k);
      }
  }
  std::map<std::string, double> out;
  for (const auto& [k, s] : m) {
    double var = 0;
    for (size_t i = 0; i < 3; ++i) var += (s[4 + i] / s[0] - std::pow(s[1 + i] / s[0], 2)) / 3;
    out[k] = std::sqrt(std::max(0.0, var));
  }
  return out;
}

// Brightness: the mean of the channels of pixel (c, r).
double brightness(const Tile<float>& t, int c, int r) {
  return (double(t.at(c, r, 0)) + t.at(c, r, 1) + t.at(c, r, 2)) / 3;
}

// Per own class (pixel_classes), the 2nd percentile of the brightness of the scene's pixels lit
// at cos i >= the fit's colour_min_incidence_cos (the example's 0.7: the sun within 46 degrees
// of the normal; flat ground 0.87) in the cells of `cells_of`, their illumination removed by the
// fit's C-correction, written out here: cos i = (hillshade - 1) / 254, the colour times
// (sin(sun altitude) + c) / (cos i + c), at most 255 / its largest channel.
std::map<std::string, double> lit_scene_p2(const Store& store, const json& fit,
                                           const std::string& cells_of) {
  const double pi = std::acos(-1.0), c_corr = fit.at("c_correction").get<double>();
  const double flat = std::sin(fit.at("sun_altitude").get<double>() * pi / 180);
  const double lit_cos = fit.at("colour_min_incidence_cos").get<double>();
  std::map<std::string, std::vector<double>> values;
  for (const CellId cell : store.tile_cells(cells_of)) {
    const Tile<float> k = float_tile(store, "pixel_classes", cell),
                      rgb = float_tile(store, "rgb", cell),
                      hill = float_tile(store, "hillshade", cell);
    for (int r = 0; r < k.size(); ++r)
      for (int c = 0; c < k.size(); ++c) {
        const double cos_i = (double(hill.at(c, r)) - 1) / 254;
        if (!std::isfinite(k.at(c, r)) || !(cos_i >= lit_cos) ||
            !std::isfinite(brightness(rgb, c, r)))
          continue;
        const double top = std::max({rgb.at(c, r, 0), rgb.at(c, r, 1), rgb.at(c, r, 2)});
        const double f = std::min((flat + c_corr) / (cos_i + c_corr), top > 0 ? 255 / top : 1e9);
        values[std::to_string(int(k.at(c, r)))].push_back(f * brightness(rgb, c, r));
      }
  }
  std::map<std::string, double> out;
  for (auto& [k, v] : values) {
    const auto at = v.begin() + std::ptrdiff_t(double(v.size()) * 0.02);
    std::nth_element(v.begin(), at, v.end());
    out[k] = *at;
  }
  return out;
}

// Per class of `classes`, the share of `imagery`'s pixels of the class darker than `floor[k]`.
std::map<std::string, double> dark_shares(const Store& store, const std::string& imagery,
                                          const std::string& classes,
                                          const std::map<std::string, double>& floor) {
  std::map<std::string, std::array<double, 2>> n;  // pixels, darker
  for (const CellId cell : store.tile_cells(classes)) {
    const Tile<float> c = float_tile(store, classes, cell), t = float_tile(store, imagery, cell);
    for (int r = 0; r < c.size(); ++r)
      for (int col = 0; col < c.size(); ++col) {
        if (!std::isfinite(c.at(col, r)) || !std::isfinite(brightness(t, col, r))) continue;
        const std::string k = std::to_string(int(c.at(col, r)));
        if (!floor.count(k)) continue;
        n[k][0] += 1;
        n[k][1] += brightness(t, col, r) < floor.at(k);
      }
  }
  std::map<std::string, double> out;
  for (const auto& [k, v] : n) out[k] = v[1] / v[0];
  return out;
}

TEST(Zion, HeldOutColoursAndDeterminism) {
  if (!std::filesystem::exists(kZion + "/srtm.tif"))
    GTEST_SKIP() << "../shared/data/zion is absent";
  const Outcome one = fit_and_assess(1);
  std::cout << one.table;
  const json model = json::parse(one.model);
  EXPECT_GE(model["fitted_classes"].size(), 4u);  // texture.cluster's k = 5, all fitted on the west
  for (const json& quantity : {json{{"name", "landcover"}, {"range", {-0.5, 255.5}}},
                               json{{"name", "extra"}, {"range", {0, 1}}}})  // the barren share
    EXPECT_NE(std::find(model["quantities"].begin(), model["quantities"].end(), quantity),
              model["quantities"].end())
        << model["quantities"];
  const json& r = one.report;
  ASSERT_TRUE(r.is_object()) << one.table;
  EXPECT_GE(r["class_colours"].size(), 4u) << "classes kept by the fit, predicted in the east";
  // Issue 14's goals not met (modules/texture/README.md "Where it stands": kappa >= 0.6, producer's
  // accuracies >= 0.5), held at what the example reaches with the share of barren land as a
  // quantity: the predicted classes compared at the observed map's minimum mapping unit (the same
  // majority filter of radius 16) kappa 0.597 (0.509 without the share), as rendered 0.444 (0.388).
  EXPECT_GE(r["kappa"].get<double>(), 0.59) << one.table;
  EXPECT_GE(r["unfiltered"]["kappa"].get<double>(), 0.44) << one.table;
  // Met since the calibration (4.94; 5.30 without the share, 10.72 on the stretched scene).
  EXPECT_LE(r["ciede2000_mean"].get<double>(), 6) << one.table;
  // Each class's colour against the scene's pixels of the class, all of them and the lit ones
  // (colour_min_incidence_cos 0.7, where the correction holds: the albedo the fit takes).
  // Spreads against the lit pixels': the texture is unshaded, and over all pixels the white
  // sandstone's (class 4) spread is its shaded walls' grey (32.5 against 18.7 lit), which an
  // albedo must not carry. Over all pixels its ratio is 0.45 (issue 14's 0.5 not met there; the
  // other classes' 0.70-1.05), held at 0.4.
  for (const auto& [k, c] : r["class_colours"].items()) {
    EXPECT_LE(c["ciede2000"].get<double>(), 5) << "class " << k << ": " << c;
    EXPECT_LE(c["ciede2000_lit"].get<double>(), 5) << "class " << k << ": " << c;
    EXPECT_GE(c["sd_ratio_lit"].get<double>(), 0.5) << "class " << k << ": " << c;
    EXPECT_LE(c["sd_ratio_lit"].get<double>(), 1.5) << "class " << k << ": " << c;
    EXPECT_GE(c["sd_ratio"].get<double>(), 0.4) << "class " << k << ": " << c;
    // The same after the blur: variation at the scene's scales, not single-pixel speckle. The
    // tan soil's (class 0) at most 1.7: it rose from 1.43 to 1.63 when the colours became the
    // lit pixels' (the texture's blurred pixels of the class, predicted on twice its observed
    // area, mix in the white sandstone, now lighter: 210 -> 222; its scene spread unchanged).
    EXPECT_GE(c["sd_ratio_blurred"].get<double>(), 0.5) << "class " << k << ": " << c;
    EXPECT_LE(c["sd_ratio_blurred"].get<double>(), k == "0" ? 1.7 : 1.5)
        << "class " << k << ": " << c;
  }
  // Producer's accuracy >= 0.5 for 4 of the 5 classes filtered (0.88, 0.72, 0.82, 0.63: the light
  // red rock 0), for 3 as rendered (0.73, 0.53, 0.77: the white sandstone 0.48, the light red
  // rock 0.01; modules/texture/README.md "Where it stands").
  const auto at_least_half = [](const json& accuracies) {
    int found = 0;
    for (const auto& [k, a] : accuracies.items()) found += a.get<double>() >= 0.5;
    return found;
  };
  EXPECT_GE(at_least_half(r["producers_accuracy"]), 4) << one.table;
  EXPECT_GE(at_least_half(r["unfiltered"]["producers_accuracy"]), 3) << one.table;
  const Outcome two = fit_and_assess(2);
  EXPECT_EQ(one.model, two.model);  // same bits
  EXPECT_EQ(one.table, two.table);  // same confusion matrix, kappa and colour difference

  const auto store = Store::open(two.dir + "/zion.mqt", Store::Mode::ReadOnly);
  ASSERT_EQ(store->require_layer("texture_fine").tile_size,
            store->require_layer("dem").tile_size * 4);  // two levels finer
  expect_seamless(*store, "texture_fine");
  expect_seamless(*store, "texture_height");

  // Detail at 8.8 m (issue 14's variation): each class's spread in the texture two levels finer,
  // over its own classes there, within 50-150 % of the scene's lit pixels' at its 30 m, and at
  // least 5 % above the texture's at the DEM's level: the octaves finer than its 35 m pixels add
  // variation (with the former noise, 3 octaves of persistence 0.5, 1-2 %;
  // modules/texture/NOTES.md, "Detail at 8.8 m").
  const auto fine = class_spreads(*store, "texture_fine", "texture_fine_classes");
  for (const auto& [k, c] : r["class_colours"].items()) {
    ASSERT_TRUE(fine.count(k)) << "class " << k << " not in the texture at 8.8 m";
    const double scene = c["image_lit_sd"].get<double>(), coarse = c["texture_sd"].get<double>();
    std::cout << "class " << k << " spread at 8.8 m " << fine.at(k) << " (35 m " << coarse
              << ", scene at 30 m " << scene << ")\n";
    EXPECT_GE(fine.at(k), 0.5 * scene) << "class " << k;
    EXPECT_LE(fine.at(k), 1.5 * scene) << "class " << k;
    EXPECT_GE(fine.at(k), 1.05 * coarse) << "class " << k;
  }
  // No dark blotches at 8.8 m (issue 14: the white sandstone's shaded grey, which the correction
  // leaves in on the 90 m DEM, scattered as black-grey spots by the noise): at most 10 % of each
  // class's pixels in the texture darker than the 2nd percentile of the scene's lit pixels of
  // the class. The fit and the assessment take a class's colours from lit pixels too
  // (colour_min_incidence_cos 0.7: the scene's spreads above are those of lit pixels). With
  // every pixel's colours fitted (the noise as now) the white sandstone's share was 27 %, the
  // other classes' 3-7 %; with lit pixels 2-6 %.
  const json example =
      json::parse(slurp(std::string(MAQUETTE_SOURCE_DIR) + "/examples/texture-zion.json"));
  json fit;
  for (const json& s : example["steps"])
    if (s["op"] == "texture.fit") fit = s["params"];
  const auto floor = lit_scene_p2(*store, fit, "texture_fine");
  for (const auto& [k, share] :
       dark_shares(*store, "texture_fine", "texture_fine_classes", floor)) {
    std::cout << "class " << k << " at 8.8 m darker than the lit scene's 2nd percentile "
              << floor.at(k) << ": " << share << "\n";
    EXPECT_LE(share, 0.1) << "class " << k;
  }
}

// The demo (Olinda, scripts/demo.sh; its data extracted next to the build's bin/ by
// scripts/setup.sh): its texture model rendered at the DEM's level and assessed against the
// scene. At least 4 surface types (texture.cluster's k = 4), each painted within CIEDE2000 5 of
// the scene's pixels of the class (no kappa gate: its town is not a function of terrain).
TEST(Olinda, DemoClassesKeepTheirColours) {
  const std::string data = std::string(MAQUETTE_BIN_DIR) + "/../demo-data";
  if (!std::filesystem::exists(data + "/L7_ETMs.tif"))
    GTEST_SKIP() << "no demo data in " << data << " (scripts/setup.sh fetches it)";
  const std::string dir = temp_dir() + "/demo";
  const CliResult demo = run_maquette("-q demo --output " + dir + " --threads 2");
  ASSERT_EQ(demo.exit_code, 0) << demo.err;
  json p = json::parse(slurp(dir + "/demo.json"));
  json steps = json::array();
  steps.push_back({{"op", "texture.procedural"},
                   {"inputs", {{"dem", "dem"}}},
                   {"outputs", {{"imagery", "texture_assessed"}, {"classes", "predicted"}}},
                   {"params", {{"model", {{"$artifact", "texture_model"}}}}}});
  steps.push_back({{"op", "texture.assess"},
                   {"inputs",
                    {{"classes", "classes"},
                     {"predicted", "predicted"},
                     {"rgb", "imagery_dem_grid"},
                     {"synthesized", "texture_assessed"}}},
                   {"outputs", {{"report", "assessment"}}}});
  p["steps"] = steps;
  p["store"] = dir + "/demo.mqt";
  std::ofstream(dir + "/assess.json") << p.dump(1);
  const CliResult assess = run_maquette("-q run " + dir + "/assess.json");
  ASSERT_EQ(assess.exit_code, 0) << assess.err;
  std::cout << assess.out;
  const auto store = Store::open(dir + "/demo.mqt", Store::Mode::ReadOnly);
  const json r = json::parse(store->get_artifact("assessment")->text());
  EXPECT_GE(r["class_colours"].size(), 4u) << assess.out;
  for (const auto& [k, c] : r["class_colours"].items())
    EXPECT_LE(c["ciede2000"].get<double>(), 5) << "class " << k << ": " << c;
}

}  // namespace
}  // namespace maquette::test
