// Round trip: render a hand-authored hat-function model (paper 4.1) on a relief, classify the
// image in hue-saturation space, fit a model to it, render that, and assess the agreement.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <map>

#include "../field.h"
#include "core/error.h"
#include "texture_module.h"

namespace maquette::texture {
namespace {

using namespace texture_test;

constexpr int kSize = 64, kLevel = 10;
constexpr int kAssessHalo = 12;  // texture.assess: its blur of sigma 4 pixels, to 3 sigma

const json kHatModel = json::parse(R"({
  "format": "maquette.texture.model", "version": 1,
  "quantities": [{"name": "height", "range": [0, 3000]}, {"name": "slope", "range": [0, 90]}],
  "root": {"colour": [150, 110, 90], "class": 0, "children": [
    {"class": 1, "colour": [90, 150, 60], "noise_scale": 0.1, "noise": {"seed": 5},
     "constraints": {"height": {"hat": [0, 100, 1000, 1200]}}},
    {"class": 2, "colour": [30, 75, 40], "noise_scale": 0.1, "noise": {"seed": 6},
     "constraints": {"height": {"hat": [1200, 1400, 2200, 2400]}, "slope": {"hat": [0, 0, 20, 30]}}},
    {"class": 3, "colour": [240, 240, 245],
     "constraints": {"height": {"hat": [2500, 2600, 3000, 3100]}}}]}})");

// Hat plateaus [b, c] of the height constraint per class.
const std::map<int, std::array<double, 2>> kHeightPlateau = {
    {1, {100, 1000}}, {2, {1400, 2200}}, {3, {2600, 3000}}};

const json kClassify = json::parse(R"({"boxes": [
  {"id": 3, "hue": [290, 310], "value": [0.8, 1]},
  {"id": 0, "hue": [0, 60]},
  {"id": 1, "hue": [60, 180], "value": [0.45, 1]},
  {"id": 2, "hue": [60, 180], "value": [0, 0.45]}]})");

const json kFit = {{"ranges", {{"height", {0, 3000}}}}, {"classes", {0, 1, 2, 3}}};

struct Scene {
  std::vector<CellId> cells;
  std::map<CellId, Tile<float>> dem, rgb, classes, predicted, synthesized;

  bool inside(CellId c) const { return dem.count(c) != 0; }
  Tile<float> halo(const std::map<CellId, Tile<float>>& layer, CellId c, int h) const {
    return assemble_halo(default_grid(), c, kSize, h, [&](CellId n) {
      return layer.count(n) ? std::optional<Tile<float>>(layer.at(n)) : std::nullopt;
    });
  }
  Tile<float> dem_halo(CellId c) const {
    return with_halo(c, kSize, kInputHalo, [](CellId n) { return sample(n, kSize, relief); });
  }
};

// Imagery as stored: rounded to uint8.
Tile<float> stored(const Tile<float>& t) {
  Tile<float> out = t;
  for (float& v : out.data()) v = std::isnan(v) ? v : std::round(std::clamp(v, 0.0f, 255.0f));
  return out;
}

Scene make_scene(const json& model) {
  Scene s;
  for (uint32_t r = 0; r < 4; ++r)
    for (uint32_t c = 0; c < 4; ++c)
      s.cells.push_back(CellId::FromFaceColRow(2, kLevel, 520 + c, 500 + r));
  for (const CellId c : s.cells) s.dem[c] = sample(c, kSize, relief);
  for (const CellId c : s.cells) {
    CellData d;
    d.inputs.emplace("dem", s.dem_halo(c));
    CellData out = run_cell("texture.procedural", c, kSize, d, {{"model", model}});
    s.rgb[c] = stored(out.outputs.at("imagery"));
    CellData in;
    in.inputs.emplace("rgb", s.rgb[c]);
    s.classes[c] = run_cell("texture.classify", c, kSize, in, kClassify).outputs.at("classes");
  }
  return s;
}

// texture.fit on the scene, with `hillshade` as inputs.hillshade when given.
json fit(const Scene& s, const json& params,
         const std::map<CellId, Tile<float>>* hillshade = nullptr) {
  return run_reduce(
      "texture.fit", s.cells, kSize,
      [&](CellId c) {
        CellData d;
        d.inputs.emplace("classes", s.classes.at(c));
        d.inputs.emplace("rgb", s.rgb.at(c));
        d.inputs.emplace("dem", s.dem_halo(c));
        if (hillshade) d.inputs.emplace("hillshade", hillshade->at(c));
        return d;
      },
      params);
}

// texture.assess of the model rendered on the scene; with a hillshade, `params` may ask for the
// illumination (sun_altitude, colour_min_incidence_cos).
json assess(Scene& s, const json& model, const json& params = json::object(),
            const std::map<CellId, Tile<float>>* hillshade = nullptr) {
  for (const CellId c : s.cells) {
    CellData d;
    d.inputs.emplace("dem", s.dem_halo(c));
    CellData out = run_cell("texture.procedural", c, kSize, d, {{"model", model}});
    s.predicted[c] = out.outputs.at("classes");
    s.synthesized[c] = stored(out.outputs.at("imagery"));
  }
  return run_reduce(
      "texture.assess", s.cells, kSize,
      [&](CellId c) {
        CellData d;
        d.inputs.emplace("classes", s.halo(s.classes, c, kAssessHalo));
        d.inputs.emplace("predicted", s.halo(s.predicted, c, kAssessHalo));
        d.inputs.emplace("rgb", s.halo(s.rgb, c, kAssessHalo));
        d.inputs.emplace("synthesized", s.halo(s.synthesized, c, kAssessHalo));
        if (hillshade) d.inputs.emplace("hillshade", s.halo(*hillshade, c, kAssessHalo));
        return d;
      },
      params);
}

TEST(RoundTrip, HatModelIsRecovered) {
  Scene s = make_scene(kHatModel);
  const json model = fit(s, kFit);
  // Every class was seen, and its height constraint peaks on its hat's plateau.
  const Model m = parse_model(model, "fitted");
  for (const Layer& l : m.layers) {
    if (l.parent != 0 || !kHeightPlateau.count(l.class_id)) continue;
    if (!l.constraints[0]) continue;  // the most widespread class: the base material
    const Table& t = *l.constraints[0];
    double sum = 0, centre = 0;
    for (int i = 0; i < kBins; ++i)
      sum += t[size_t(i)], centre += t[size_t(i)] * (i + 0.5) * 3000 / kBins;
    centre /= sum;
    const auto [b, c] = kHeightPlateau.at(l.class_id);
    EXPECT_GT(centre, b) << "class " << l.class_id;
    EXPECT_LT(centre, c) << "class " << l.class_id;
  }
  // The forest's slope function falls off where its hat did (0 beyond 30 degrees).
  for (const Layer& l : m.layers)
    if (l.parent == 0 && l.class_id == 2) {
      EXPECT_GT((*l.constraints[1])[size_t(10 * kBins / 90)], 0.5);
      EXPECT_EQ((*l.constraints[1])[size_t(40 * kBins / 90)], 0);
    }
  const json report = assess(s, model);
  EXPECT_GE(report["kappa"].get<double>(), 0.9);
  RecordProperty("kappa", std::to_string(report["kappa"].get<double>()));
  // The hand-authored model itself reproduces the classes at least as well.
  EXPECT_GE(assess(s, kHatModel)["kappa"].get<double>(), 0.9);
}

// Each class's colours given a spread along a known axis e (a checkerboard of -+ 20 along e
// around the rendered colour): the fit finds the axis (the class layer and its variation child
// differ along e) and the synthesized texture has each class's mean colour and spread.
const std::array<double, 3> kSpreadAxis = {2 / 3.0, 1 / 3.0, 2 / 3.0};  // unit

// The hat scene with each class's colours spread by a checkerboard of -+ 20 along kSpreadAxis.
Scene spread_scene() {
  Scene s = make_scene(kHatModel);
  for (const CellId c : s.cells)
    for (int r = 0; r < kSize; ++r)
      for (int col = 0; col < kSize; ++col)
        for (int k = 0; k < 3; ++k)
          if (!std::isnan(s.classes[c].at(col, r)))
            s.rgb[c].at(col, r, k) += float(((col + r) % 2 ? 20 : -20) * kSpreadAxis[size_t(k)]);
  return s;
}

// Each class's texture within CIEDE2000 3 of its scene colour and its spread within 67-150 %.
void expect_class_means_and_spreads(const json& report) {
  for (const auto& [k, c] : report["class_colours"].items()) {
    EXPECT_LT(c["ciede2000"].get<double>(), 3) << "class " << k << ": " << c;
    EXPECT_GT(c["sd_ratio"].get<double>(), 0.67) << "class " << k << ": " << c;
    EXPECT_LT(c["sd_ratio"].get<double>(), 1.5) << "class " << k << ": " << c;
  }
}

TEST(RoundTrip, VariationGivesEachClassItsMeanAndSpread) {
  Scene s = spread_scene();
  const std::array<double, 3>& e = kSpreadAxis;
  // Noise of 2 km: its 3 octaves are longer than 2 pixels of 153 m (level 10, 64-pixel tiles),
  // so none is left out as too fine to show.
  json given = kFit;
  given["noise_wavelength_m"] = 2000;
  const json model = fit(s, given);
  const Model m = parse_model(model, "fitted");
  int variations = 0;
  for (const Layer& l : m.layers) {
    if (l.parent <= 0) continue;
    const Layer& p = m.layers[size_t(l.parent)];
    if (p.parent != 0) continue;
    std::array<double, 3> d{};
    double norm = 0, along = 0;
    for (size_t k = 0; k < 3; ++k) d[k] = l.colour[k] - p.colour[k], norm += d[k] * d[k];
    for (size_t k = 0; k < 3; ++k) along += d[k] * e[k];
    // The child is lighter, along e (within 18 degrees: the classes' edges blend colours too).
    EXPECT_GT(along / std::sqrt(norm), 0.95) << l.name;
    ++variations;
  }
  EXPECT_EQ(variations, 4);  // one per class
  const json report = assess(s, model);
  expect_class_means_and_spreads(report);
  // Without the variation, one colour per class (spread only where classes blend): less spread,
  // on the whole (the white class, near 255, has little room for its variation).
  given["variation"] = false;
  const json plain = assess(s, fit(s, given));
  double with = 0, without = 0;
  for (const auto& [k, c] : plain["class_colours"].items()) {
    without += c["texture_sd"].get<double>() / 4;
    with += report["class_colours"][k]["texture_sd"].get<double>() / 4;
  }
  EXPECT_GT(with, without + 3) << plain["class_colours"];
}

// `noise_persistence` (the Zion example's 0.7: more of the variation in the finer octaves) is
// the model's noise, level-1 layers and variation children alike, and the variation still gives
// each class its mean and spread: its coverage moments are measured on that noise.
TEST(RoundTrip, NoisePersistenceIsTheModelsAndKeepsTheSpread) {
  Scene s = spread_scene();
  json given = kFit;
  given["noise_wavelength_m"] = 2000;
  given["noise_persistence"] = 0.8;
  const json model = fit(s, given);
  int noisy = 0;
  for (const Layer& l : parse_model(model, "fitted").layers)
    if (l.noise_scale != 0) {
      EXPECT_EQ(l.noise.persistence, 0.8) << l.name;
      ++noisy;
    }
  EXPECT_GE(noisy, 4);  // at least the variation children
  expect_class_means_and_spreads(assess(s, model));
}

// The prior-aware fit (class odds, calibrated biases, as the Zion example uses) recovers the
// hat model too, and each class dominates about as much land as it was observed on.
const json kPriorAwareFit = {{"ranges", {{"height", {0, 3000}}}},
                             {"classes", {0, 1, 2, 3}},
                             {"constraints", "odds"},
                             {"calibrate", true},
                             {"sample_step", 2}};

TEST(RoundTrip, PriorAwareFitIsRecovered) {
  Scene s = make_scene(kHatModel);
  const json report = assess(s, fit(s, kPriorAwareFit));
  EXPECT_GE(report["kappa"].get<double>(), 0.9);
  RecordProperty("kappa", std::to_string(report["kappa"].get<double>()));
  for (const auto& [k, p] : report["proportions"].items())
    EXPECT_NEAR(p["predicted"].get<double>(), p["observed"].get<double>(), 0.03) << "class " << k;
}

// Both fits (the calibration sample is concatenated in cell order).
TEST(RoundTrip, FitIsDeterministicAndMergesAssociatively) {
  const Scene s = make_scene(kHatModel);
  for (const json& given : {kFit, kPriorAwareFit}) {
    const json a = fit(s, given);
    EXPECT_EQ(a, fit(s, given));
    // Partials merged pairwise as a tree give the same model as merged in sequence.
    const auto& op = static_cast<const ReduceOperator&>(texture_operator("texture.fit"));
    const json params = full_params("texture.fit", given);
    std::vector<json> parts;
    for (const CellId c : s.cells) {
      CellData d;
      d.inputs.emplace("classes", s.classes.at(c));
      d.inputs.emplace("rgb", s.rgb.at(c));
      d.inputs.emplace("dem", s.dem_halo(c));
      parts.push_back(
          op.map({.cell = c, .tile_size = kSize, .grid = &default_grid(), .params = &params}, d));
    }
    while (parts.size() > 1) {
      std::vector<json> next;
      for (size_t i = 0; i + 1 < parts.size(); i += 2)
        next.push_back(op.merge(parts[i], parts[i + 1]));
      parts = next;
    }
    const Artifact tree = op.finish(parts[0], {&default_grid(), &params, nullptr});
    EXPECT_EQ(json::parse(tree.text()), a);
  }
}

// The spread after the blur tells speckle from variation at the scene's scales: one class over
// 4 x 4 cells, the image a smooth wave across the columns (period 50 pixels), the texture either
// the same wave or a checkerboard of the same spread. Both have the image's spread; blurred, the
// wave keeps it and the checkerboard loses it.
TEST(RoundTrip, BlurredSpreadRatioRejectsSpeckle) {
  const Scene s = make_scene(kHatModel);
  const auto wave = [](int64_t col, int64_t) { return 100 + 40 * std::sin(col * 2 * M_PI / 50); };
  const auto checker = [](int64_t col, int64_t row) {
    return 100 + ((col + row) % 2 ? 40 : -40) / std::sqrt(2.0);
  };
  const auto report = [&](const std::function<double(int64_t, int64_t)>& texture) {
    Scene t = s;
    for (const CellId c : s.cells) {
      Tile<float> classes(kSize, 1, 0), rgb(kSize, 3, 0), synthesized(kSize, 3, 0);
      for (int r = 0; r < kSize; ++r)
        for (int col = 0; col < kSize; ++col) {
          const int64_t gc = global_col(c, kSize, col), gr = global_row(c, kSize, r);
          classes.at(col, r) = 0;
          for (int k = 0; k < 3; ++k) {
            rgb.at(col, r, k) = float(wave(gc, gr));
            synthesized.at(col, r, k) = float(texture(gc, gr));
          }
        }
      t.classes[c] = classes, t.predicted[c] = classes, t.rgb[c] = rgb;
      t.synthesized[c] = synthesized;
    }
    return run_reduce(
        "texture.assess", t.cells, kSize,
        [&](CellId c) {
          CellData d;
          d.inputs.emplace("classes", t.halo(t.classes, c, kAssessHalo));
          d.inputs.emplace("predicted", t.halo(t.predicted, c, kAssessHalo));
          d.inputs.emplace("rgb", t.halo(t.rgb, c, kAssessHalo));
          d.inputs.emplace("synthesized", t.halo(t.synthesized, c, kAssessHalo));
          return d;
        },
        json::object())["class_colours"]["0"];
  };
  const json same = report(wave), speckle = report(checker);
  EXPECT_NEAR(same["sd_ratio"].get<double>(), 1, 1e-6) << same;
  EXPECT_NEAR(same["sd_ratio_blurred"].get<double>(), 1, 1e-6) << same;
  EXPECT_NEAR(speckle["sd_ratio"].get<double>(), 1, 0.02) << speckle;
  EXPECT_LT(speckle["sd_ratio_blurred"].get<double>(), 0.05) << speckle;
}

// inputs.colour_classes: a class's colours come only from the pixels whose own class it is. Every
// other pixel of the scene (not its own class) painted blue: the model is the same, bit for bit,
// as with those pixels left as they were, and differs without colour_classes; a class with no
// pixel of its own is an error naming it.
TEST(RoundTrip, ColourClassesKeepOtherPixelsOutOfTheColours) {
  const Scene s = make_scene(kHatModel);
  Scene painted = s;
  std::map<CellId, Tile<float>> own;
  for (const CellId c : s.cells) {
    own[c] = s.classes.at(c);
    for (int r = 0; r < kSize; ++r)
      for (int col = 0; col < kSize; ++col)
        if ((col + 2 * r) % 3 == 0) {
          own[c].at(col, r) = std::numeric_limits<float>::quiet_NaN();
          for (int k = 0; k < 3; ++k) painted.rgb[c].at(col, r, k) = k == 2 ? 255.0f : 0.0f;
        }
  }
  const auto fit_with = [&](const Scene& scene, const std::map<CellId, Tile<float>>* colour) {
    return run_reduce(
        "texture.fit", scene.cells, kSize,
        [&](CellId c) {
          CellData d;
          d.inputs.emplace("classes", scene.classes.at(c));
          d.inputs.emplace("rgb", scene.rgb.at(c));
          d.inputs.emplace("dem", scene.dem_halo(c));
          if (colour) d.inputs.emplace("colour_classes", colour->at(c));
          return d;
        },
        kFit);
  };
  EXPECT_EQ(fit_with(painted, &own), fit_with(s, &own));
  EXPECT_NE(fit(painted, kFit), fit(s, kFit));
  std::map<CellId, Tile<float>> none = own;
  for (auto& [c, t] : none)
    for (float& v : t.data())
      if (v == 3) v = 1;  // no pixel is class 3's own
  EXPECT_THROW(
      {
        try {
          fit_with(s, &none);
        } catch (const Error& e) {
          EXPECT_STREQ(e.what(),
                       "texture.fit: class 3: no pixel whose own class (inputs.colour_classes) it "
                       "is: no colour");
          throw;
        }
      },
      Error);
}

// colour_min_incidence_cos: a class's colours from its lit pixels only. A third of the pixels
// painted dark grey and shaded (hillshade at cos i = 0.3, the sun at 30 degrees: corrected x 1.67
// but still grey), the rest lit as flat ground (cos i = 0.5): with the pixels lit at cos i >= 0.4
// the fitted model is the unpainted scene's, with every pixel it is not; without a sun, an error.
// texture.assess's lit colours likewise.
TEST(RoundTrip, ShadedPixelsKeptOutOfTheColours) {
  const Scene s = make_scene(kHatModel);
  Scene painted = s;
  std::map<CellId, Tile<float>> shade;
  for (const CellId c : s.cells) {
    shade[c] = Tile<float>(kSize, 1, 0, 1 + 254 * 0.5f);
    for (int r = 0; r < kSize; ++r)
      for (int col = 0; col < kSize; ++col)
        if ((col + 2 * r) % 3 == 0) {
          shade[c].at(col, r) = 1 + 254 * 0.3f;
          for (int k = 0; k < 3; ++k) painted.rgb[c].at(col, r, k) = 30;
        }
  }
  const auto fit_lit = [&](const Scene& scene, double lit_cos, double sun) {
    json p = kFit;
    p["sun_altitude"] = sun, p["colour_min_incidence_cos"] = lit_cos;
    return fit(scene, p, &shade);
  };
  EXPECT_EQ(fit_lit(painted, 0.4, 30), fit_lit(s, 0.4, 30));
  EXPECT_NE(fit_lit(painted, 0, 30), fit_lit(s, 0, 30));
  // texture.assess compares each class with its lit pixels beside all of them: the lit ones the
  // unpainted scene's, all of them not (the grey third in).
  const json model = fit_lit(s, 0.4, 30);
  const json lit = {{"sun_altitude", 30}, {"colour_min_incidence_cos", 0.4}};
  Scene plain = s;
  const json a = assess(painted, model, lit, &shade)["class_colours"],
             b = assess(plain, model, lit, &shade)["class_colours"];
  ASSERT_FALSE(a.empty());
  for (const auto& [k, c] : a.items()) {
    ASSERT_TRUE(c.contains("image_lit_mean")) << c;
    EXPECT_EQ(c["image_lit_mean"], b[k]["image_lit_mean"]) << "class " << k;
    EXPECT_NE(c["image_mean"], c["image_lit_mean"]) << "class " << k;
  }
  EXPECT_FALSE(
      assess(plain, model, {{"sun_altitude", 30}}, &shade)["class_colours"].begin()->contains(
          "image_lit_mean"));
  EXPECT_THROW(
      {
        try {
          fit_lit(s, 0.4, 0);
        } catch (const Error& e) {
          EXPECT_STREQ(
              e.what(),
              "texture.fit: params.colour_min_incidence_cos needs params.sun_altitude > 0");
          throw;
        }
      },
      Error);
}

// texture.fit's "out" file, given to texture.procedural as "model_file", renders the same.
TEST(RoundTrip, ModelFileFromFitOut) {
  Scene s = make_scene(kHatModel);
  const std::string path = ::testing::TempDir() + "texture_model.json";
  json params = kFit;
  params["out"] = path;
  const json model = fit(s, params);
  const CellId c = s.cells[5];
  CellData d;
  d.inputs.emplace("dem", s.dem_halo(c));
  const CellData a = run_cell("texture.procedural", c, kSize, d, {{"model", model}});
  const CellData b = run_cell("texture.procedural", c, kSize, d, {{"model_file", path}});
  const auto x = a.outputs.at("imagery").data(), y = b.outputs.at("imagery").data();
  EXPECT_TRUE(std::equal(x.begin(), x.end(), y.begin()));
  try {
    run_cell("texture.procedural", c, kSize, d, {{"model", model}, {"model_file", path}});
    FAIL();
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(),
                 "texture.procedural: params: give exactly one of \"model\" and \"model_file\"");
  }
}

std::string fit_error(const Scene& s, const json& params) {
  try {
    fit(s, params);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(RoundTrip, BadInputErrors) {
  const Scene s = make_scene(kHatModel);
  EXPECT_EQ(fit_error(s, {{"ranges", {{"height", {0, 3000}}}}, {"classes", {0, 7}}}),
            "texture.fit: params.classes: class 7 has no pixels with every quantity known");
  EXPECT_EQ(fit_error(s, {{"ranges", {{"height", {0, 3000}}, {"rainfall", {0, 900}}}},
                          {"quantities", {"height", "rainfall"}}}),
            "texture.fit: params.quantities: 'rainfall' has no input (map inputs.rainfall)");
  EXPECT_EQ(fit_error(s, {{"ranges", json::object()}}),
            "texture.fit: params.ranges.height: missing (give [lo, hi] of the region's values)");
  EXPECT_EQ(fit_error(s, {{"ranges", {{"height", {10, 5}}}}}),
            "texture.fit: params.ranges.height: expected [lo, hi] with lo < hi, got [10,5]");
  // A DEM with no values: no pixel has every quantity known.
  try {
    run_reduce("texture.fit", s.cells, kSize,
               [&](CellId c) {
                 CellData d;
                 d.inputs.emplace("classes", s.classes.at(c));
                 d.inputs.emplace("rgb", s.rgb.at(c));
                 d.inputs.emplace("dem", Tile<float>(kSize, 1, kInputHalo, NAN));
                 return d;
               },
               {{"ranges", {{"height", {0, 3000}}}}});
    FAIL();
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(),
                 "texture.fit: no classified pixel with every quantity known in the region "
                 "(inputs.classes empty, or the quantities missing)");
  }
}

// Quantities missing for some cells (documented fallback): their pixels are left out of the
// fit, so the model is the one fitted on the other cells alone; the assessment refuses a
// region with no classified pixel (an image that does not overlap the DEM's region).
TEST(RoundTrip, MissingQuantitiesAndNoOverlap) {
  const Scene s = make_scene(kHatModel);
  const std::vector<CellId> half(s.cells.begin() + 8, s.cells.end());
  const auto inputs = [&](CellId c) {
    CellData d;
    d.inputs.emplace("classes", s.classes.at(c));
    d.inputs.emplace("rgb", s.rgb.at(c));
    const bool missing = std::find(half.begin(), half.end(), c) == half.end();
    d.inputs.emplace("dem", missing ? Tile<float>(kSize, 1, kInputHalo, NAN) : s.dem_halo(c));
    return d;
  };
  EXPECT_EQ(run_reduce("texture.fit", s.cells, kSize, inputs, kFit),
            run_reduce("texture.fit", half, kSize, inputs, kFit));
  try {
    run_reduce(
        "texture.assess", s.cells, kSize,
        [&](CellId c) {
          CellData d;
          d.inputs.emplace("classes", Tile<float>(kSize, 1, 2, NAN));
          d.inputs.emplace("predicted", s.halo(s.classes, c, kAssessHalo));
          return d;
        },
        json::object());
    FAIL();
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(),
                 "texture.assess: no classified pixel in the region (inputs.classes empty)");
  }
}

}  // namespace
}  // namespace maquette::texture
