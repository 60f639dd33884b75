// export png --hillshade has no waffle: the shade of a smooth lon/lat DEM, exported through the
// real program, against gdaldem's Horn hillshade of the same DEM resampled (gdalwarp, bilinear)
// onto the PNG's own georeferenced grid. Resampling the store by nearest neighbour before
// shading repeats rows and columns at regular intervals: a periodic pattern far above this bound.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <numbers>
#include <sstream>

#include "export_fixture.h"
#include "run_cli.h"
#include "synthetic_raster.h"

namespace maquette::test {
namespace {

// Hills a few km across at 46.6-47 degrees north, where a lon/lat pixel is 1.5 times taller
// than wide on the ground (as at Mount Rainier, where the waffle was seen).
double hills(double lon, double lat) {
  constexpr double k = 2 * std::numbers::pi;
  return 800 + 300 * std::sin(k * lon / 0.11) * std::cos(k * lat / 0.13) +
         150 * std::sin(k * (lon + lat) / 0.07);
}

TEST(PngHillshade, AgreesWithGdaldemWithoutPeriodicArtefacts) {
  const std::string dir = temp_dir();
  RasterSpec spec;
  spec.width = spec.height = 800;
  spec.geotransform = {10, 0.0005, 0, 47, 0, -0.0005};
  spec.crs = "EPSG:4326";
  write_raster(dir + "/dem.tif", spec, [](int, double x, double y) { return hills(x, y); });
  CliResult r = run_maquette("ingest " + dir + "/s.mqt --layer dem --as dem " + dir + "/dem.tif");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // A grey ramp held at white: the PNG is the shade alone, 255 x shade.
  r = run_maquette("export png " + dir + "/s.mqt --layer dem " + dir +
                   "/shade.png --hillshade --ramp grey --range -100000 -99999 --no-legend");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto png = open_raster(dir + "/shade.png");
  ASSERT_TRUE(png);
  double gt[6];
  ASSERT_EQ(png->GetGeoTransform(gt), CE_None);
  const int w = png->GetRasterXSize(), h = png->GetRasterYSize();
  std::ostringstream cmd;
  cmd << std::setprecision(17) << "gdalwarp -q -r bilinear -te " << gt[0] << " "
      << gt[3] + h * gt[5] << " " << gt[0] + w * gt[1] << " " << gt[3] << " -ts " << w << " " << h
      << " " << dir << "/dem.tif " << dir << "/warped.tif";
  // gdaldem takes one scale for both axes: shrink the longitudes by cos(latitude) at the centre
  // (it varies by 0.4 % over the box).
  const double shrink = std::cos((gt[3] + h * gt[5] / 2) * std::numbers::pi / 180);
  cmd << " && gdal_translate -q -a_ullr " << gt[0] * shrink << " " << gt[3] << " "
      << (gt[0] + w * gt[1]) * shrink << " " << gt[3] + h * gt[5] << " " << dir << "/warped.tif "
      << dir << "/metric.tif && gdaldem hillshade -q -s 111195 -az 315 -alt 45 " << dir
      << "/metric.tif " << dir << "/gdaldem.tif";
  ASSERT_EQ(std::system(cmd.str().c_str()), 0) << cmd.str();
  const auto ref = open_raster(dir + "/gdaldem.tif");
  ASSERT_TRUE(ref);
  const std::vector<double> ours = read_band(*png, 1), alpha = read_band(*png, 4),
                            theirs = read_band(*ref, 1);
  // Interior pixels only: gdaldem leaves the outer ring empty and our data edge is ragged.
  double sum2 = 0;
  std::vector<double> row_sum(size_t(h), 0.0), row_n(size_t(h), 0.0);
  int n = 0;
  for (int row = 4; row < h - 4; ++row)
    for (int col = 4; col < w - 4; ++col) {
      bool inside = true;
      for (int d = -3; d <= 3 && inside; ++d)
        inside = alpha[size_t(row + d) * w + col] == 255 && alpha[size_t(row) * w + col + d] == 255;
      const double g = theirs[size_t(row) * w + col];
      if (!inside || g == 0) continue;  // 0: gdaldem's nodata
      const double diff = ours[size_t(row) * w + col] / 255 - (g - 1) / 254;
      sum2 += diff * diff, ++n;
      row_sum[size_t(row)] += diff, row_n[size_t(row)] += 1;
    }
  ASSERT_GT(n, w * h / 2);
  const double rms = std::sqrt(sum2 / n);
  EXPECT_LT(rms, 0.008);  // 0.004 measured; nearest resampling before shading: 0.017
  // A waffle shows as rows darker or lighter than their neighbours all the way across.
  double worst_row_step = 0;
  auto mean = [&](int row) { return row_sum[size_t(row)] / std::max(row_n[size_t(row)], 1.0); };
  for (int row = 6; row < h - 6; ++row)
    if (row_n[size_t(row)] > w / 2 && row_n[size_t(row - 1)] > w / 2)
      worst_row_step = std::max(worst_row_step, std::abs(mean(row) - mean(row - 1)));
  EXPECT_LT(worst_row_step, 0.004);  // 0.0012 measured; nearest: 0.008
  std::cout << "hillshade vs gdaldem: rms " << rms << ", worst row step " << worst_row_step << "\n";
}

}  // namespace
}  // namespace maquette::test
