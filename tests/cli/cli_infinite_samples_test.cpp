// +-Inf in a float source is missing, like NaN: a raster with blocks of +Inf and -Inf ingests to
// the tiles of the same raster with NaN there (the oracle), with every resampling; where a
// coarser read averages source blocks (a tile spanning more than 2048 source pixels), no sample
// is infinite and every valid one equals the NaN raster's.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "run_cli.h"
#include "store/store.h"
#include "synthetic_raster.h"

namespace maquette::test {
namespace {

// A Float32 DEM of `size` pixels a side over 1 degree at 7 E 46 N, smooth, with two square blocks
// of `hole_value` (+Inf in one, -Inf in the other, or NaN in both).
void write_dem(const std::string& path, int size, bool infinite) {
  const RasterSpec s = lonlat_raster(7, 46, size, 1.0 / size, "Float32");
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  constexpr double kInf = std::numeric_limits<double>::infinity();
  write_raster(path, s, [=](int, double lon, double lat) {
    const double x = lon - 7, y = 46 - lat;  // 0..1
    if (x > 0.2 && x < 0.3 && y > 0.2 && y < 0.3) return infinite ? kInf : kNaN;
    if (x > 0.6 && x < 0.65 && y > 0.5 && y < 0.7) return infinite ? -kInf : kNaN;
    return 1000 + 300 * std::sin(5 * x) * std::cos(4 * y);
  });
}

// The float samples of every tile of layer `d`, in cell order.
std::vector<float> samples(const std::string& store) {
  const auto s = Store::open(store, Store::Mode::ReadOnly);
  std::vector<float> out;
  for (CellId c : s->tile_cells("d")) {
    const RawTile t = *s->get_tile("d", c);
    const auto* f = reinterpret_cast<const float*>(t.bytes.data());
    out.insert(out.end(), f, f + t.bytes.size() / sizeof(float));
  }
  return out;
}

std::vector<float> ingest(const std::string& tif, const std::string& options) {
  const std::string store = temp_dir() + "/s.mqt";
  const CliResult r = run_maquette("-q ingest " + store + " --layer d --as dem " + options + tif);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return samples(store);
}

TEST(InfiniteSamples, AreMissingLikeNaNWithEveryResampling) {
  const std::string dir = temp_dir(), inf = dir + "/inf.tif", nan = dir + "/nan.tif";
  write_dem(inf, 300, true);
  write_dem(nan, 300, false);
  for (const char* resampling : {"nearest", "bilinear", "cubic", "average", "mode"}) {
    for (const char* level : {"", "--level 8 "}) {  // the source's level, and coarser
      const std::string options = std::string("--resampling ") + resampling + " " + level;
      const std::vector<float> a = ingest(inf, options), b = ingest(nan, options);
      ASSERT_EQ(a.size(), b.size()) << options;
      ASSERT_FALSE(a.empty());
      size_t missing = 0;
      for (size_t i = 0; i < a.size(); ++i) {
        ASSERT_FALSE(std::isinf(a[i])) << options << " sample " << i;
        missing += std::isnan(a[i]);
        // The same bits: NaN where the NaN raster has NaN, its value elsewhere.
        ASSERT_EQ(std::isnan(a[i]), std::isnan(b[i])) << options << " sample " << i;
        if (!std::isnan(a[i])) {
          ASSERT_EQ(a[i], b[i]) << options << " sample " << i;
        }
      }
      EXPECT_GT(missing, 0u) << options;
    }
  }
}

TEST(InfiniteSamples, CoarseReadsStoreNoInfinity) {
  // 2100 pixels in one level-4 cell: the tile's window is read at every second pixel, averaged
  // by GDAL.
  const std::string dir = temp_dir(), inf = dir + "/inf.tif", nan = dir + "/nan.tif";
  write_dem(inf, 2100, true);
  write_dem(nan, 2100, false);
  for (const char* resampling : {"average", "bilinear"}) {
    const std::string options = std::string("--resampling ") + resampling + " --level 4 ";
    const std::vector<float> a = ingest(inf, options), b = ingest(nan, options);
    ASSERT_EQ(a.size(), b.size());
    size_t valid = 0;
    for (size_t i = 0; i < a.size(); ++i) {
      ASSERT_FALSE(std::isinf(a[i])) << options << " sample " << i;
      if (std::isnan(a[i])) continue;
      ++valid;
      ASSERT_EQ(a[i], b[i]) << options << " sample " << i;  // never a value the oracle lacks
    }
    EXPECT_GT(valid, 0u);
  }
}

}  // namespace
}  // namespace maquette::test
