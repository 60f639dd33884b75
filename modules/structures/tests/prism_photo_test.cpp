// The photo's EXIF as GDAL's JPEG driver writes and reads it: the 35 mm-equivalent focal length
// scaled by the diagonal, and a turned photo refused.
#include "../prism_photo.h"

#include <gdal_priv.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/error.h"

namespace maquette::structures {
namespace {

// A 64 x 48 RGB JPEG with the EXIF items given.
std::string jpeg_with_exif(const std::string& name,
                           const std::vector<std::pair<std::string, std::string>>& exif) {
  GDALAllRegister();
  const std::string path = (std::filesystem::temp_directory_path() / name).string();
  std::unique_ptr<GDALDataset> mem(
      GetGDALDriverManager()->GetDriverByName("MEM")->Create("", 64, 48, 3, GDT_Byte, nullptr));
  for (int b = 1; b <= 3; ++b) mem->GetRasterBand(b)->Fill(40 * b);
  for (const auto& [key, value] : exif) mem->SetMetadataItem(key.c_str(), value.c_str());
  std::unique_ptr<GDALDataset> jpeg(GetGDALDriverManager()->GetDriverByName("JPEG")->CreateCopy(
      path.c_str(), mem.get(), false, nullptr, nullptr, nullptr));
  EXPECT_TRUE(jpeg);
  return path;
}

TEST(PrismPhoto, FocalLengthIn35mmScalesByTheDiagonal) {
  const Photo photo = read_photo(jpeg_with_exif(
      "maquette_exif_f35.jpg", {{"EXIF_FocalLengthIn35mmFilm", "28"}, {"EXIF_Orientation", "1"}}));
  ASSERT_TRUE(photo.focal_px);
  // 28 mm on a full frame's 43.27 mm diagonal, on the photo's 80-pixel diagonal.
  EXPECT_NEAR(*photo.focal_px, 28 * 80 / std::hypot(36, 24), 1e-9);
  EXPECT_FALSE(read_photo(jpeg_with_exif("maquette_exif_none.jpg", {})).focal_px);
}

TEST(PrismPhoto, TurnedPhotoIsRefusedNamingItsOrientation) {
  const std::string path = jpeg_with_exif("maquette_exif_turned.jpg", {{"EXIF_Orientation", "6"}});
  try {
    read_photo(path);
    ADD_FAILURE() << "a photo tagged EXIF_Orientation 6 was read";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(path + ": EXIF_Orientation 6: the photo is shown turned"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace maquette::structures
