// terrain.derive on fields with analytic answers, on cells inside faces, along face seams
// (equatorial-polar, R|O at the antimeridian), at cube corners and at the pole.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/ecef.h"
#include "terrain_module.h"

namespace maquette::terrain {
namespace {

using terrain_test::run;
using terrain_test::sample;
using terrain_test::true_centre;

constexpr int kSize = 16;
constexpr int kLevel = 10;  // pixels of ~560 m
constexpr double kDeg = 180 / M_PI;

enum Face { N, O, P, Q, R, S };

std::vector<CellId> test_cells() {
  const uint32_t last = (1U << kLevel) - 1, mid = 1U << (kLevel - 1);
  return {
      CellId::FromFaceColRow(Q, kLevel, 300, 700),          // inside an equatorial face
      CellId::FromFaceColRow(O, kLevel, mid, 0),            // equatorial-polar edge (O | N)
      CellId::FromFaceColRow(P, kLevel, mid, last),         // equatorial-polar edge (P | S, turned)
      CellId::FromFaceColRow(R, kLevel, last, mid),         // equatorial-equatorial edge (R | O)
      CellId::FromFaceColRow(O, kLevel, 0, 0),              // cube corner O, N, R
      CellId::FromFaceColRow(N, kLevel, last, last),        // cube corner N, O, P
      CellId::FromFaceColRow(S, kLevel, 0, last),           // cube corner S, R, Q
      CellId::FromFaceColRow(N, kLevel, mid - 1, mid - 1),  // at the north pole (sheared pixels)
  };
}

double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 minus(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

CellData dem_input(CellId cell, const std::function<double(LonLat)>& field) {
  CellData data;
  data.inputs.emplace("dem", assemble_halo(default_grid(), cell, kSize, 1, [&](CellId c) {
                        return std::optional<Tile<float>>(sample(c, kSize, field));
                      }));
  return data;
}

double expected_hillshade(double gradient, double aspect_deg, double azimuth, double altitude,
                          double z_factor) {
  const double slope = std::atan(z_factor * gradient), zenith = (90 - altitude) / kDeg;
  const double c = std::cos(zenith) * std::cos(slope) +
                   std::sin(zenith) * std::sin(slope) * std::cos((azimuth - aspect_deg) / kDeg);
  return 1 + 254 * std::max(0.0, c);
}

// h = c . (p - p_ref), p the ECEF position: its gradient is c projected on east and north.
TEST(Derive, LinearFieldEverywhere) {
  const Vec3 c{0.31, -0.22, 0.45};
  const json light = {{"azimuth", 100}, {"altitude", 30}, {"z_factor", 2}};
  for (const CellId cell : test_cells()) {
    SCOPED_TRACE(cell.ToText());
    const Vec3 ref = ecef(true_centre(cell, kSize, kSize / 2, kSize / 2));
    const auto field = [&](LonLat p) { return dot(c, minus(ecef(p), ref)); };
    const CellData out = run("terrain.derive", cell, kSize, dem_input(cell, field));
    const CellData lit = run("terrain.derive", cell, kSize, dem_input(cell, field), light);
    for (int row = 0; row < kSize; ++row)
      for (int col = 0; col < kSize; ++col) {
        const LonLat p = true_centre(cell, kSize, col, row);
        const double ge = dot(c, east_unit(p)), gn = dot(c, north_unit(p));
        const double g = std::hypot(ge, gn);
        const double aspect = std::fmod(std::atan2(-ge, -gn) * kDeg + 360, 360);
        ASSERT_NEAR(out.outputs.at("slope").at(col, row), std::atan(g) * kDeg, 2e-3);
        ASSERT_NEAR(out.outputs.at("aspect").at(col, row), aspect, 5e-3);
        const double k = 1 / std::sqrt(1 + g * g);
        const Tile<float>& normal = out.outputs.at("normal");
        ASSERT_NEAR(normal.at(col, row, 0), -ge * k, 2e-5);
        ASSERT_NEAR(normal.at(col, row, 1), -gn * k, 2e-5);
        ASSERT_NEAR(normal.at(col, row, 2), k, 2e-5);
        ASSERT_NEAR(out.outputs.at("hillshade").at(col, row),
                    expected_hillshade(g, aspect, 315, 45, 1), 0.01);
        ASSERT_NEAR(lit.outputs.at("hillshade").at(col, row),
                    expected_hillshade(g, aspect, 100, 30, 2), 0.01);
      }
  }
}

// h = 1000 - k |p - p0|^2 / 2 around a point p0 just outside the tile: in each pixel's tangent
// plane a paraboloid of curvature k, so the profile curvature is k / (1 + |grad h|^2)^(3/2).
TEST(Derive, CurvatureOfAQuadraticBump) {
  constexpr double k = 1e-4;
  for (const CellId cell : test_cells()) {
    SCOPED_TRACE(cell.ToText());
    const Vec3 p0 = ecef(true_centre(cell, kSize, -3, -2));
    const auto field = [&](LonLat p) {
      const Vec3 d = minus(ecef(p), p0);
      return 1000 - k * dot(d, d) / 2;
    };
    const CellData out = run("terrain.derive", cell, kSize, dem_input(cell, field));
    for (int row = 0; row < kSize; ++row)
      for (int col = 0; col < kSize; ++col) {
        const LonLat p = true_centre(cell, kSize, col, row);
        const Vec3 d = minus(ecef(p), p0);
        const double ge = -k * dot(d, east_unit(p)), gn = -k * dot(d, north_unit(p));
        const double expected = k / std::pow(1 + ge * ge + gn * gn, 1.5);
        ASSERT_NEAR(out.outputs.at("curvature").at(col, row), expected, 2e-4 * expected)
            << col << "," << row;
      }
  }
}

TEST(Derive, FlatGroundAndNaN) {
  const CellId cell = test_cells()[1];
  CellData data = dem_input(cell, [](LonLat) { return 250.0; });
  data.inputs.at("dem").at(5, 5) = std::numeric_limits<float>::quiet_NaN();
  const CellData out = run("terrain.derive", cell, kSize, data);
  for (const auto& [name, tile] : out.outputs)
    for (int row = 4; row <= 6; ++row)
      for (int col = 4; col <= 6; ++col) EXPECT_TRUE(std::isnan(tile.at(col, row))) << name;
  EXPECT_EQ(out.outputs.at("slope").at(10, 10), 0.0f);
  EXPECT_TRUE(std::isnan(out.outputs.at("aspect").at(10, 10)));
  EXPECT_TRUE(std::isnan(out.outputs.at("curvature").at(10, 10)));
  EXPECT_NEAR(out.outputs.at("hillshade").at(10, 10), 1 + 254 * std::sin(45 / kDeg), 1e-4);
  EXPECT_EQ(out.outputs.at("normal").at(10, 10, 2), 1.0f);
}

TEST(Derive, ComputesOnlyTheMappedOutputs) {
  const CellId cell = test_cells()[0];
  CellData data = dem_input(cell, [](LonLat p) { return 10 * p.lon; });
  const CellOperator& op = terrain_test::terrain_operator("terrain.derive");
  data.outputs.emplace("slope", Tile<float>());
  const json params = validate_params(op.spec().params_schema, json::object(), "derive");
  op.run({.cell = cell, .tile_size = kSize, .grid = &default_grid(), .params = &params}, data);
  EXPECT_EQ(data.outputs.size(), 1U);
  EXPECT_EQ(data.outputs.at("slope").size(), kSize);
  EXPECT_GT(data.outputs.at("slope").at(3, 3), 0.0f);
}

TEST(Derive, Spec) {
  const OperatorSpec& spec = terrain_test::terrain_operator("terrain.derive").spec();
  EXPECT_EQ(spec.halo, 1);
  ASSERT_EQ(spec.inputs.size(), 1U);
  EXPECT_EQ(spec.inputs[0].name, "dem");
  ASSERT_EQ(spec.outputs.size(), 5U);
  EXPECT_EQ(spec.outputs[3].dtype, DType::U8);
  EXPECT_EQ(spec.outputs[4].channels, 3);
  EXPECT_THROW(validate_params(spec.params_schema, {{"altitude", 120}}, "derive"), Error);
}

}  // namespace
}  // namespace maquette::terrain
