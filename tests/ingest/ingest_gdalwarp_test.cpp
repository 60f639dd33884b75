// The same output grid as one of our tiles, made by the real gdalwarp to +proj=rhealpix.
#include <gdal_priv.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include "core/halo.h"
#include "ingest_fixture.h"
#include "synthetic_raster.h"

namespace maquette::test {
namespace {

TEST(IngestGdalwarp, BilinearTileMatchesGdalwarp) {
  if (std::system("gdalwarp --version >/dev/null 2>&1") != 0) GTEST_SKIP() << "no gdalwarp";
  const std::string dir = temp_dir(), tif = dir + "/utm.tif";
  RasterSpec spec;
  spec.width = spec.height = 300;
  spec.geotransform = {494000, 30, 0, 4126000, 0, -30};
  spec.crs = "EPSG:32612";
  write_raster(tif, spec, [](int, double e, double n) {
    return 1000 + 50 * std::sin(e / 700) * std::cos(n / 900);
  });
  RasterIngestOptions o;
  o.layer = "f";
  o.as = "raster";
  o.tile_size = 128;
  const auto store = ingest(dir, "w", {tif}, o);
  // The tile with the most valid samples.
  CellId best;
  int64_t best_valid = -1;
  for (CellId c : store->tile_cells("f")) {
    const Tile<float> t = to_tile<float>(*store->get_tile("f", c));
    int64_t valid = 0;
    for (float v : t.data()) valid += !std::isnan(v);
    if (valid > best_valid) best = c, best_valid = valid;
  }
  ASSERT_GT(best_valid, 128 * 128 / 2);
  const PlaneSquare sq = default_grid().plane_square(best);
  const std::string out = dir + "/warp.tif";
  char cmd[1024];
  std::snprintf(cmd, sizeof cmd,
                "gdalwarp -q -overwrite -t_srs '+proj=rhealpix +ellps=WGS84 +north_square=0 "
                "+south_square=0' -te %.6f %.6f %.6f %.6f -ts 128 128 -r bilinear -ot Float32 "
                "-dstnodata nan %s %s",
                sq.x_min, sq.y_max - sq.side, sq.x_min + sq.side, sq.y_max, tif.c_str(),
                out.c_str());
  ASSERT_EQ(std::system(cmd), 0) << cmd;
  GDALAllRegister();
  GDALDatasetUniquePtr ds(GDALDataset::Open(out.c_str(), GDAL_OF_RASTER));
  ASSERT_TRUE(ds);
  std::vector<float> warp(128 * 128);
  ASSERT_EQ(ds->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, 128, 128, warp.data(), 128, 128,
                                           GDT_Float32, 0, 0),
            CE_None);
  const Tile<float> ours = to_tile<float>(*store->get_tile("f", best));
  double sum = 0, worst = 0;
  int64_t n = 0;
  for (int r = 0; r < 128; ++r)
    for (int c = 0; c < 128; ++c) {
      const float a = ours.at(c, r), b = warp[size_t(r) * 128 + size_t(c)];
      if (std::isnan(a) || std::isnan(b)) continue;
      const double d = std::abs(double(a) - double(b));
      sum += d;
      worst = std::max(worst, d);
      ++n;
    }
  ASSERT_GT(n, 128 * 128 / 2);
  // Field range 100, gradient <= 2.2 per pixel: both keep the transform within 1/8 pixel.
  EXPECT_LT(sum / double(n), 0.01);
  EXPECT_LT(worst, 0.3);
}

}  // namespace
}  // namespace maquette::test
