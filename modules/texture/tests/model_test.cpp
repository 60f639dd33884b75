// The model document (parsing, errors naming field and value, hats, serialisation) and the
// coverage / colour / height formulas of paper 4.2 against hand-computed values.
#include <gtest/gtest.h>

#include <algorithm>

#include "../calibration.h"
#include "../hierarchy.h"
#include "../noise.h"
#include "../surface.h"
#include "core/error.h"

namespace maquette::texture {
namespace {

json base_model() {
  return json::parse(R"({
    "format": "maquette.texture.model", "version": 1,
    "quantities": [{"name": "height", "range": [0, 1000]}, {"name": "slope", "range": [0, 90]}],
    "root": {"colour": [100, 100, 100], "class": 0, "children": [
      {"name": "a", "class": 1, "colour": [200, 40, 0], "bias": 0.9, "noise_scale": 0.3,
       "roughness_m": 5, "noise": {"seed": 4, "octaves": 2, "wavelength_m": 50},
       "constraints": {"height": {"hat": [0, 200, 600, 800]}, "slope": {"hat": [0, 0, 30, 60]}},
       "children": [{"name": "a1", "colour": [0, 0, 250], "bias": 2}]},
      {"name": "b", "class": 2, "colour": [0, 255, 0], "bias": 0.5,
       "constraints": {"height": {"hat": [700, 900, 1000, 1000]}}}]}})");
}

std::string parse_error(const json& doc) {
  try {
    parse_model(doc, "ctx");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(Model, ParsesDepthFirst) {
  const Model m = parse_model(base_model(), "ctx");
  ASSERT_EQ(m.layers.size(), 4u);
  EXPECT_EQ(m.layers[1].name, "a");
  EXPECT_EQ(m.layers[2].name, "a1");
  EXPECT_EQ(m.layers[2].parent, 1);
  EXPECT_EQ(m.layers[3].parent, 0);
  EXPECT_EQ(layer_class(m, 2), 1);  // inherited
  EXPECT_FALSE(m.layers[3].constraints[1].has_value());
}

TEST(Model, JsonRoundTrip) {
  const Model m = parse_model(base_model(), "ctx");
  const json again = model_to_json(parse_model(model_to_json(m), "ctx"));
  EXPECT_EQ(again, model_to_json(m));
}

TEST(Model, HatTable) {
  const Table t = hat_table({200, 400, 600, 800}, 0, 1024);  // bins of 4, centres at 4i + 2
  EXPECT_EQ(t[0], 0);
  EXPECT_NEAR(t[75], (302 - 200) / 200.0, 1e-6);   // rising
  EXPECT_EQ(t[125], 1);                            // plateau
  EXPECT_NEAR(t[175], (800 - 702) / 200.0, 1e-6);  // falling
  EXPECT_EQ(t[255], 0);
}

TEST(Model, ErrorsNameFieldAndValue) {
  json m = base_model();
  m["version"] = 2;
  EXPECT_EQ(parse_error(m),
            "ctx: model.version: unsupported version 2 (this build reads version 1)");
  m = base_model();
  m.erase("format");
  EXPECT_EQ(parse_error(m), "ctx: model.format: expected \"maquette.texture.model\", got nothing");
  m = base_model();
  m["root"]["children"][0]["constraints"]["height"] = {{"table", json::array({0.5, 0.5})}};
  EXPECT_EQ(parse_error(m),
            "ctx: model.root.children[0].constraints.height.table: expected 256 numbers, got 2");
  m = base_model();
  m["root"]["children"][1]["constraints"]["rainfall"] = {{"hat", {0, 1, 2, 3}}};
  EXPECT_EQ(parse_error(m),
            "ctx: model.root.children[1].constraints.rainfall: not a quantity of the model "
            "(declare it in \"quantities\")");
  m = base_model();
  m["root"]["children"][0]["constraints"]["slope"]["hat"] = {0, 50, 40, 60};
  EXPECT_EQ(parse_error(m),
            "ctx: model.root.children[0].constraints.slope.hat: expected a <= b <= c <= d, got "
            "[0,50,40,60]");
  m = base_model();
  m["root"]["children"][0]["colour"] = {1, 2};
  EXPECT_EQ(parse_error(m), "ctx: model.root.children[0].colour: expected [r, g, b], got [1,2]");
  m = base_model();
  m["root"]["children"][0]["colur"] = {1, 2, 3};
  EXPECT_EQ(parse_error(m), "ctx: model.root.children[0]: unknown field 'colur'");
  m = base_model();
  m["root"]["constraints"] = {{"height", {{"hat", {0, 1, 2, 3}}}}};
  EXPECT_EQ(parse_error(m),
            "ctx: model.root.constraints: the root layer has no constraints (paper 4.2)");
  m = base_model();
  m["quantities"][1]["range"] = {90, 0};
  EXPECT_EQ(parse_error(m), "ctx: model.quantities[1].range: expected lo < hi, got [90,0]");
}

// One pixel, by hand: C = clamp((b + s N) F_h F_s) C_parent, RGB and H blended layer by layer.
TEST(Model, CoverageFormulaByHand) {
  const Model m = parse_model(base_model(), "ctx");
  const float h0 = 450, slope = 45;
  const PixelPositions position(default_grid(), CellId::FromFaceColRow(2, 14, 7700, 8100), 16, 0,
                                0);
  const Vec3d pos = position.at(0, 0);
  SurfaceInputs in;
  in.height = Plane(1, 0, h0);
  in.slope = Plane(1, 0, slope);
  in.quantities = {nullptr, nullptr};
  in.position = &position;
  const Surface s = evaluate(m, in);

  const float n = NoiseField(m.layers[1].noise)(pos);
  ASSERT_GE(n, -1);
  ASSERT_LE(n, 1);
  const float fh = lookup(*m.layers[1].constraints[0], h0 / 1000);
  const float fs = lookup(*m.layers[1].constraints[1], slope / 90);
  EXPECT_NEAR(fh, 1, 1e-6);         // on the height plateau
  EXPECT_NEAR(fs, 0.5, 1.0 / 256);  // half-way down the slope hat
  const float ca = std::clamp((0.9f + 0.3f * n) * fh * fs, 0.0f, 1.0f);
  const float ca1 = std::clamp(2.0f, 0.0f, 1.0f) * ca;  // bounded by its parent
  std::array<float, 3> rgb{100, 100, 100};              // root, coverage 1
  for (int k = 0; k < 3; ++k) rgb[k] = (1 - ca) * rgb[k] + ca * m.layers[1].colour[k];
  for (int k = 0; k < 3; ++k) rgb[k] = (1 - ca1) * rgb[k] + ca1 * m.layers[2].colour[k];
  const float fb = lookup(*m.layers[3].constraints[0], (h0 + ca * 5 * n) / 1000);
  EXPECT_EQ(fb, 0);  // layer b sees the displaced height, far below its hat
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(s.rgb[k], rgb[k], 1e-3) << k;
  EXPECT_NEAR(s.height.v[0], h0 + ca * 5 * n, 1e-4);
  EXPECT_EQ(s.dominant_class.v[0], ca1 >= 0.5 ? 1.0f : 0.0f);
}

// Linear between bin centres, clamped at both ends; a missing value reads 0 (the padded zeros).
TEST(Model, TableLookupByHand) {
  Table t{};
  for (int i = 0; i < kBins; ++i) t[size_t(i)] = float(i % 7) / 6;
  EXPECT_EQ(lookup(t, (10 + 0.5f) / kBins), t[10]);  // a bin centre
  EXPECT_FLOAT_EQ(lookup(t, (10 + 0.75f) / kBins), t[10] + 0.25f * (t[11] - t[10]));
  EXPECT_EQ(lookup(t, -3), t[0]);
  EXPECT_EQ(lookup(t, 0.2f / kBins), t[0]);  // below the first centre
  EXPECT_EQ(lookup(t, 1), t[kBins - 1]);
  EXPECT_EQ(lookup(t, 5), t[kBins - 1]);
  EXPECT_EQ(lookup(t, NAN), 0);
}

TEST(Model, NaNHeightGivesNaN) {
  const Model m = parse_model(base_model(), "ctx");
  SurfaceInputs in;
  in.height = Plane(1, 0, NAN);
  in.slope = Plane(1, 0, 0);
  in.quantities = {nullptr, nullptr};
  const PixelPositions position(default_grid(), CellId::FromFaceColRow(2, 14, 7700, 8100), 16, 0,
                                0);
  in.position = &position;
  const Surface s = evaluate(m, in);
  EXPECT_TRUE(std::isnan(s.rgb[0]));
  EXPECT_TRUE(std::isnan(s.dominant_class.v[0]));
}

TEST(Model, ConstraintFunctionHasMeanHalf) {
  std::array<uint64_t, kBins> h{};
  for (int i = 100; i < 140; ++i) h[size_t(i)] = 10 + uint64_t(i % 3);
  const Table t = constraint_function(h);
  double sum = 0;
  for (const float v : t) sum += v;
  EXPECT_EQ(t[0], 0);
  EXPECT_EQ(t[120], 1);  // clamped: 40 bins hold everything, far above twice the mean
  std::array<uint64_t, kBins> flat{};
  flat.fill(7);
  const Table f = constraint_function(flat);
  EXPECT_FLOAT_EQ(f[3], 0.5f);
  EXPECT_GT(sum, 0);
}

TEST(Model, OddsFunctionByHand) {
  std::array<uint64_t, kBins> mine{}, all{};
  mine[3] = 1, all[3] = 4;          // odds 1.5 / 3.5
  mine[9] = 5, all[9] = 5;          // 5.5 / 0.5 = 11
  all[10] = 2;                      // 0.5 / 2.5 = 0.2
  mine[20] = 1000, all[20] = 1000;  // 2001, clamped to 64: the largest
  all[30] = 1000;                   // 0.5 / 1000.5, clamped to 1 / 64
  const Table t = odds_function(mine, all);
  EXPECT_FLOAT_EQ(t[3], float(1.5 / 3.5 / 64));
  EXPECT_FLOAT_EQ(t[9], float(11.0 / 64));
  EXPECT_FLOAT_EQ(t[10], float(0.2 / 64));
  EXPECT_FLOAT_EQ(t[20], 1.0f);
  EXPECT_FLOAT_EQ(t[30], float(1.0 / 64 / 64));
  // Bins without pixels take the nearest bin with pixels, the lower on a tie.
  for (int i = 0; i < 3; ++i) EXPECT_EQ(t[size_t(i)], t[3]);
  for (int i = 11; i <= 15; ++i) EXPECT_EQ(t[size_t(i)], t[10]) << i;  // 15: 10 and 20 tie
  EXPECT_EQ(t[16], t[20]);
  EXPECT_EQ(t[25], t[20]);  // a tie
  EXPECT_EQ(t[26], t[30]);
  EXPECT_EQ(t[255], t[30]);
  EXPECT_EQ(odds_function({}, {}), Table{});  // no pixel at all
}

// A categorical quantity: a bin per code, unseen codes at the class's odds over all codes.
TEST(Model, OddsFunctionOfCodes) {
  std::array<uint64_t, kBins> mine{}, all{};
  mine[42] = 9, all[42] = 10;  // 9.5 / 1.5
  mine[52] = 1, all[52] = 10;  // 1.5 / 9.5
  const Table t = odds_function(mine, all, true);
  EXPECT_FLOAT_EQ(t[42], 1.0f);
  EXPECT_FLOAT_EQ(t[52], float((1.5 / 9.5) / (9.5 / 1.5)));
  const double overall = 10.5 / 10.5;  // 10 of the 20 pixels
  for (const size_t i : {size_t(0), size_t(43), size_t(51), size_t(255)})
    EXPECT_FLOAT_EQ(t[i], float(overall / (9.5 / 1.5))) << i;
}

TEST(Model, CategoricalQuantityHasABinPerCode) {
  json doc = base_model();
  doc["quantities"].push_back({{"name", "landcover"}, {"range", {0, 256}}});
  EXPECT_EQ(parse_error(doc),
            "ctx: model.quantities[2].range: the categorical quantity 'landcover' has the range "
            "[-0.5, 255.5] (a bin per code), got [0,256]");
  doc["quantities"][2]["range"] = {-0.5, 255.5};
  EXPECT_EQ(parse_model(doc, "ctx").quantities[2].lo, kCategoricalLo);
}

// Calibration by hand: layer "b" (class 1, after "a") has product bin / 255; 10 of 100
// samples are of class 1, so its threshold is the 10th largest product among all samples.
TEST(Model, CalibratedBiasMatchesTheObservedArea) {
  Model m;
  m.quantities = {{"height", 0, 1}};
  Table ramp{}, one{};
  for (int i = 0; i < kBins; ++i) ramp[size_t(i)] = float(i) / 255, one[size_t(i)] = 1;
  m.layers.resize(3);
  m.layers[0].class_id = 0, m.layers[0].constraints.resize(1);
  m.layers[1].parent = 0, m.layers[1].class_id = 0, m.layers[1].constraints = {one};
  m.layers[2].parent = 0, m.layers[2].class_id = 1, m.layers[2].constraints = {ramp};
  std::vector<Sample> samples;
  for (int i = 0; i < 90; ++i) samples.push_back({0, {uint8_t(i)}});
  for (int i = 0; i < 10; ++i) samples.push_back({1, {uint8_t(200 + i)}});
  calibrate_biases(m, samples);
  EXPECT_FLOAT_EQ(m.layers[2].bias, 0.5f / (200.0f / 255));
  EXPECT_EQ(m.layers[1].bias, 1);  // the first level-1 layer takes the rest
  // A tiny product: the bias is capped (0.5 / 1e-7 would be 5e6).
  Table tiny{};
  tiny[1] = 1e-7f;
  m.layers[2].constraints = {tiny};
  samples = {{0, {0}}, {1, {1}}};
  calibrate_biases(m, samples);
  EXPECT_EQ(m.layers[2].bias, kMaxBias);
  samples = {{0, {0}}, {1, {0}}};
  m.layers[2].bias = 1;
  calibrate_biases(m, samples);
  EXPECT_EQ(m.layers[2].bias, 1);  // no sample with a positive product: unchanged
  samples = {{0, {1}}, {0, {2}}};
  calibrate_biases(m, samples);
  EXPECT_EQ(m.layers[2].bias, 1);  // no sample of the class: unchanged
}

// Sharpened coverage by hand: the ramp table to the 4th power, the bias 0.5 (2 b)^4, so the
// pixels at coverage >= 0.5 are the same while coverage below falls off as the 4th power; the
// root and unconstrained layers are unchanged.
TEST(Model, SharpenedCoverageKeepsTheDominantPixels) {
  Model m;
  m.quantities = {{"height", 0, 1}};
  Table ramp{};
  for (int i = 0; i < kBins; ++i) ramp[size_t(i)] = float(i) / 255;
  m.layers.resize(3);
  m.layers[0].constraints.resize(1);
  m.layers[1].parent = 0, m.layers[1].constraints.resize(1), m.layers[1].bias = 2;
  m.layers[2].parent = 0, m.layers[2].constraints = {ramp}, m.layers[2].bias = 3;
  const Model before = m;
  sharpen_coverage(m, 4);
  EXPECT_EQ(m.layers[0].bias, 1);
  EXPECT_EQ(m.layers[1].bias, 2);
  EXPECT_FLOAT_EQ(m.layers[2].bias, 0.5f * 6 * 6 * 6 * 6);
  for (size_t i = 0; i < size_t(kBins); ++i) {
    const float p = float(i) / 255, was = std::min(1.0f, 3 * p);
    const float now = std::min(1.0f, m.layers[2].bias * (*m.layers[2].constraints[0])[i]);
    EXPECT_NEAR((*m.layers[2].constraints[0])[i], p * p * p * p, 1e-7f);
    EXPECT_EQ(now >= 0.5f, was >= 0.5f) << i;  // 0.5 / 3 = 0.1667: bin 43 on
    if (was < 0.5f) {
      EXPECT_LE(now, was);
    }
  }
  sharpen_coverage(m = before, 1);
  EXPECT_EQ(m.layers[2].bias, 3);
  EXPECT_EQ(*m.layers[2].constraints[0], ramp);
}

TEST(Noise, CodomainAndDeterminism) {
  const NoiseParams p{9, 4, 100, 0.5};
  float lo = 1, hi = -1;
  for (int i = 0; i < 2000; ++i) {
    const float v = NoiseField(p)({i * 7.31, i * -3.7, 6.3e6 + i});
    lo = std::min(lo, v), hi = std::max(hi, v);
    ASSERT_EQ(v, NoiseField(p)({i * 7.31, i * -3.7, 6.3e6 + i}));
  }
  EXPECT_GE(lo, -1);
  EXPECT_LE(hi, 1);
  EXPECT_LT(lo, -0.4);  // uses its range
  EXPECT_GT(hi, 0.4);
}

}  // namespace
}  // namespace maquette::texture
