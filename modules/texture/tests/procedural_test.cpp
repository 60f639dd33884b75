// texture.procedural through the loaded module: seamless across tile borders and a face seam at
// levels finer than the DEM, same bits for any thread count and tiling, errors naming the missing
// input. Pixels of 9 to 35 m, so the noise (wavelengths 50 to 300 m) is resolved and cached on
// lattices coarser than the pixels (lattice_noise.h).
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <set>
#include <thread>

#include "../categorical_values.h"
#include "../field.h"
#include "../render.h"
#include "../surface.h"
#include "texture_module.h"

namespace maquette::texture {
namespace {

using namespace texture_test;

const json kModel = json::parse(R"({
  "format": "maquette.texture.model", "version": 1,
  "quantities": [{"name": "height", "range": [0, 3000]}, {"name": "slope", "range": [0, 90]}],
  "root": {"colour": [150, 110, 90], "class": 0, "roughness_m": 3,
           "noise": {"seed": 3, "wavelength_m": 200}, "children": [
    {"class": 1, "colour": [80, 140, 60], "bias": 1, "noise_scale": 0.4, "roughness_m": 2,
     "noise": {"seed": 5, "wavelength_m": 300, "octaves": 4},
     "constraints": {"height": {"hat": [0, 100, 1200, 1400]}}},
    {"class": 2, "colour": [30, 80, 40], "bias": 1, "noise_scale": 0.3,
     "constraints": {"height": {"hat": [1200, 1400, 2200, 2400]}, "slope": {"hat": [0, 0, 25, 35]}}},
    {"class": 3, "colour": [240, 240, 245], "bias": 1,
     "constraints": {"height": {"hat": [2400, 2600, 3000, 3100]}}}]}})");

Rendered render(CellId cell, int size, int refine) {
  const auto tile_of = [&](CellId c) { return sample(c, size, relief); };
  return render_tile(parse_model(kModel, "test"), default_grid(), cell, size, refine,
                     with_halo(cell, size, kInputHalo, tile_of), {}, "test");
}

// The step across the border (between a's last and b's first column, b to the right of a) is
// within the range of steps between neighbouring interior pixels of the two tiles.
void expect_seamless(const std::vector<float>& a, const std::vector<float>& b, int m, int channels,
                     const char* what) {
  const auto value = [&](const std::vector<float>& t, int c, int r) {
    double s = 0;
    for (int k = 0; k < channels; ++k)
      s += t[(size_t(r) * size_t(m) + size_t(c)) * size_t(channels) + size_t(k)];
    return s;
  };
  double interior = 0, border = 0;
  for (int r = 0; r < m; ++r) {
    for (int c = 1; c < m; ++c)
      interior = std::max({interior, std::abs(value(a, c, r) - value(a, c - 1, r)),
                           std::abs(value(b, c, r) - value(b, c - 1, r))});
    border = std::max(border, std::abs(value(b, 0, r) - value(a, m - 1, r)));
  }
  EXPECT_GT(interior, 0) << what;
  EXPECT_LE(border, interior) << what << ": a seam";
}

TEST(Procedural, SeamlessAcrossTilesTwoLevelsFiner) {
  const int size = 16, refine = 2, level = 14;  // 35 m inputs, 8.8 m pixels
  const CellId a = CellId::FromFaceColRow(2, level, 8320, 8000),
               b = CellId::FromFaceColRow(2, level, 8321, 8000);
  const Rendered ra = render(a, size, refine), rb = render(b, size, refine);
  ASSERT_EQ(ra.size, 64);
  expect_seamless(ra.rgb, rb.rgb, ra.size, 3, "rgb");
  expect_seamless(ra.height, rb.height, ra.size, 1, "height");
  expect_seamless(ra.normal, rb.normal, ra.size, 3, "normal");
}

// The categorical land cover (categorical_values.h): a layer's table values at the input
// pixels, interpolated (as logs) by the cubic B-spline. At the input's level each pixel reads its
// code's value (within 3 %: the prefilter's truncation and the log table's steps); two levels
// finer, pixels whose 4 x 4 input neighbours share a code read its value too (within 6 %: the
// interpolating spline rings from the codes beyond), every pixel lies
// between the values around it (within the spline's overshoot, a quarter), and the largest step
// between neighbouring pixels is a fraction of the step between codes (a curve, not a staircase).
TEST(Procedural, CategoricalQuantityInterpolatesItsValues) {
  json doc = json::parse(R"({"format": "maquette.texture.model", "version": 1,
    "quantities": [{"name": "landcover", "range": [-0.5, 255.5]}],
    "root": {"colour": [0, 0, 0], "class": 0, "children": [
      {"class": 1, "colour": [255, 255, 255], "bias": 1, "constraints": {"landcover": {}}}]}})");
  json table = json::array();
  for (int i = 0; i < kBins; ++i) table.push_back(i == 42 ? 1.0 : i == 52 ? 0.25 : (i % 5) / 8.0);
  doc["root"]["children"][0]["constraints"]["landcover"]["table"] = table;
  const int size = 16;
  const CellId cell = CellId::FromFaceColRow(2, 14, 8320, 8000);
  const auto codes = [](LonLat p) {  // stripes of three codes across the tile, ~4 pixels wide
    const int k = (int(std::floor(p.lon / 0.0017)) % 3 + 3) % 3;
    return k == 0 ? 42.0 : k == 1 ? 52.0 : 71.0;
  };
  const int halo = kInputHalo + kPrefilterReach;
  const Tile<float> landcover =
      with_halo(cell, size, halo, [&](CellId c) { return sample(c, size, codes); });
  const Tile<float> dem =
      with_halo(cell, size, halo, [&](CellId c) { return sample(c, size, relief); });
  const Model model = parse_model(doc, "test");
  const auto value = [&](int c, int r) { return table[size_t(landcover.at(c, r))].get<double>(); };
  const Rendered r0 =
      render_tile(model, default_grid(), cell, size, 0, dem, {{"landcover", &landcover}}, "test");
  std::set<float> seen;
  double step0 = 0;
  for (int row = 0; row < size; ++row)
    for (int col = 0; col < size; ++col) {
      const double got = r0.rgb[(size_t(row) * size_t(size) + size_t(col)) * 3] / 255;
      ASSERT_NEAR(got, value(col, row), 0.03 * value(col, row)) << col << " " << row;
      seen.insert(landcover.at(col, row));
      if (col > 0) step0 = std::max(step0, std::abs(value(col, row) - value(col - 1, row)));
    }
  EXPECT_EQ(seen.size(), 3u);
  const int refine = 2, m = size << refine;
  const Rendered r2 = render_tile(model, default_grid(), cell, size, refine, dem,
                                  {{"landcover", &landcover}}, "test");
  int uniform = 0;
  double step2 = 0;
  for (int row = 0; row < m; ++row)
    for (int col = 0; col < m; ++col) {
      const double got = r2.rgb[(size_t(row) * size_t(m) + size_t(col)) * 3] / 255;
      const int c0 = int(std::floor((col + 0.5) / (1 << refine) - 0.5)),
                r0_ = int(std::floor((row + 0.5) / (1 << refine) - 0.5));
      double lo = 1, hi = 0;
      for (int j = -1; j <= 2; ++j)
        for (int i = -1; i <= 2; ++i)
          lo = std::min(lo, value(c0 + i, r0_ + j)), hi = std::max(hi, value(c0 + i, r0_ + j));
      if (lo == hi) {
        ++uniform;
        ASSERT_NEAR(got, lo, 0.06 * lo) << col << " " << row;
      }
      EXPECT_GE(got, 0.75 * lo) << col << " " << row;
      EXPECT_LE(got, std::min(1.0, 1.25 * hi)) << col << " " << row;
      if (col > 0)
        step2 = std::max(
            step2, std::abs(got - r2.rgb[(size_t(row) * size_t(m) + size_t(col - 1)) * 3] / 255));
    }
  EXPECT_GT(uniform, m * m / 10);
  EXPECT_LT(step2, 0.5 * step0);
}

TEST(Procedural, SeamlessAcrossFaceSeam) {
  const int size = 16, refine = 1, level = 13;  // 35 m pixels
  const uint32_t last = (1u << level) - 1;
  // O's last column meets P's first (equatorial faces side by side).
  const CellId a = CellId::FromFaceColRow(1, level, last, 3200),
               b = CellId::FromFaceColRow(2, level, 0, 3200);
  const Rendered ra = render(a, size, refine), rb = render(b, size, refine);
  expect_seamless(ra.rgb, rb.rgb, ra.size, 3, "rgb");
  expect_seamless(ra.height, rb.height, ra.size, 1, "height");
}

// Finer levels refine the same surface: a pixel of refine 0 and the mean of its 4 children at
// refine 1 have about the same height.
TEST(Procedural, LevelsAgree) {
  const CellId cell = CellId::FromFaceColRow(2, 14, 8320, 8000);  // 35 and 17.6 m pixels
  const Rendered r0 = render(cell, 16, 0), r1 = render(cell, 16, 1);
  double worst = 0;
  for (int r = 0; r < 16; ++r)
    for (int c = 0; c < 16; ++c) {
      double mean = 0;
      for (int k = 0; k < 4; ++k)
        mean += r1.height[size_t(2 * r + k / 2) * 32 + size_t(2 * c + k % 2)] / 4;
      worst = std::max(worst, std::abs(mean - r0.height[size_t(r) * 16 + size_t(c)]));
    }
  EXPECT_LT(worst, 15);  // metres, on a relief of 3000 m with roughness of a few metres
}

TEST(Procedural, SameBitsForAnyThreadCount) {
  const int size = 32;
  std::vector<CellId> cells;
  for (uint32_t i = 0; i < 8; ++i)
    cells.push_back(CellId::FromFaceColRow(2, 14, 8320 + i % 4, 8000 + i / 4));
  const auto run_all = [&](int threads) {
    std::vector<std::vector<float>> out(cells.size());
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t)
      pool.emplace_back([&, t] {
        for (size_t i = size_t(t); i < cells.size(); i += size_t(threads)) {
          CellData d;
          d.inputs.emplace("dem", with_halo(cells[i], size, kInputHalo,
                                            [&](CellId c) { return sample(c, size, relief); }));
          const CellData r = run_cell("texture.procedural", cells[i], size, d, {{"model", kModel}});
          const auto img = r.outputs.at("imagery").data(), h = r.outputs.at("height").data();
          out[i].assign(img.begin(), img.end());
          out[i].insert(out[i].end(), h.begin(), h.end());
        }
      });
    for (auto& th : pool) th.join();
    return out;
  };
  const auto one = run_all(1);
  EXPECT_EQ(one, run_all(2));
  EXPECT_EQ(one, run_all(4));
}

// A cell rendered whole and as its 4 children one level finer (the same output pixels, the
// same DEM pixels): the same bits.
TEST(Procedural, SameBitsForAnyTiling) {
  const CellId parent = CellId::FromFaceColRow(2, 14, 8320, 8000);
  const Rendered whole = render(parent, 32, 2);
  ASSERT_EQ(whole.size, 128);
  for (uint32_t k = 0; k < 4; ++k) {
    const Rendered part =
        render(CellId::FromFaceColRow(2, 15, 2 * 8320 + k % 2, 2 * 8000 + k / 2), 16, 2);
    ASSERT_EQ(part.size, 64);
    for (size_t r = 0; r < 64; ++r)
      for (size_t c = 0; c < 64; ++c) {
        const size_t p = r * 64 + c, w = (r + 64 * (k / 2)) * 128 + c + 64 * (k % 2);
        for (size_t i = 0; i < 3; ++i) {
          ASSERT_EQ(part.rgb[3 * p + i], whole.rgb[3 * w + i]) << k << " " << c << " " << r;
          ASSERT_EQ(part.normal[3 * p + i], whole.normal[3 * w + i]) << k << " " << c << " " << r;
        }
        ASSERT_EQ(part.height[p], whole.height[w]) << k << " " << c << " " << r;
      }
  }
}

// The branch-free float arc tangent of the slope against std::atan in double, the slope of a
// ramp and its normals by hand.
TEST(Procedural, SlopeArcTangentAndNormals) {
  double worst_ulp = 0;
  for (int i = 1; i <= 200000; ++i) {  // 1e-4 to 10, then up to e^10
    const float x = float(i <= 100000 ? i * 1e-4 : 10 * std::exp((i - 100000) * 1e-4));
    const double a = std::atan(double(x));
    const float ulp = std::nextafter(float(a), 2.0f) - float(a);
    worst_ulp = std::max(worst_ulp, std::abs(atan_nonnegative(x) - a) / ulp);
  }
  EXPECT_LE(worst_ulp, 3);
  EXPECT_EQ(atan_nonnegative(0.0f), 0);
  EXPECT_TRUE(std::isnan(atan_nonnegative(NAN)));

  Plane ramp(16, 2);  // rising 3 m per column, pixels of 2 m: gradient 1.5
  for (int r = -2; r < 18; ++r)
    for (int c = -2; c < 18; ++c) ramp.at(c, r) = 3.0f * float(c);
  const Plane s = slope_degrees(ramp, 2);
  ASSERT_EQ(s.ring, 1);
  for (int r = -1; r < 17; ++r)
    for (int c = -1; c < 17; ++c) EXPECT_NEAR(s.at(c, r), 56.3099325, 1e-5) << c << " " << r;
  // Unit normal (-1.5, 0, 1) / sqrt(3.25); then rising 2 m per row downwards, gradient 1 up
  // the rows: (-1.5, 1, 1) / sqrt(4.25).
  std::vector<float> n(3 * 16 * 16);
  normals(ramp, 2, n.data());
  for (size_t p = 0; p < 16 * 16; ++p) {
    EXPECT_NEAR(n[3 * p], -1.5 / std::sqrt(3.25), 1e-6) << p;
    EXPECT_NEAR(n[3 * p + 1], 0, 1e-6) << p;
    EXPECT_NEAR(n[3 * p + 2], 1 / std::sqrt(3.25), 1e-6) << p;
  }
  for (int r = -2; r < 18; ++r)
    for (int c = -2; c < 18; ++c) ramp.at(c, r) = 3.0f * float(c) + 2.0f * float(r);
  normals(ramp, 2, n.data());
  for (size_t p = 0; p < 16 * 16; ++p) {
    EXPECT_NEAR(n[3 * p], -1.5 / std::sqrt(4.25), 1e-6) << p;
    EXPECT_NEAR(n[3 * p + 1], 1 / std::sqrt(4.25), 1e-6) << p;
    EXPECT_NEAR(n[3 * p + 2], 1 / std::sqrt(4.25), 1e-6) << p;
  }
}

// Every sample of every output is written, NaN where the DEM is missing (the runner hands
// texture.procedural uninitialized output tiles, OperatorSpec::writes_all_samples): rendered into
// tiles pre-filled with a NaN of a payload nothing computes, none of it survives.
TEST(Procedural, WritesEverySampleOfEveryOutput) {
  const auto& op = static_cast<const CellOperator&>(texture_operator("texture.procedural"));
  ASSERT_TRUE(op.spec().writes_all_samples);
  const json params = full_params("texture.procedural", {{"model", kModel}});
  const uint32_t sentinel = 0x7fc0dbad;
  const int size = 16, missing_rows = 6;
  const CellId cell = CellId::FromFaceColRow(2, 14, 8320, 8000);
  for (const int refine : {0, 1}) {
    Tile<float> dem =
        with_halo(cell, size, kInputHalo, [&](CellId c) { return sample(c, size, relief); });
    for (int r = -kInputHalo; r < missing_rows; ++r)  // a missing strip along the top
      for (int c = -kInputHalo; c < size + kInputHalo; ++c) dem.at(c, r) = NAN;
    CellData d;
    d.inputs.emplace("dem", std::move(dem));
    const int m = size << refine;
    for (const OutputSpec& out : op.spec().outputs)
      d.outputs.emplace(out.name, Tile<float>(m, out.channels, 0, std::bit_cast<float>(sentinel)));
    op.run({.cell = cell,
            .tile_size = size,
            .refine = refine,
            .grid = &default_grid(),
            .params = &params},
           d);
    for (const auto& [port, tile] : d.outputs) {
      ASSERT_EQ(tile.size(), m) << port;
      size_t left = 0, nan = 0;
      for (const float v : tile.data()) {
        left += std::bit_cast<uint32_t>(v) == sentinel;
        nan += std::isnan(v);
      }
      EXPECT_EQ(left, 0u) << port << ", refine " << refine;
      // NaN over the missing strip, values below it.
      EXPECT_GE(nan, size_t(missing_rows << refine) * size_t(m) * size_t(tile.channels())) << port;
      EXPECT_LT(nan, tile.data().size()) << port;
    }
  }
}

TEST(Procedural, ErrorsNameTheInput) {
  json model = kModel;
  model["quantities"].push_back({{"name", "rainfall"}, {"range", {0, 2000}}});
  const CellId cell = CellId::FromFaceColRow(2, 10, 520, 500);
  CellData d;
  d.inputs.emplace(
      "dem", with_halo(cell, 16, kInputHalo, [&](CellId c) { return sample(c, 16, relief); }));
  try {
    run_cell("texture.procedural", cell, 16, d, {{"model", model}});
    FAIL();
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(),
                 "texture.procedural: model quantity 'rainfall' has no input raster (map "
                 "inputs.rainfall)");
  }
  model = kModel;
  model["version"] = "1";
  try {
    run_cell("texture.procedural", cell, 16, d, {{"model", model}});
    FAIL();
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(),
                 "texture.procedural: params: model.version: unsupported version \"1\" (this "
                 "build reads version 1)");
  }
}

}  // namespace
}  // namespace maquette::texture
