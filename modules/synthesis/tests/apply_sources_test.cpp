// apply_sources.h on images written in the test with GDAL, each block's value worked out by hand.
#include "apply_sources.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/error.h"
#include "run_cli.h"
#include "synthetic_raster.h"

namespace maquette::synthesis {
namespace {

// A one-band float GeoTIFF of width x height pixels, pixel (x, y) value(x, y); `nodata` declared.
std::string value_tiff(const std::string& name, int width, int height,
                       const std::function<double(int, int)>& value,
                       std::optional<double> nodata = std::nullopt, int bands = 1) {
  test::RasterSpec spec;
  spec.width = width;
  spec.height = height;
  spec.bands = bands;
  spec.geotransform = {0, 1, 0, 0, 0, 1};  // pixel centres at (x + 0.5, y + 0.5)
  spec.nodata = nodata;
  const std::string path = test::temp_dir() + "/" + name;
  test::write_raster(path, spec, [&](int, double x, double y) { return value(int(x), int(y)); });
  return path;
}

TEST(ApplySources, EachBlocksMeanOrMostFrequentValue) {
  // 4 x 2, blocks of 2: left block 1 2 / 2 7, right block 5 5 / 3 3 (a tie: the smaller wins).
  const int values[2][4] = {{1, 2, 5, 5}, {2, 7, 3, 3}};
  const std::string path =
      value_tiff("apply-values.tif", 4, 2, [&](int x, int y) { return values[y][x]; });
  const SourceImage mean = value_image(path, 2, BlockValue::Mean);
  ASSERT_EQ(mean.blocks.size(), 2u);
  EXPECT_FLOAT_EQ(mean.blocks[0], 3.0f);  // (1 + 2 + 2 + 7) / 4
  EXPECT_FLOAT_EQ(mean.blocks[1], 4.0f);  // (5 + 5 + 3 + 3) / 4
  const SourceImage mode = value_image(path, 2, BlockValue::Mode);
  EXPECT_EQ(mode.blocks[0], 2.0f);
  EXPECT_EQ(mode.blocks[1], 3.0f);
  float out = 0;
  block_at({mode}, 2, 0, 0, &out);  // the block whose top-left painting pixel is (2, 0)
  EXPECT_EQ(out, 3.0f);
  block_at({mean}, 0, 0, 0, &out);
  EXPECT_EQ(out, 3.0f);
}

TEST(ApplySources, NodataIsNaNInTheMeanAndNotCountedInTheMode) {
  // Left block 4 -9 / -9 -9 (nodata -9): its mean NaN, its mode 4; right block all nodata: NaN.
  const std::string path = value_tiff(
      "apply-nodata.tif", 4, 2, [](int x, int y) { return x == 0 && y == 0 ? 4 : -9; }, -9.0);
  const SourceImage mean = value_image(path, 2, BlockValue::Mean);
  EXPECT_TRUE(std::isnan(mean.blocks[0]));
  const SourceImage mode = value_image(path, 2, BlockValue::Mode);
  EXPECT_EQ(mode.blocks[0], 4.0f);
  EXPECT_TRUE(std::isnan(mode.blocks[1]));
}

TEST(ApplySources, ColoursAreEachBlocksMeanAndImagesFollowTheirPainting) {
  // Painting 0: 4 x 4 grey 10 everywhere but (1, 1) at 50; painting 1: 2 x 2 RGB (200, 100, 0).
  const std::string grey =
      test::write_png(test::temp_dir() + "/apply-grey.png", 4, 4, 1,
                      [](int x, int y, int) { return x == 1 && y == 1 ? 50 : 10; });
  const std::string rgb = test::write_png(test::temp_dir() + "/apply-rgb.png", 2, 2, 3,
                                          [](int, int, int b) { return 200 - 100 * b; });
  const std::vector<SourceImage> images = {colour_image(grey, 2), colour_image(rgb, 2)};
  float out[3];
  block_at(images, 0, 0, 0, out);
  for (const float v : out) EXPECT_FLOAT_EQ(v, 20.0f);  // (10 + 10 + 10 + 50) / 4
  block_at(images, 2, 2, 0, out);
  for (const float v : out) EXPECT_FLOAT_EQ(v, 10.0f);
  block_at(images, 0, 0, 1, out);
  EXPECT_FLOAT_EQ(out[0], 200.0f);
  EXPECT_FLOAT_EQ(out[1], 100.0f);
  EXPECT_FLOAT_EQ(out[2], 0.0f);
}

TEST(ApplySources, SourcesThatNoImageHoldsAreNamed) {
  const std::string path = value_tiff("apply-small.tif", 4, 2, [](int x, int) { return x; });
  const std::vector<SourceImage> images = {value_image(path, 2, BlockValue::Mean)};
  float out = 0;
  const auto refused = [&](float col, float row, float painting, const std::string& message) {
    try {
      block_at(images, col, row, painting, &out);
      ADD_FAILURE() << "accepted (" << col << ", " << row << ") of painting " << painting;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
  };
  refused(0, 0, 1, "the source names painting 1.000000, and params.images gives 1");
  refused(0, 0, 0.5f, "the source names painting 0.500000");
  refused(1, 0, 0, "painting pixel (1, 0), which starts no block of exemplar_scale 2");
  refused(4, 0, 0, path + ": 4 x 2 pixels, and the source names painting pixel (4, 0)");
  refused(0, -2, 0, "painting pixel (0, -2): the image must have its painting's size");
  // A three-band image is no value image; an image smaller than a block holds none.
  try {
    value_image(value_tiff(
                    "apply-3.tif", 4, 2, [](int, int) { return 1; }, {}, 3),
                2, BlockValue::Mean);
    ADD_FAILURE() << "a three-band value image was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("the value image has 3 bands: it must be one band"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(value_image(path, 4, BlockValue::Mean), Error);
}

}  // namespace
}  // namespace maquette::synthesis
