// LayerSampler's tiles shared between threads (image/layer_sampler.h, as the panorama's samplers
// share the texture's): every value the same bits as a sampler reading its own tiles, sampled on
// two threads at once, at plane points and at lon/lat, and again after the shared tiles dropped
// those unused; tiles of 64 pixels, so the points cross many tile edges and halos. A point's value
// at its lon/lat is its value at its plane point (two ways to its cell).
#include "image/layer_sampler.h"

#include <gtest/gtest.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include "core/grid.h"
#include "run_cli.h"
#include "store/store.h"
#include "synthetic_raster.h"

namespace maquette {
namespace {

// A store of 3-band imagery (layer rgb) from 10 E to 10.3 E and 45 N to 45.3 N in 64-pixel tiles.
std::string imagery_store() {
  const std::string dir = test::temp_dir(), path = dir + "/rgb.mqt";
  test::RasterSpec rgb = test::lonlat_raster(10, 45.3, 600, 0.0005, "Byte");
  rgb.bands = 3;
  test::write_raster(dir + "/rgb.tif", rgb, [](int band, double lon, double lat) {
    return band == 1 ? 60 + 40 * std::sin(lon * 3000) : band == 2 ? (lat - 45) * 600 : 90;
  });
  const auto r = test::run_maquette("-q ingest " + path +
                                    " --layer rgb --as imagery --tile-size 64 " + dir + "/rgb.tif");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return path;
}

TEST(LayerSampler, SharedTilesGiveEachSamplersOwnValues) {
  const auto store = Store::open(imagery_store(), Store::Mode::ReadOnly);
  const Grid& grid = default_grid();
  const LayerInfo layer = store->require_layer("rgb");
  constexpr int kSide = 240;  // points a row and rows, 0.00125 degree apart (2.5 pixels)
  auto point = [](int i) {
    return LonLat{10.0004 + 0.00125 * (i % kSide), 45.0004 + 0.00125 * (i / kSide)};
  };
  constexpr int kPoints = kSide * kSide;
  // Each point at its lon/lat and at its plane point: 3 bands each, NaN where no tile.
  using Values = std::vector<float>;
  auto sample_all = [&](auto&& sampler_of_thread) {
    Values out(6 * size_t(kPoints), NAN);
    tbb::parallel_for(0, kSide, [&](int row) {
      LayerSampler& s = sampler_of_thread();
      s.start_run();
      for (int i = row * kSide; i < (row + 1) * kSide; ++i) {
        const LonLat p = point(i);
        s.sample(p, grid.cell_from_point(p, layer.level), &out[6 * size_t(i)]);
        s.sample(grid.forward(p), &out[6 * size_t(i) + 3]);
      }
    });
    return out;
  };
  Values own;
  tbb::task_arena(1).execute([&] {
    LayerSampler s(*store, grid, layer, layer.level, true);
    own = sample_all([&]() -> LayerSampler& { return s; });
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
  ASSERT_GT(finite, size_t(kPoints) * 3 * 9 / 10);

  const auto tiles = LayerSampler::shared_tiles(*store, grid, layer, layer.level);
  tbb::enumerable_thread_specific<std::optional<LayerSampler>> samplers;
  auto shared = [&]() -> LayerSampler& {
    auto& s = samplers.local();
    if (!s) s.emplace(tiles, true);
    return *s;
  };
  for (int round = 0; round < 3; ++round) {  // then after dropping the unused tiles, twice
    Values two;
    tbb::task_arena(2).execute([&] { two = sample_all(shared); });
    ASSERT_EQ(std::memcmp(two.data(), own.data(), own.size() * sizeof(float)), 0)
        << "round " << round;
    LayerSampler::forget_unused(*tiles);
  }
}

}  // namespace
}  // namespace maquette
