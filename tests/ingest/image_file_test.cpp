// 8-bit images through GDAL's drivers (formats/gdal/image_file.h, used for GLB textures and
// quicklooks): decoded back by GDAL, PNG exactly, JPEG within its loss.
#include "gdal/image_file.h"

#include <gdal_priv.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "core/error.h"
#include "gdal/gdal_env.h"

namespace maquette {
namespace {

// A smooth test picture: width x height pixels of `bands` interleaved bytes.
std::vector<uint8_t> picture(int width, int height, int bands) {
  std::vector<uint8_t> px(size_t(width) * size_t(height) * size_t(bands));
  for (int r = 0; r < height; ++r)
    for (int c = 0; c < width; ++c)
      for (int b = 0; b < bands; ++b)
        px[(size_t(r) * size_t(width) + size_t(c)) * size_t(bands) + size_t(b)] =
            uint8_t(b == 3 ? 255 - c : (c * (b + 1) + r * (3 - b)) % 256);
  return px;
}

// The pixels of an encoded image, decoded by GDAL, with its driver's name.
std::pair<std::string, std::vector<uint8_t>> decode(const std::vector<uint8_t>& bytes, int& width,
                                                    int& height, int& bands) {
  const std::string path = "/vsimem/image_file_test";
  VSIFCloseL(
      VSIFileFromMemBuffer(path.c_str(), const_cast<GByte*>(bytes.data()), bytes.size(), FALSE));
  const GDALDatasetUniquePtr ds(GDALDataset::Open(path.c_str(), GDAL_OF_RASTER));
  EXPECT_TRUE(ds);
  if (!ds) return {};
  width = ds->GetRasterXSize();
  height = ds->GetRasterYSize();
  bands = ds->GetRasterCount();
  std::vector<uint8_t> px(size_t(width) * size_t(height) * size_t(bands));
  EXPECT_EQ(ds->RasterIO(GF_Read, 0, 0, width, height, px.data(), width, height, GDT_Byte, bands,
                         nullptr, bands, GSpacing(bands) * width, 1, nullptr),
            CE_None);
  const std::string driver = ds->GetDriver()->GetDescription();
  VSIUnlink(path.c_str());
  return {driver, px};
}

TEST(ImageFile, PngKeepsEveryPixelOfGreyAndRgba) {
  init_gdal();
  for (int bands : {1, 4}) {
    const std::vector<uint8_t> in = picture(40, 24, bands);
    int w = 0, h = 0, n = 0;
    const auto [driver, out] = decode(encode_image(in, 40, 24, bands, {"PNG", {}}), w, h, n);
    EXPECT_EQ(driver, "PNG");
    EXPECT_EQ(w, 40);
    EXPECT_EQ(h, 24);
    EXPECT_EQ(n, bands);
    EXPECT_EQ(out, in) << bands << " bands";
  }
}

TEST(ImageFile, JpegIsCloseToTheRgbPicture) {
  init_gdal();
  const std::vector<uint8_t> in = picture(64, 48, 3);
  int w = 0, h = 0, n = 0;
  const auto [driver, out] = decode(encode_image(in, 64, 48, 3, {"JPEG", {"QUALITY=90"}}), w, h, n);
  EXPECT_EQ(driver, "JPEG");
  ASSERT_EQ(out.size(), in.size());
  // Channels in RGB order (a swap would differ by ~100 on this picture), within JPEG's loss.
  double sum = 0;
  for (size_t i = 0; i < in.size(); ++i) sum += std::abs(int(out[i]) - int(in[i]));
  EXPECT_LT(sum / double(in.size()), 4.0);
}

TEST(ImageFile, FileOnDiskAndErrors) {
  const std::string dir =
      std::filesystem::temp_directory_path() / ("image_file_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::vector<uint8_t> in = picture(8, 8, 1);
  write_image(in, 8, 8, 1, {"PNG", {}}, dir + "/a.png");
  EXPECT_GT(std::filesystem::file_size(dir + "/a.png"), 8u);
  EXPECT_THROW(write_image(in, 8, 9, 1, {"PNG", {}}, dir + "/b.png"), Error);  // wrong size
  EXPECT_THROW(write_image(in, 8, 8, 1, {"NOSUCH", {}}, dir + "/c.png"), Error);
  EXPECT_THROW(write_image(in, 8, 8, 1, {"PNG", {}}, dir + "/missing/d.png"), Error);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace maquette
