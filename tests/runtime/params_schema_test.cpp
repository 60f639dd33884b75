#include "runtime/params_schema.h"

#include <gtest/gtest.h>

#include "test_util.h"

namespace maquette {
namespace {

using nlohmann::json;
using test::error_of;

const json kSchema = {
    {"type", "object"},
    {"properties",
     {{"z_factor", {{"type", "number"}, {"default", 1.0}}},
      {"azimuth", {{"type", "number"}, {"minimum", 0}, {"maximum", 360}, {"default", 315}}},
      {"steps", {{"type", "integer"}, {"minimum", 1}}},
      {"mode", {{"type", "string"}, {"enum", {"mean", "max"}}, {"default", "mean"}}},
      {"weights", {{"type", "array"}, {"items", {{"type", "number"}}}}},
      {"pair",
       {{"type", "array"}, {"items", {{"type", "number"}}}, {"minItems", 2}, {"maxItems", 2}}},
      {"fast", {{"type", "boolean"}, {"default", false}}},
      {"x", {{"type", "number"}}}}},
    {"required", {"x"}},
    {"additionalProperties", false}};
const std::string kStep = "step 2 (terrain.derive)";

TEST(ParamsSchema, FillsDefaults) {
  const json p = validate_params(kSchema, {{"x", 3}, {"steps", 2.0}}, kStep);
  EXPECT_EQ(p, json({{"x", 3},
                     {"steps", 2},
                     {"z_factor", 1.0},
                     {"azimuth", 315},
                     {"mode", "mean"},
                     {"fast", false}}));
  EXPECT_TRUE(p.at("steps").is_number_integer());
}

TEST(ParamsSchema, NamesStepFieldAndValue) {
  auto err = [](const json& p) { return error_of([&] { validate_params(kSchema, p, kStep); }); };
  EXPECT_EQ(err({{"x", 1}, {"z_factor", "abc"}}),
            "step 2 (terrain.derive): params.z_factor: expected a number, got \"abc\"");
  EXPECT_EQ(err({{"x", 1}, {"azimuth", 400}}),
            "step 2 (terrain.derive): params.azimuth: 400 is above the maximum 360");
  EXPECT_EQ(err({{"x", 1}, {"azimuth", -1}}),
            "step 2 (terrain.derive): params.azimuth: -1 is below the minimum 0");
  EXPECT_EQ(err({{"x", 1}, {"zfactor", 2}}),
            "step 2 (terrain.derive): params: unknown field 'zfactor'");
  EXPECT_EQ(err(json::object()), "step 2 (terrain.derive): params: missing required field 'x'");
  EXPECT_EQ(err({{"x", 1}, {"steps", 1.5}}),
            "step 2 (terrain.derive): params.steps: expected an integer, got 1.5");
  // Whole doubles become int64: out of range is an error, not an undefined cast.
  EXPECT_EQ(err({{"x", 1}, {"steps", 1e300}}),
            "step 2 (terrain.derive): params.steps: 1e+300 is outside the 64-bit integer range");
  EXPECT_EQ(err({{"x", 1}, {"steps", 0x1p63}}),
            "step 2 (terrain.derive): params.steps: 9.223372036854776e+18 is outside the 64-bit "
            "integer range");
  EXPECT_EQ(err({{"x", 1}, {"steps", 18446744073709551615u}}),
            "step 2 (terrain.derive): params.steps: 18446744073709551615 is outside the 64-bit "
            "integer range");
  EXPECT_EQ(err({{"x", 1}, {"mode", "median"}}),
            "step 2 (terrain.derive): params.mode: \"median\" is not one of [\"mean\",\"max\"]");
  EXPECT_EQ(err({{"x", 1}, {"weights", {1, "w"}}}),
            "step 2 (terrain.derive): params.weights[1]: expected a number, got \"w\"");
  EXPECT_EQ(err({{"x", 1}, {"pair", {1000}}}),
            "step 2 (terrain.derive): params.pair: expected at least 2 items, got [1000]");
  EXPECT_EQ(err({{"x", 1}, {"pair", {1, 2, 3}}}),
            "step 2 (terrain.derive): params.pair: expected at most 2 items, got [1,2,3]");
  EXPECT_EQ(validate_params(kSchema, {{"x", 1}, {"pair", {1, 2}}}, kStep).at("pair"), json({1, 2}));
  EXPECT_EQ(err({{"x", 1}, {"fast", 1}}),
            "step 2 (terrain.derive): params.fast: expected a boolean, got 1");
  EXPECT_EQ(err(json::array()), "step 2 (terrain.derive): params: expected an object, got []");
}

TEST(ParamsSchema, NullParamsAreEmpty) {
  const json schema = {{"type", "object"},
                       {"properties", {{"a", {{"type", "integer"}, {"default", 4}}}}}};
  EXPECT_EQ(validate_params(schema, nullptr, kStep), json({{"a", 4}}));
  // Without additionalProperties: false, extra fields pass through.
  EXPECT_EQ(validate_params(schema, {{"b", 1}}, kStep), json({{"a", 4}, {"b", 1}}));
}

TEST(ParamsSchema, HelpersMakeBoundedNumbersAndStringsWithDefaults) {
  const json schema = {{"type", "object"},
                       {"additionalProperties", false},
                       {"properties",
                        {{"n", number_param(0, 1, 0.5, "a fraction")},
                         {"i", integer_param(1, 9, 3, "a count")},
                         {"s", string_param("none", "a name")}}}};
  EXPECT_EQ(validate_params(schema, json::object(), kStep),
            json({{"n", 0.5}, {"i", 3}, {"s", "none"}}));
  EXPECT_EQ(validate_params(schema, {{"s", "zones"}}, kStep).at("s"), "zones");
  EXPECT_EQ(error_of([&] {
              validate_params(schema, {{"s", 2}}, kStep);
            }),
            "step 2 (terrain.derive): params.s: expected a string, got 2");
  EXPECT_NE(error_of([&] {
              validate_params(schema, {{"i", 10}}, kStep);
            }).find("params.i"),
            std::string::npos);
  EXPECT_NE(error_of([&] {
              validate_params(schema, {{"n", 1.5}}, kStep);
            }).find("params.n"),
            std::string::npos);
}

}  // namespace
}  // namespace maquette
