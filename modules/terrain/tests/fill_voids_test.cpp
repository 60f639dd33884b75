// terrain.fill_voids on fields with known answers: the Laplace fill reproduces harmonic fields
// (linear, x^2 - y^2, xy) and the biharmonic fill every cubic, as the discrete equations do
// exactly; samples outside voids keep their bits; a void gives the same values whichever tile
// computes it, within a face (same bits) and across a turned face seam.
#include <gtest/gtest.h>

#include <cstring>
#include <limits>

#include "../void_fill.h"
#include "core/ecef.h"
#include "terrain_module.h"

namespace maquette::terrain {
namespace {

using terrain_test::run;

constexpr int kSize = 64, kHalo = 64;
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
const CellId kCell = CellId::FromFaceColRow(3, 8, 100, 60);

using Field = std::function<double(double x, double y)>;
using Mask = std::function<bool(int col, int row)>;

bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// The operator's input: field at window pixel (col, row), halo included, scaled to x, y in
// [-6, 6], NaN where `is_void`.
CellData window(const Field& field, const Mask& is_void) {
  Tile<float> dem(kSize, 1, kHalo);
  for (int row = -kHalo; row < kSize + kHalo; ++row)
    for (int col = -kHalo; col < kSize + kHalo; ++col)
      dem.at(col, row) =
          is_void(col, row) ? kNaN : float(field((col - 32) / 16.0, (row - 32) / 16.0));
  CellData data;
  data.inputs.emplace("dem", std::move(dem));
  return data;
}

// A disc inside the tile, a void with a known island across the tile's top-left corner, and a
// thin one across its right edge; 3 pixels apart or more, so no stencil meets two voids.
bool three_voids(int col, int row) {
  const bool disc = (col - 20) * (col - 20) + (row - 30) * (row - 30) <= 100;
  const bool corner = col >= -12 && col <= 5 && row >= -8 && row <= 9 &&
                      !(col >= -6 && col <= -3 && row >= -2 && row <= 1);
  const bool thin = col >= 55 && col <= 75 && row >= 44 && row <= 46;
  return disc || corner || thin;
}

// Largest |filled - field| over the void samples of the tile; every one must be filled.
double max_fill_error(const Field& field, const json& params) {
  const CellData in = window(field, three_voids);
  const Tile<float> out = run("terrain.fill_voids", kCell, kSize, in, params).outputs.at("dem");
  double worst = 0;
  for (int row = 0; row < kSize; ++row)
    for (int col = 0; col < kSize; ++col) {
      if (!three_voids(col, row)) continue;
      EXPECT_FALSE(std::isnan(out.at(col, row))) << col << "," << row;
      worst =
          std::max(worst, std::abs(out.at(col, row) - field((col - 32) / 16.0, (row - 32) / 16.0)));
    }
  return worst;
}

TEST(FillVoids, LaplaceReproducesHarmonicFields) {
  const json laplace = {{"method", "laplace"}};
  EXPECT_LT(max_fill_error([](double x, double y) { return 100 + 3 * x - 2 * y; }, laplace), 1e-4);
  EXPECT_LT(max_fill_error([](double x, double y) { return x * x - y * y + 0.5 * x * y; }, laplace),
            1e-4);
  // Not the paraboloid: its Laplacian is not zero, and the membrane sags below it (by ~R^2/256).
  EXPECT_GT(max_fill_error([](double x, double y) { return x * x + y * y; }, laplace), 0.2);
}

TEST(FillVoids, BiharmonicReproducesCubics) {
  const json biharmonic = {{"method", "biharmonic"}};
  // The 5-point Laplacian of a cubic is linear, whose Laplacian is zero: the thin-plate
  // equations hold exactly for every quadratic and cubic.
  EXPECT_LT(
      max_fill_error(
          [](double x, double y) { return 1 + x - y + 0.5 * x * x - 0.3 * x * y + 0.2 * y * y; },
          biharmonic),
      1e-4);
  EXPECT_LT(max_fill_error(
                [](double x, double y) {
                  return 0.05 * x * x * x - 0.02 * x * x * y + 0.01 * x * y * y + 0.03 * y * y * y;
                },
                biharmonic),
            1e-4);
  // But not x^4, whose discrete bilaplacian is 24 (times the pixel scale).
  EXPECT_GT(max_fill_error([](double x, double y) { return x * x * x * x + y; }, biharmonic), 1e-3);
}

// A rough field: samples outside the voids keep their bits, and the mask is 1 exactly where a
// void was filled. A void larger than the halo is filled from the input's overviews, which a
// cell run outside a pipeline does not have: an error says so.
TEST(FillVoids, OnlyVoidsChange) {
  const Mask voids = [](int col, int row) {
    return three_voids(col, row) || (col >= 0 && col <= 62 && row == 20);  // extent 63
  };
  const auto rough = [](double x, double y) {
    return std::sin(97 * x) * 40 + std::cos(53 * x * y) * 70;
  };
  const CellData in = window(rough, voids);
  for (const std::string method : {"laplace", "biharmonic"}) {
    const CellData out = run("terrain.fill_voids", kCell, kSize, in, {{"method", method}});
    const Tile<float>& dem = out.outputs.at("dem");
    const Tile<float>& mask = out.outputs.at("filled");
    for (int row = 0; row < kSize; ++row)
      for (int col = 0; col < kSize; ++col) {
        const float before = in.inputs.at("dem").at(col, row);
        if (!voids(col, row))
          ASSERT_TRUE(same_bits(dem.at(col, row), before)) << method << " " << col << "," << row;
        else
          ASSERT_FALSE(std::isnan(dem.at(col, row))) << method << " " << col << "," << row;
        ASSERT_EQ(mask.at(col, row), voids(col, row) ? 1.f : 0.f);
      }
  }
  const CellData large = window(rough, [](int col, int row) { return col <= 63 && row == 60; });
  try {
    run("terrain.fill_voids", kCell, kSize, large);
    FAIL() << "a void of 64 pixels was filled without overviews";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("set params.pyramid"), std::string::npos) << e.what();
  }
}

// Global face pixels at level 14 of one face: rough terrain with voids placed across the borders
// of the four level-8 children of a level-7 cell and across its own border.
constexpr int64_t kCol0 = 40 * 128, kRow0 = 50 * 128;

float global_sample(int64_t gc, int64_t gr) {
  const auto in_disc = [&](int64_t c, int64_t r, int64_t radius) {
    return (gc - c) * (gc - c) + (gr - r) * (gr - r) <= radius * radius;
  };
  const int64_t c = gc - kCol0, r = gr - kRow0;
  const bool hole = in_disc(kCol0 + 64, kRow0 + 30, 8) || in_disc(kCol0 + 64, kRow0 + 64, 12) ||
                    in_disc(kCol0, kRow0 + 90, 6) || (c >= 10 && c <= 70 && r >= 100 && r <= 102);
  return hole ? kNaN
              : float(500 + 200 * std::sin(gc / 9.0) * std::cos(gr / 13.0) + 0.3 * (gc % 50));
}

Tile<float> global_tile(CellId cell, int size) {
  Tile<float> tile(size, 1);
  for (int row = 0; row < size; ++row)
    for (int col = 0; col < size; ++col)
      tile.at(col, row) = global_sample(global_col(cell, size, col), global_row(cell, size, row));
  return tile;
}

CellData dem_with_halo(CellId cell, int size, const TileFetch& fetch) {
  CellData data;
  data.inputs.emplace("dem", assemble_halo(default_grid(), cell, size, kHalo, fetch));
  return data;
}

TEST(FillVoids, SameBitsWhicheverTileFillsAVoid) {
  const TileFetch fetch = [](CellId c) {
    return std::optional<Tile<float>>(global_tile(c, c.level() == 7 ? 128 : 64));
  };
  const CellId parent = CellId::FromFaceColRow(2, 7, 40, 50);
  for (const std::string method : {"laplace", "biharmonic"}) {
    const json params = {{"method", method}};
    const CellData whole =
        run("terrain.fill_voids", parent, 128, dem_with_halo(parent, 128, fetch), params);
    const CellData again =
        run("terrain.fill_voids", parent, 128, dem_with_halo(parent, 128, fetch), params);
    const Tile<float>& a = whole.outputs.at("dem");
    EXPECT_EQ(
        std::memcmp(a.data().data(), again.outputs.at("dem").data().data(), a.data().size_bytes()),
        0);
    int filled = 0;
    for (int k = 0; k < 4; ++k) {
      const CellId child = parent.child(k);
      const CellData part =
          run("terrain.fill_voids", child, 64, dem_with_halo(child, 64, fetch), params);
      const int dc = int(child.col() - 2 * parent.col()) * 64,
                dr = int(child.row() - 2 * parent.row()) * 64;
      for (int row = 0; row < 64; ++row)
        for (int col = 0; col < 64; ++col) {
          ASSERT_TRUE(same_bits(part.outputs.at("dem").at(col, row), a.at(col + dc, row + dr)))
              << method << " child " << k << " " << col << "," << row;
          ASSERT_EQ(part.outputs.at("filled").at(col, row),
                    whole.outputs.at("filled").at(col + dc, row + dr));
          filled += int(part.outputs.at("filled").at(col, row));
        }
    }
    EXPECT_GT(filled, 700);
  }
}

// A void on the P | N seam, where N's pixels arrive turned by 90 degrees: the void's samples in
// P's tile, filled by P, match the same samples filled in the halo of N's tile.
TEST(FillVoids, SeamlessAcrossTurnedFaces) {
  const Grid& grid = default_grid();
  const CellId a = CellId::FromFaceColRow(2, 6, 20, 0);
  const CellId b = grid.edge_neighbours(a)[0];
  ASSERT_NE(b.face(), a.face());
  const int level = a.level() + log2_tile_size(kSize);
  const Vec3 seam = up_unit(terrain_test::true_centre(a, kSize, 30, 0));
  const double radius = 12 * (M_PI / 2) / double(1 << level);  // ~12 pixels
  const TileFetch fetch = [&](CellId c) {
    Tile<float> tile(kSize, 1);
    for (int row = 0; row < kSize; ++row)
      for (int col = 0; col < kSize; ++col) {
        const Vec3 u = up_unit(terrain_test::true_centre(c, kSize, col, row));
        const double d = std::hypot(u[0] - seam[0], u[1] - seam[1], u[2] - seam[2]);
        tile.at(col, row) =
            d < radius ? kNaN : float(2000 * u[0] + 3000 * u[1] * u[2] + 700 * u[2]);
      }
    return std::optional<Tile<float>>(tile);
  };
  const Tile<float> from_a =
      run("terrain.fill_voids", a, kSize, dem_with_halo(a, kSize, fetch)).outputs.at("dem");
  const Tile<float> window_b = assemble_halo(grid, b, kSize, kHalo, fetch);
  const Tile<float> from_b = fill_voids(window_b, {});
  int compared = 0;
  for (int row = -kHalo; row < kSize + kHalo; ++row)
    for (int col = -kHalo; col < kSize + kHalo; ++col) {
      const std::optional<FaceCoord> src = pixel_source(grid, b, kSize, col, row);
      if (!src || src->face != a.face() || !std::isnan(window_b.at(col, row))) continue;
      const int64_t ac = src->col - int64_t(a.col()) * kSize,
                    ar = src->row - int64_t(a.row()) * kSize;
      if (ac < 0 || ar < 0 || ac >= kSize || ar >= kSize) continue;
      ASSERT_NEAR(from_b.at(col, row), from_a.at(int(ac), int(ar)), 1e-3) << col << "," << row;
      ++compared;
    }
  EXPECT_GT(compared, 100);
}

}  // namespace
}  // namespace maquette::terrain
