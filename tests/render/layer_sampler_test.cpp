// LayerSampler (image/layer_sampler.h) on a store written here, each texel a hash of its face
// pixel: nearest sampling at every texel centre gives the stored texel exactly (at its plane point
// and at its lon/lat); tiles shared between threads give every value the same bits as a sampler
// reading its own tiles, sampled on two threads at once, at plane points and at lon/lat, again
// after the shared tiles dropped all their tiles and halos (re-read and re-made), and after they
// dropped the half not used since. Tiles of 64 pixels, so the points cross many tile edges and
// halos; one cell of the block has no tile. A point's value at its lon/lat is its value at its
// plane point (two ways to its cell). Bilinear values against an oracle computed here from the
// stored texels at face pixel coordinates: 3-band imagery without nodata and 4-band imagery with
// a fifth of its samples nodata, the samples of neighbours without a tile and nodata samples left
// out (the weights renormalized), NaN where the nearest is missing.
#include "image/layer_sampler.h"

#include <gtest/gtest.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/grid.h"
#include "store/store.h"
#include "test_tiles.h"

namespace maquette {
namespace {

constexpr int kLevel = 5, kSize = 64, kFace = 1, kCol0 = 9, kRow0 = 11, kCells = 3;

// Channel k's stored value at the face pixel (col, row): a hash, so a texel read from the wrong
// place (tile, halo, face) shows.
uint8_t texel_value(int64_t col, int64_t row, int k) {
  uint64_t x = uint64_t(col) * 1000003u + uint64_t(row) * 7919u + uint64_t(k);
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return uint8_t(x ^ (x >> 31));
}

// Channel k of the layer "rgba" at the face pixel (col, row): texel_value, a fifth of them 0, its
// nodata.
uint8_t rgba_value(int64_t col, int64_t row, int k) {
  const uint8_t v = texel_value(col, row, k);
  return v % 5 == 0 ? 0 : v;
}

// A store of 3-band imagery (layer rgb) and of 4-band imagery with nodata 0 (layer rgba) on
// kCells x kCells cells of kLevel, the top right one without a tile.
struct Imagery {
  std::string path = (std::filesystem::temp_directory_path() /
                      ("maquette-layer-sampler-" + std::to_string(::getpid()) + ".mqt"))
                         .string();
  LayerInfo layer = test::layer_info("rgb", DType::U8, 3, kSize, kLevel);
  LayerInfo rgba = [] {
    LayerInfo l = test::layer_info("rgba", DType::U8, 4, kSize, kLevel);
    l.nodata = 0;
    return l;
  }();
  std::vector<CellId> cells;  // those with a tile

  Imagery() {
    const Grid& grid = default_grid();
    std::filesystem::remove(path);
    auto store = Store::open(path, Store::Mode::Create);
    store->create_layer(layer);
    store->create_layer(rgba);
    Store::Batch batch(*store);
    for (int r = 0; r < kCells; ++r)
      for (int c = 0; c < kCells; ++c) {
        if (r == 0 && c == kCells - 1) continue;
        const CellId cell = CellId::FromFaceColRow(kFace, kLevel, kCol0 + c, kRow0 + r);
        cells.push_back(cell);
        batch.put_tile(
            "rgb", cell,
            test::make_tile<uint8_t>(grid, cell, kSize, 3, [](const test::TileSample& s, int k) {
              return texel_value(s.col, s.row, k);
            }));
        batch.put_tile(
            "rgba", cell,
            test::make_tile<uint8_t>(grid, cell, kSize, 4, [](const test::TileSample& s, int k) {
              return rgba_value(s.col, s.row, k);
            }));
      }
    batch.commit();
  }
  ~Imagery() {
    for (const char* suffix : {"", "-wal", "-shm"}) std::filesystem::remove(path + suffix);
  }
};

TEST(LayerSampler, NearestAtATexelCentreIsTheStoredTexel) {
  const Imagery im;
  const auto store = Store::open(im.path, Store::Mode::ReadOnly);
  const Grid& grid = default_grid();
  LayerSampler nearest(LayerSampler::shared_tiles(*store, grid, im.layer, kLevel),
                       LayerSampler::Read::kNearest);
  for (const CellId cell : im.cells)
    for (const test::TileSample& s : test::tile_samples(grid, cell, kSize)) {
      float at_plane[3], at_lonlat[3];
      ASSERT_TRUE(nearest.sample(s.plane, at_plane));
      ASSERT_TRUE(nearest.sample(s.lonlat, cell, at_lonlat));
      for (int k = 0; k < 3; ++k) {
        const float stored = texel_value(s.col, s.row, k);
        ASSERT_EQ(at_plane[k], stored) << "pixel " << s.col << ", " << s.row << " band " << k;
        ASSERT_EQ(at_lonlat[k], stored) << "pixel " << s.col << ", " << s.row << " band " << k;
      }
    }
}

TEST(LayerSampler, BilinearLeavesOutMissingSamplesAsAnOracle) {
  const Imagery im;
  const auto store = Store::open(im.path, Store::Mode::ReadOnly);
  const Grid& grid = default_grid();
  const PlaneSquare first = grid.plane_square(CellId::FromFaceColRow(kFace, kLevel, kCol0, kRow0));
  // A layer's stored value of channel k at the face pixel (col, row), NaN for its nodata.
  using Stored = std::function<double(int64_t, int64_t, int)>;
  // The bilinear value of `stored` at the face pixel coordinates (u, v) of the
  // pixel centres into out[k], and into used[k] how many of the four samples it weighs (0: the
  // nearest missing, NaN); false in a cell without a tile.
  auto oracle = [&](double u, double v, int channels, const Stored& stored, float* out, int* used) {
    auto has_tile = [](int64_t col, int64_t row) {
      const int64_t c = col / kSize - kCol0, r = row / kSize - kRow0;
      return c >= 0 && c < kCells && r >= 0 && r < kCells && !(r == 0 && c == kCells - 1);
    };
    auto value = [&](int64_t col, int64_t row, int k) {
      return has_tile(col, row) ? stored(col, row, k) : NAN;
    };
    if (!has_tile(std::llround(u), std::llround(v))) return false;
    const auto c0 = int64_t(std::floor(u)), r0 = int64_t(std::floor(v));
    const double fx = u - double(c0), fy = v - double(r0);
    for (int k = 0; k < channels; ++k) {
      out[k] = NAN;
      used[k] = 0;
      if (std::isnan(value(std::llround(u), std::llround(v), k))) continue;
      double sum = 0, weight = 0;
      for (int dr = 0; dr < 2; ++dr)
        for (int dc = 0; dc < 2; ++dc)
          if (const double s = value(c0 + dc, r0 + dr, k); !std::isnan(s)) {
            const double w = (dc ? fx : 1 - fx) * (dr ? fy : 1 - fy);
            sum += w * s, weight += w, ++used[k];
          }
      out[k] = float(sum / weight);
    }
    return true;
  };
  // Points 0.3 texel apart over the block, a row a run.
  constexpr int kSide = kCells * kSize * 10 / 3;
  const double step = kCells * first.side / kSide;
  // Counts the bands sampled by the samples weighed: four, fewer, none.
  using Kinds = std::array<size_t, 3>;
  auto expect_oracle = [&](const LayerInfo& layer, const Stored& stored, Kinds& kinds) {
    LayerSampler sampler(*store, grid, layer, kLevel, LayerSampler::Read::kBilinear);
    for (int row = 0; row < kSide; ++row) {
      sampler.start_run();
      for (int col = 0; col < kSide; ++col) {
        const double x = step * (col + 0.37), y = step * (row + 0.41);
        const double u = double(kCol0 * kSize) + x / first.side * kSize - 0.5;
        const double v = double(kRow0 * kSize) + y / first.side * kSize - 0.5;
        float got[4], want[4];
        int used[4];
        const bool sampled = sampler.sample(PlanePoint{first.x_min + x, first.y_max - y}, got);
        ASSERT_EQ(sampled, oracle(u, v, layer.channels, stored, want, used))
            << layer.name << " pixel " << u << ", " << v;
        if (!sampled) continue;
        for (int k = 0; k < layer.channels; ++k) {
          ++kinds[used[k] == 4 ? 0 : used[k] == 0 ? 2 : 1];
          if (used[k] == 0)
            ASSERT_TRUE(std::isnan(got[k])) << layer.name << " pixel " << u << ", " << v;
          else
            ASSERT_NEAR(got[k], want[k], 1e-3)
                << layer.name << " pixel " << u << ", " << v << " band " << k;
        }
      }
    }
  };
  // Without nodata, samples are missing only beyond the block and next to the cell without a
  // tile.
  Kinds rgb{}, rgba{};
  expect_oracle(
      im.layer, [](int64_t c, int64_t r, int k) { return double(texel_value(c, r, k)); }, rgb);
  EXPECT_GT(rgb[1], size_t(3000)) << "bands with samples missing";
  EXPECT_GT(rgb[0], 50 * rgb[1]) << "bands of four samples";
  expect_oracle(
      im.rgba,
      [](int64_t c, int64_t r, int k) {
        const uint8_t v = rgba_value(c, r, k);
        return v == 0 ? NAN : double(v);
      },
      rgba);
  for (size_t kind = 0; kind < 3; ++kind) EXPECT_GT(rgba[kind], size_t(200000)) << kind;
}

TEST(LayerSampler, SharedTilesGiveEachSamplersOwnValuesAfterDroppingThem) {
  const Imagery im;
  const auto store = Store::open(im.path, Store::Mode::ReadOnly);
  const Grid& grid = default_grid();
  const LayerInfo& layer = im.layer;
  // kSide x kSide points over the block's square (0.8 texel apart), a row a run.
  constexpr int kSide = 240;
  const PlaneSquare first = grid.plane_square(CellId::FromFaceColRow(kFace, kLevel, kCol0, kRow0));
  const double step = kCells * first.side / kSide;
  auto point = [&](int i) {
    return PlanePoint{first.x_min + step * (i % kSide + 0.37),
                      first.y_max - step * (i / kSide + 0.41)};
  };
  constexpr int kPoints = kSide * kSide;
  // Each point at its lon/lat and at its plane point: 3 bands each, NaN where no tile.
  using Values = std::vector<float>;
  auto sample_rows = [&](int rows, auto&& sampler_of_thread) {
    Values out(6 * size_t(kPoints), NAN);
    tbb::parallel_for(0, rows, [&](int row) {
      LayerSampler& s = sampler_of_thread();
      s.start_run();
      for (int i = row * kSide; i < (row + 1) * kSide; ++i) {
        const PlanePoint q = point(i);
        const LonLat p = grid.inverse(q);
        s.sample(p, grid.cell_from_point(p, layer.level), &out[6 * size_t(i)]);
        s.sample(q, &out[6 * size_t(i) + 3]);
      }
    });
    return out;
  };
  Values own;
  tbb::task_arena(1).execute([&] {
    LayerSampler s(*store, grid, layer, layer.level, LayerSampler::Read::kBilinear);
    own = sample_rows(kSide, [&]() -> LayerSampler& { return s; });
  });
  // A point's value at its lon/lat (its cell given, the previous one's kept when the same) is its
  // value at its plane point (the cell found from the point): the same texel, up to the last bits
  // of a point on a tile edge read from either tile's halo.
  size_t finite = 0;
  for (size_t i = 0; i < own.size(); i += 6)
    for (size_t k = 0; k < 3; ++k) {
      ASSERT_EQ(std::isfinite(own[i + k]), std::isfinite(own[i + 3 + k])) << i / 6;
      if (!std::isfinite(own[i + k])) continue;
      ++finite;
      EXPECT_NEAR(own[i + k], own[i + 3 + k], 1e-3) << "point " << i / 6 << " band " << k;
    }
  // The cell without a tile is a ninth of the points.
  ASSERT_GT(finite, size_t(kPoints) * 3 * 8 / 10);
  ASSERT_LT(finite, size_t(kPoints) * 3 * 9 / 10);

  const auto tiles = LayerSampler::shared_tiles(*store, grid, layer, layer.level);
  tbb::enumerable_thread_specific<std::optional<LayerSampler>> samplers;
  auto shared = [&]() -> LayerSampler& {
    auto& s = samplers.local();
    if (!s) s.emplace(tiles, LayerSampler::Read::kBilinear);
    return *s;
  };
  auto expect_own = [&](const char* when) {
    Values two;
    tbb::task_arena(2).execute([&] { two = sample_rows(kSide, shared); });
    ASSERT_EQ(std::memcmp(two.data(), own.data(), own.size() * sizeof(float)), 0) << when;
  };
  expect_own("first read");
  // Nothing used between the two calls: the second drops every tile and halo.
  LayerSampler::forget_unused(*tiles);
  LayerSampler::forget_unused(*tiles);
  expect_own("after dropping all");
  // The top half's tiles used since the last call kept, the others dropped.
  LayerSampler::forget_unused(*tiles);
  tbb::task_arena(2).execute([&] { sample_rows(kSide / 2, shared); });
  LayerSampler::forget_unused(*tiles);
  expect_own("after dropping the bottom half");
}

}  // namespace
}  // namespace maquette
