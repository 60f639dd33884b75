// `maquette render panorama` samples the texture at the level the distance needs: a checkerboard
// of one raster pixel (0.0005 degrees, 39 x 55 m) over flat ground, ingested at level 11 (17.6 m
// texels: a wave of about +-32 around grey once resampled), seen straight down. From 3 km a pixel
// is 0.6 texels wide: the texture's own level, the wave kept (deviation ~32). From 40 km a pixel
// is 8 texels wide: the levels of its overviews (their children's means), grey (~2). Sampled at
// the texture's own level from 40 km (before), the pixels fell on the wave's crests and troughs by
// the beat of the two grids (aliasing): a deviation of ~33, the near picture's.
#include <gdal_priv.h>
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "run_cli.h"
#include "synthetic_raster.h"

namespace maquette {
namespace {

constexpr double kWest = 10, kNorth = 45.1, kPixel = 0.0005;  // degrees
constexpr int kSize = 400, kPicture = 100;

struct Stats {
  double mean = 0, deviation = 0;
  int terrain = 0;
};

// The red band's mean and standard deviation over the picture `path`.
Stats red_stats(const std::string& path) {
  std::unique_ptr<GDALDataset> picture(GDALDataset::Open(path.c_str(), GDAL_OF_RASTER));
  EXPECT_TRUE(picture) << path;
  if (!picture) return {};
  std::vector<uint8_t> red(size_t(kPicture) * kPicture);
  EXPECT_EQ(picture->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, kPicture, kPicture, red.data(),
                                                kPicture, kPicture, GDT_Byte, 0, 0),
            CE_None);
  Stats s;
  double sum = 0, squares = 0;
  for (const uint8_t r : red) sum += r, squares += double(r) * r, ++s.terrain;
  s.mean = sum / s.terrain;
  s.deviation = std::sqrt(squares / s.terrain - s.mean * s.mean);
  return s;
}

TEST(PanoramaTexture, FarGroundIsSampledFromTheOverviewsItsPixelsSpan) {
  const std::string dir = test::temp_dir(), store = dir + "/s.mqt";
  test::write_raster(dir + "/dem.tif", test::lonlat_raster(kWest, kNorth, kSize, kPixel, "Float32"),
                     [](int, double, double) { return 100.0; });
  test::RasterSpec rgb = test::lonlat_raster(kWest, kNorth, kSize, kPixel, "Byte");
  rgb.bands = 3;
  test::write_raster(dir + "/rgb.tif", rgb, [](int, double lon, double lat) {
    const auto col = int64_t(std::floor((lon - kWest) / kPixel)),
               row = int64_t(std::floor((kNorth - lat) / kPixel));
    return (col + row) % 2 == 0 ? 255.0 : 0.0;
  });
  for (const std::string& ingest :
       {"--layer dem --as dem --vertical-datum ellipsoid " + dir + "/dem.tif",
        "--layer rgb --as imagery --level 11 " + dir + "/rgb.tif"}) {
    const auto r = test::run_maquette("-q ingest " + store + " " + ingest);
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  // Straight down on the box's centre, the sun overhead (flat ground shaded 1), no haze, the
  // texture as stored.
  auto picture = [&](const std::string& name, int height) {
    const std::string out = dir + "/" + name + ".png";
    const auto r = test::run_maquette(
        "-q render panorama " + store + " " + out +
        " --dem dem --texture rgb --no-stretch --sun 0 90 --haze-distance 1e12 --camera " +
        std::to_string(kWest + kSize * kPixel / 2) + " " +
        std::to_string(kNorth - kSize * kPixel / 2) + " " + std::to_string(height) +
        " --pitch -90 --fov 20 --size " + std::to_string(kPicture) + " " +
        std::to_string(kPicture));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return red_stats(out);
  };
  const Stats near = picture("near", 3000), far = picture("far", 40000);
  EXPECT_EQ(near.terrain, kPicture * kPicture);
  EXPECT_EQ(far.terrain, kPicture * kPicture);
  RecordProperty("near_deviation", std::to_string(near.deviation));
  RecordProperty("far_deviation", std::to_string(far.deviation));
  EXPECT_GT(near.deviation, 25) << "the checker's contrast near";
  EXPECT_LT(far.deviation, 8) << "the checker averaged far";
  EXPECT_NEAR(far.mean, 127.5, 15);
}

}  // namespace
}  // namespace maquette
