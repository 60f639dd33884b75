// synthesis.transfer's params refused where they would be read wrong: a painting too small for
// its exemplar_scale (its blocks would read past the image), one half of the altitude guide
// without the other (it would be dropped without a word).
#include "../transfer_params.h"

#include <gdal_priv.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "../synthesis.h"
#include "../transfer_exemplar.h"
#include "core/error.h"
#include "run_cli.h"

namespace maquette::synthesis {
namespace {

// A `size` x `size` RGB PNG of a grey ramp, written by GDAL.
std::string painting_png(int size) {
  GDALAllRegister();
  const std::string path = test::temp_dir() + "/painting.png";
  std::unique_ptr<GDALDataset> mem(
      GetGDALDriverManager()->GetDriverByName("MEM")->Create("", size, size, 3, GDT_Byte, nullptr));
  std::vector<uint8_t> ramp(size_t(size) * size_t(size));
  for (size_t i = 0; i < ramp.size(); ++i) ramp[i] = uint8_t(i * 7);
  for (int b = 1; b <= 3; ++b)
    EXPECT_EQ(mem->GetRasterBand(b)->RasterIO(GF_Write, 0, 0, size, size, ramp.data(), size, size,
                                              GDT_Byte, 0, 0),
              CE_None);
  GDALClose(GetGDALDriverManager()->GetDriverByName("PNG")->CreateCopy(
      path.c_str(), mem.get(), false, nullptr, nullptr, nullptr));
  return path;
}

nlohmann::json params(const std::string& painting, int scale) {
  return {{"painting", painting},
          {"classes", 2},
          {"exclude_classes", nlohmann::json::array()},
          {"exemplar_scale", scale},
          {"k", 2}};
}

TEST(TransferParams, PaintingSmallerThanItsScaleNeedsIsNamed) {
  const std::string png = painting_png(3);
  try {
    transfer_exemplar(params(png, 4));
    FAIL() << "a 3 x 3 painting at exemplar_scale 4 was accepted";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(png), std::string::npos) << what;
    EXPECT_NE(what.find("3 x 3"), std::string::npos) << what;
    EXPECT_NE(what.find("exemplar_scale 4"), std::string::npos) << what;
  }
  // The least size the levels need is accepted.
  const int least = 1 << (kLevels - 1);
  EXPECT_EQ(transfer_exemplar(params(painting_png(least), 1))->pyramid.levels.size(),
            size_t(kLevels));
}

TEST(TransferParams, AltitudeGuideNeedsBothHalves) {
  const nlohmann::json with_range = {{"altitude_range", {1000, 2600}}};
  EXPECT_EQ(altitude_range(nlohmann::json::object(), "op", false), std::nullopt);
  EXPECT_EQ(*altitude_range(with_range, "op", true), (std::array<double, 2>{1000, 2600}));
  const auto refused = [](const nlohmann::json& p, bool dem, const std::string& message) {
    try {
      altitude_range(p, "synthesis.transfer", dem);
      ADD_FAILURE() << "accepted: " << p.dump() << " dem " << dem;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
  };
  refused(with_range, false, "synthesis.transfer.altitude_range is given without inputs.dem");
  refused(nlohmann::json::object(), true, "synthesis.transfer: inputs.dem is given without");
}

}  // namespace
}  // namespace maquette::synthesis
