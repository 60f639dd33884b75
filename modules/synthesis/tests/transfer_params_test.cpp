// synthesis.transfer's params refused where they would be read wrong: a painting too small for
// its exemplar_scale (its blocks would read past the image), one part of the altitude guide
// without the others (it would be dropped without a word), a class the table asks for that has
// no pixel to copy (any class would be copied instead), a painting wholly excluded, line classes
// that would do nothing.
#include "../transfer_params.h"

#include <gdal_priv.h>
#include <gtest/gtest.h>

#include <bitset>
#include <filesystem>
#include <map>
#include <set>
#include <string>

#include "../synthesis.h"
#include "../transfer_exemplar.h"
#include "core/error.h"
#include "run_cli.h"
#include "synthetic_raster.h"

namespace maquette::synthesis {
namespace {

// A `size` x `size` RGB PNG of a grey ramp (pixel i: i * 7 modulo 256).
std::string painting_png(int size) {
  return test::write_png(maquette::test::temp_dir() + "/painting.png", size, size, 3,
                         [size](int x, int y, int) { return double(uint8_t((y * size + x) * 7)); });
}

// Expects `call` to throw maquette::Error whose message holds `message`; `input` names what it
// was given.
template <typename Call>
void expect_refused(const Call& call, const std::string& input, const std::string& message) {
  try {
    call();
    ADD_FAILURE() << "accepted: " << input;
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
  }
}

nlohmann::json params(const std::string& painting, int scale) {
  return {{"painting", painting},
          {"classes", 2},
          {"exclude_classes", nlohmann::json::array()},
          {"exemplar_scale", scale},
          {"k", 2}};
}

TEST(TransferParams, PaintingSmallerThanItsScaleNeedsIsNamed) {
  const std::string png = painting_png(3);
  try {
    transfer_exemplar(params(png, 4));
    FAIL() << "a 3 x 3 painting at exemplar_scale 4 was accepted";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(png), std::string::npos) << what;
    EXPECT_NE(what.find("3 x 3"), std::string::npos) << what;
    EXPECT_NE(what.find("exemplar_scale 4"), std::string::npos) << what;
  }
  // The least size the levels need is accepted.
  const int least = 1 << (kLevels - 1);
  EXPECT_EQ(transfer_exemplar(params(painting_png(least), 1))->pyramid.levels.size(),
            size_t(kLevels));
}

TEST(TransferParams, AClassWithNoPixelToCopyAndAPaintingAllExcludedAreNamed) {
  // 16 x 16, dark on the left half, light on the right: 2 classes by colour, one a half each.
  const std::string png = test::write_png(maquette::test::temp_dir() + "/halves.png", 16, 16, 3,
                                          [](int x, int, int) { return x < 8 ? 40.0 : 200.0; });
  const auto message = [](const nlohmann::json& p) {
    try {
      transfer_exemplar(p);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  nlohmann::json p = params(png, 1);
  p["landcover_classes"] = {{"41", 0}, {"42", 1}};
  EXPECT_EQ(message(p), "no error");
  // A class the painting's 2 do not have: its land cover would be painted from any class.
  p["landcover_classes"] = {{"41", 0}, {"42", 9}};
  EXPECT_NE(message(p).find("synthesis.transfer.landcover_classes.42: painting class 9 has no "
                            "pixel to copy (not in the painting, or excluded); the classes that "
                            "have: 0, 1"),
            std::string::npos)
      << message(p);
  p["landcover_classes"] = {{"41", 0}, {"42", 1}};
  p["exclude_classes"] = {1};
  EXPECT_NE(message(p).find("synthesis.transfer.landcover_classes.42: painting class 1 has no "
                            "pixel to copy (not in the painting, or excluded); the classes that "
                            "have: 0"),
            std::string::npos)
      << message(p);
  p["exclude_classes"] = {0, 1};
  EXPECT_NE(message(p).find("synthesis.transfer: every pixel of " + png +
                            " is excluded (by its transparency, exclusion or exclude_classes "
                            "[0,1]): nothing is left to copy"),
            std::string::npos)
      << message(p);
  // The grey ramp's classes alternate in stripes: one excluded leaves no 2 x 2 block whole, so
  // no pixel at a coarser level.
  p = params(painting_png(16), 1);
  p["landcover_classes"] = {{"41", 0}};
  p["exclude_classes"] = {1};
  EXPECT_NE(message(p).find("synthesis.transfer: painting " + p["painting"].get<std::string>() +
                            ": synthesis: the exemplar has no pixel left to copy at level "),
            std::string::npos)
      << message(p);
}

TEST(TransferParams, EveryParamIsDescribed) {
  // `maquette modules` prints the descriptions: a param without one is a number to guess.
  const nlohmann::json schema = transfer_params_schema();
  ASSERT_GE(schema.at("properties").size(), 20u);
  for (const auto& [name, param] : schema.at("properties").items())
    EXPECT_TRUE(param.contains("description")) << name;
}

TEST(TransferParams, AltitudeGuideNeedsItsThreeParts) {
  const nlohmann::json with_range = {{"altitude_range", {1000, 2600}}};
  nlohmann::json whole = with_range;
  whole["painting_altitude"] = "rows";
  EXPECT_EQ(altitude_range(nlohmann::json::object(), "op", false), std::nullopt);
  EXPECT_EQ(*altitude_range(whole, "op", true), (std::array<double, 2>{1000, 2600}));
  const auto refused = [](const nlohmann::json& p, bool dem, const std::string& message) {
    expect_refused([&] { altitude_range(p, "synthesis.transfer", dem); },
                   p.dump() + " dem " + std::to_string(dem), message);
  };
  refused(with_range, false, "synthesis.transfer.altitude_range is given without inputs.dem");
  refused(nlohmann::json::object(), true, "synthesis.transfer: inputs.dem is given without");
  // The painting's altitude missing, or alone: the altitude weight would do nothing.
  refused(with_range, true,
          "synthesis.transfer: inputs.dem and altitude_range are given without painting_altitude");
  refused({{"painting_altitude", "rows"}}, false,
          "synthesis.transfer.painting_altitude is given without inputs.dem and altitude_range");
  // Its weight without the guide weighed nothing, silently; its default (filled in) is no choice.
  refused({{"w_altitude", 3.0}}, false,
          "synthesis.transfer.w_altitude 3.0 weighs the altitude guide, which is not given");
  EXPECT_EQ(altitude_range({{"w_altitude", 1.0}}, "op", false), std::nullopt);
  EXPECT_EQ(
      *altitude_range(
          {{"altitude_range", {1000, 2600}}, {"painting_altitude", "rows"}, {"w_altitude", 3.0}},
          "op", true),
      (std::array<double, 2>{1000, 2600}));
}

TEST(TransferParams, SetsOfClassesInTheTableAreTakenAsOne) {
  // Forest and wetlands take painting classes 6 and 1 (in either order), shrubland 7 alone.
  const nlohmann::json table = {{"4", {6, 1}}, {"8", {1, 6}}, {"1", 7}};
  EXPECT_EQ(class_table(table, "op"), (std::map<int, uint8_t>{{1, 7}, {4, 1}, {8, 1}}));
  EXPECT_EQ(class_groups(table, "op"), (std::map<uint8_t, uint8_t>{{1, 1}, {6, 1}, {7, 7}}));
  const auto refused = [](const nlohmann::json& t, const std::string& message) {
    expect_refused([&] { class_groups(t, "synthesis.transfer"); }, t.dump(), message);
  };
  refused({{"4", {6, 1}}, {"8", 6}},
          "synthesis.transfer.landcover_classes.8: painting class 6 is in two different sets");
  refused({{"4", nlohmann::json::array()}}, "synthesis.transfer.landcover_classes.4: []");
  refused({{"4", {6, 255}}}, "synthesis.transfer.landcover_classes.4: [6,255] is not");
  refused(nlohmann::json::object(),
          "synthesis.transfer.landcover_classes: {}: map at least one land-cover value");
  refused({{"-1", 6}}, "synthesis.transfer.landcover_classes: key '-1': land-cover values are 0");
  refused({{"forest", 6}}, "synthesis.transfer.landcover_classes: key 'forest' is not an integer");

  // The exemplar's pixels are relabelled: the ramp's two colour classes become one.
  nlohmann::json p = params(painting_png(64), 1);
  const auto labels = [](const nlohmann::json& with) {
    const auto& l = transfer_exemplar(with)->pyramid.levels[0].labels;
    return std::set<uint8_t>(l.begin(), l.end());
  };
  EXPECT_EQ(labels(p), (std::set<uint8_t>{0, 1}));
  p["landcover_classes"] = {{"3", {1, 0}}};
  EXPECT_EQ(labels(p), (std::set<uint8_t>{0}));
}

// line_classes are painting classes as the table gives them (a set's smallest class); one in no
// table value, or without patch passes, would do nothing and is refused, as are the passes'
// other fields without them.
// A land-cover value the layer cannot hold (a typo: 300 for 30 in NLCD's uint8 classes) is named.
TEST(TransferParams, ATableValueTheLandCoverCannotHoldIsNamed) {
  LayerInfo landcover;
  landcover.name = "nlcd";
  landcover.dtype = DType::U8;
  const auto table = class_table({{"30", 2}, {"255", 3}}, "synthesis.transfer");
  check_table_fits(table, landcover, "synthesis.transfer");  // 0..255: accepted
  const auto typo = class_table({{"300", 2}}, "synthesis.transfer");
  expect_refused([&] { check_table_fits(typo, landcover, "synthesis.transfer"); }, "300",
                 "synthesis.transfer.landcover_classes: land-cover value 300 is outside what layer "
                 "'nlcd' holds (uint8, 0..255): no pixel would take its class");
  landcover.dtype = DType::U16;
  check_table_fits(typo, landcover, "synthesis.transfer");
}

TEST(TransferParams, LineClassesAreTheTablesLabels) {
  nlohmann::json p = {{"landcover_classes", {{"2", 3}, {"4", {6, 1}}}},
                      {"patch_passes", 2},
                      {"line_classes", {3, 6}}};
  const std::bitset<256> lines = line_labels(p, "op");
  EXPECT_EQ(lines.count(), 2u);
  EXPECT_TRUE(lines[3]);
  EXPECT_TRUE(lines[1]);  // 6's set is labelled 1
  const auto refused = [](const nlohmann::json& with, const std::string& message) {
    expect_refused(
        [&] {
          check_fields_without_effect(with, "synthesis.transfer");
          line_labels(with, "synthesis.transfer");
        },
        with.dump(), message);
  };
  p["line_classes"] = {3, 5};
  refused(p,
          "synthesis.transfer.line_classes: painting class 5 is in no value of "
          "landcover_classes");
  p["line_classes"] = {3};
  p["patch_passes"] = 0;
  refused(p,
          "synthesis.transfer.line_classes [3] keep lines through the patch passes, and "
          "patch_passes is 0");
  p["line_classes"] = nlohmann::json::array();
  EXPECT_TRUE(line_labels(p, "op").none());
  // The passes' other fields without the passes: refused the same way.
  p["patch_edges"] = 3;
  refused(p,
          "synthesis.transfer.patch_edges: 3 is a field of the patch passes, and patch_passes "
          "is 0");
  p["patch_passes"] = 1;
  EXPECT_TRUE(line_labels(p, "op").none());
  EXPECT_NO_THROW(check_fields_without_effect(p, "op"));
  // Nor is the blocks' typical share taken without their preferences.
  p["spread_typical"] = 0.6;
  p["w_spread"] = 0.0;
  refused(p,
          "synthesis.transfer.spread_typical: 0.6 chooses the regions the blocks prefer, and "
          "w_spread is 0");
  p["w_spread"] = 8.0;
  EXPECT_TRUE(line_labels(p, "op").none());
  EXPECT_NO_THROW(check_fields_without_effect(p, "op"));
}

}  // namespace
}  // namespace maquette::synthesis
