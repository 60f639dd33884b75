#include "test_png.h"

#include <gdal_priv.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

namespace maquette::test {

std::string write_png(const std::string& path, int width, int height, int bands,
                      const std::function<double(int x, int y, int band)>& value) {
  GDALAllRegister();
  std::unique_ptr<GDALDataset> mem(GetGDALDriverManager()->GetDriverByName("MEM")->Create(
      "", width, height, bands, GDT_Byte, nullptr));
  std::vector<uint8_t> band(size_t(width) * size_t(height));
  for (int b = 0; b < bands; ++b) {
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x)
        band[size_t(y) * size_t(width) + size_t(x)] =
            uint8_t(std::clamp(std::lround(value(x, y, b)), 0L, 255L));
    EXPECT_EQ(mem->GetRasterBand(b + 1)->RasterIO(GF_Write, 0, 0, width, height, band.data(), width,
                                                  height, GDT_Byte, 0, 0),
              CE_None);
  }
  GDALClose(GetGDALDriverManager()->GetDriverByName("PNG")->CreateCopy(
      path.c_str(), mem.get(), false, nullptr, nullptr, nullptr));
  return path;
}

}  // namespace maquette::test
