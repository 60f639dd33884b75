// The painting's segmentation by colour on a tiny analytic case: its majority filter; a class
// image drawn as polygons, against the pixel centres' classes worked out by hand (a class written
// as text named by its feature); masks of one 8-bit band only; paintings with transparency, a
// palette or 16 bits read as a viewer shows them; a file GDAL cannot read named with GDAL's reason.
#include "../painting.h"

#include <gdal_priv.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/error.h"
#include "logged_warnings.h"
#include "run_cli.h"
#include "synthetic_raster.h"

namespace maquette::synthesis {
namespace {

TEST(SegmentByColour, SpeckleJoinsTheClassAroundIt) {
  // Left half red, right half blue; single blue pixels inside the red half, every 6 pixels.
  Exemplar e;
  e.width = e.height = 32;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) {
      const bool blue = x >= 16 || (x % 6 == 3 && y % 6 == 3);
      e.rgb.insert(e.rgb.end(), blue ? std::initializer_list<float>{20, 30, 220}
                                     : std::initializer_list<float>{220, 30, 20});
    }
  const auto labels = segment_by_colour(e, 2);
  const uint8_t red = labels[0], blue = labels[31];
  ASSERT_NE(red, blue);
  size_t wrong = 0;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) wrong += labels[size_t(y * 32 + x)] != (x < 16 ? red : blue);
  EXPECT_EQ(wrong, 0u);
}

// A GeoJSON file of `features` (each a Feature's text) in a fresh directory.
std::string geojson(const std::string& features) {
  const std::string path = test::temp_dir() + "/classes.geojson";
  std::ofstream(path) << R"({"type": "FeatureCollection", "features": [)" << features << "]}";
  return path;
}

std::string polygon(const std::string& properties, const std::string& ring) {
  return R"({"type": "Feature", "properties": )" + properties +
         R"(, "geometry": {"type": "Polygon", "coordinates": [)" + ring + "]}}";
}

TEST(ReadClassImage, PolygonsTakeThePixelsWhoseCentreTheyHoldTheLaterOverTheEarlier) {
  // 8 x 6 painting pixels: class 3 over all of it, then class 7 over the rectangle x 2..5, y
  // 1..4 (pixel edges), then class 1 over the triangle (0, 1.5), (4.5, 6), (0, 6): below its
  // slanted edge y = x + 1.5, so pixel (x, y), centre (x + 0.5, y + 0.5), when y >= x + 2 (no
  // centre lies on an edge).
  const std::string path =
      geojson(polygon(R"({"class": 3})", "[[0, 0], [8, 0], [8, 6], [0, 6], [0, 0]]") + "," +
              polygon(R"({"class": 7})", "[[2, 1], [5, 1], [5, 4], [2, 4], [2, 1]]") + "," +
              polygon(R"({"class": 1})", "[[0, 1.5], [4.5, 6], [0, 6], [0, 1.5]]"));
  const auto labels = read_class_image(path, 8, 6);
  ASSERT_EQ(labels.size(), 48u);
  for (int y = 0; y < 6; ++y)
    for (int x = 0; x < 8; ++x) {
      const int expected = y >= x + 2 ? 1 : x >= 2 && x < 5 && y >= 1 && y < 4 ? 7 : 3;
      EXPECT_EQ(labels[size_t(y * 8 + x)], expected) << "pixel " << x << ", " << y;
    }
}

TEST(ReadClassImage, RefusesUncoveredPixelsAndClassesOutOfRange) {
  const auto message = [](const std::string& path) {
    try {
      read_class_image(path, 8, 6);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  // Column 7 in no polygon: 6 pixels.
  EXPECT_NE(message(geojson(polygon(R"({"class": 3})", "[[0, 0], [7, 0], [7, 6], [0, 6], [0, 0]]")))
                .find("6 painting pixels lie in no polygon"),
            std::string::npos);
  EXPECT_NE(
      message(geojson(polygon(R"({"class": 255})", "[[0, 0], [8, 0], [8, 6], [0, 6], [0, 0]]")))
          .find("class '255' is not an integer in 0..254"),
      std::string::npos);
  EXPECT_NE(
      message(geojson(polygon(R"({"name": "sky"})", "[[0, 0], [8, 0], [8, 6], [0, 6], [0, 0]]")))
          .find("no attribute \"class\""),
      std::string::npos);
  // One class in quotes makes the attribute a String for every feature (GDAL would read "7a" as
  // 7, "forest" as 0): the feature written in quotes is refused, naming its value and the type,
  // not the first one, whose 2 is a number in the file.
  EXPECT_NE(
      message(geojson(polygon(R"({"class": 2})", "[[0, 0], [8, 0], [8, 6], [0, 6], [0, 0]]") +
                      ", " +
                      polygon(R"({"class": "7a"})", "[[0, 0], [4, 0], [4, 6], [0, 6], [0, 0]]")))
          .find("feature 1's class '7a' is written as text (the attribute \"class\" is of type "
                "String"),
      std::string::npos);
  // A number in quotes among numbers (the bad-input report's file: feature 1 of 3).
  const std::string quoted = message(
      geojson(polygon(R"({"class": 0})", "[[0, 0], [8, 0], [8, 6], [0, 6], [0, 0]]") + ", " +
              polygon(R"({"class": "3"})", "[[0, 0], [4, 0], [4, 6], [0, 6], [0, 0]]") + ", " +
              polygon(R"({"class": 8})", "[[0, 0], [2, 0], [2, 6], [0, 6], [0, 0]]")));
  EXPECT_NE(quoted.find("classes.geojson: feature 1's class '3' is written as text"),
            std::string::npos)
      << quoted;
  // Among text, a value that is no number at all: named as such, not as text.
  const std::string listed = message(
      geojson(polygon(R"({"class": [2]})", "[[0, 0], [8, 0], [8, 6], [0, 6], [0, 0]]") + ", " +
              polygon(R"({"class": "3"})", "[[0, 0], [4, 0], [4, 6], [0, 6], [0, 0]]")));
  EXPECT_NE(listed.find("feature 0's class '[2]' is not an integer in 0..254"), std::string::npos)
      << listed;
  EXPECT_NE(message(geojson(polygon(R"({"class": "forest"})",
                                    "[[0, 0], [8, 0], [8, 6], [0, 6], [0, 0]]")))
                .find("class 'forest' is written as text"),
            std::string::npos);
  // A line drawn by mistake: GDAL would burn its path.
  EXPECT_NE(message(geojson(polygon(R"({"class": 2})", "[[0, 0], [8, 0], [8, 6], [0, 6], [0, 0]]") +
                            R"(, {"type": "Feature", "properties": {"class": 3}, "geometry": )"
                            R"({"type": "LineString", "coordinates": [[0, 0], [8, 6]]}})"))
                .find("feature 1 is a LINESTRING, not a polygon"),
            std::string::npos);
}

// A class image, an exclusion mask or an altitude is one 8-bit band: read as bytes, a float 0..1
// altitude would be 0 or 1, 16-bit classes 255, and of an RGB image its red band alone. Refused,
// naming the file and its type or bands.
TEST(ReadMask, OnlyOneByteBandIsRead) {
  const std::string dir = test::temp_dir();
  const auto message = [](const auto& read) {
    try {
      read();
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const auto raster = [&](const std::string& name, const std::string& type, int bands) {
    test::RasterSpec spec;
    spec.width = 8, spec.height = 6, spec.bands = bands, spec.type = type;
    spec.geotransform = {0, 1, 0, 0, 0, 1};
    test::write_raster(dir + "/" + name, spec, [](int, double x, double) { return x / 8; });
    return dir + "/" + name;
  };
  const std::string altitude = raster("altitude.tif", "Float32", 1);
  EXPECT_EQ(message([&] { read_mask(altitude, 8, 6, "altitude image"); }),
            altitude +
                ": the altitude image is Float32: it must be one 8-bit band (Byte, "
                "values 0..255)");
  const std::string classes = raster("classes.tif", "UInt16", 1);
  EXPECT_EQ(message([&] { read_class_image(classes, 8, 6); }),
            classes +
                ": the class image is UInt16: it must be one 8-bit band (Byte, values "
                "0..255)");
  const std::string rgb = test::write_png(dir + "/rgb.png", 8, 6, 3,
                                          [](int x, int, int band) { return 40 * band + x; });
  EXPECT_EQ(message([&] { read_mask(rgb, 8, 6, "exclusion mask"); }),
            rgb +
                ": the exclusion mask has 3 bands: it must be one 8-bit band (grey, not RGB "
                "or with alpha)");
  EXPECT_EQ(message([&] { read_class_image(rgb, 8, 6); }),
            rgb +
                ": the class image has 3 bands: it must be one 8-bit band (grey, not RGB or "
                "with alpha)");
  const std::string grey =
      test::write_png(dir + "/grey.png", 8, 6, 1, [](int x, int y, int) { return x + 10 * y; });
  const auto bytes = read_mask(grey, 8, 6, "exclusion mask");
  ASSERT_EQ(bytes.size(), 48u);
  EXPECT_EQ(bytes[13], 15);  // (5, 1)
}

// The message of read_painting's error on `path`, or "no error".
std::string painting_error(const std::string& path) {
  try {
    read_painting(path);
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

TEST(ReadPainting, TransparentPixelsAreExcludedTheirColoursKept) {
  // RGBA and grey + alpha, 8 x 6: transparent (alpha 0) left of column 3 and at pixel (6, 4),
  // half transparent (alpha 128: still the painting) at (5, 1).
  const auto alpha = [](int x, int y) {
    return x < 3 || (x == 6 && y == 4) ? 0 : x == 5 && y == 1 ? 128 : 255;
  };
  const std::string dir = test::temp_dir();
  for (const int bands : {4, 2}) {
    const std::string path = test::write_png(
        dir + "/alpha" + std::to_string(bands) + ".png", 8, 6, bands, [&](int x, int y, int b) {
          return b == bands - 1 ? alpha(x, y) : 25 * x + 6 * y + 11 * b;
        });
    const Exemplar e = read_painting(path);
    ASSERT_EQ(e.excluded.size(), 48u);
    for (int y = 0; y < 6; ++y)
      for (int x = 0; x < 8; ++x) {
        const size_t i = size_t(y * 8 + x);
        EXPECT_EQ(e.excluded[i], alpha(x, y) == 0) << bands << " bands, pixel " << x << ", " << y;
        for (int c = 0; c < 3; ++c)
          EXPECT_EQ(e.rgb[3 * i + size_t(c)], 25 * x + 6 * y + (bands == 4 ? 11 * c : 0));
      }
  }
}

TEST(ReadPainting, APaletteImageIsItsTablesColours) {
  // Indices (x + 2 y) mod 13 through the table entry i = (10 i, 20 i, 15 i) (synthetic_raster.h).
  const std::string path = test::temp_dir() + "/palette.tif";
  test::RasterSpec spec;
  spec.width = 8;
  spec.height = 6;
  spec.type = "Byte";
  spec.geotransform = {0, 1, 0, 0, 0, 1};
  spec.colour_table = true;
  test::write_raster(path, spec,
                     [](int, double x, double y) { return double((int(x) + 2 * int(y)) % 13); });
  const Exemplar e = read_painting(path);
  for (int y = 0; y < 6; ++y)
    for (int x = 0; x < 8; ++x) {
      const size_t i = size_t(y * 8 + x);
      const int index = (x + 2 * y) % 13;
      EXPECT_EQ(e.rgb[3 * i], 10 * index);
      EXPECT_EQ(e.rgb[3 * i + 1], 20 * index);
      EXPECT_EQ(e.rgb[3 * i + 2], 15 * index);
      EXPECT_EQ(e.excluded[i], 0);
    }
}

TEST(ReadPainting, AnExifOrientationIsReadAsStoredAndSaid) {
  // A JPEG turned by its EXIF orientation 6 (a viewer shows it 90 degrees clockwise), and one of
  // orientation 1.
  GDALAllRegister();  // run alone (ctest runs each test in its own process): no driver yet
  const std::string dir = test::temp_dir();
  const auto jpeg = [&](const char* orientation) {
    std::unique_ptr<GDALDataset> mem(
        GetGDALDriverManager()->GetDriverByName("MEM")->Create("", 16, 8, 3, GDT_Byte, nullptr));
    mem->SetMetadataItem("EXIF_Orientation", orientation);
    const std::string path = dir + "/turned" + orientation + ".jpg";
    GDALClose(GetGDALDriverManager()->GetDriverByName("JPEG")->CreateCopy(
        path.c_str(), mem.get(), false, nullptr, nullptr, nullptr));
    return path;
  };
  const std::string turned = jpeg("6"), upright = jpeg("1");
  const Warnings warnings;
  const Exemplar e = read_painting(turned);
  EXPECT_EQ(e.width, 16);  // as stored
  EXPECT_NE(warnings.text.str().find(turned + ": EXIF orientation 6: the painting is read as "
                                              "stored, not turned as a viewer shows it"),
            std::string::npos)
      << warnings.text.str();
  const auto before = warnings.text.str().size();
  read_painting(upright);
  EXPECT_EQ(warnings.text.str().size(), before) << warnings.text.str();
}

TEST(ReadPainting, SixteenBitsSpanTheirRangeOtherTypesAreNamed) {
  const std::string dir = test::temp_dir();
  test::RasterSpec spec;
  spec.width = 8;
  spec.height = 6;
  spec.bands = 3;
  spec.type = "UInt16";
  spec.geotransform = {0, 1, 0, 0, 0, 1};
  // Band b's pixel: 257 (8-bit value 30 x + 7 y + b) + 128, so 16-bit white is 255.
  const auto value = [](int b, double x, double y) {
    return 257.0 * (30 * int(x) + 7 * int(y) + b) + 128;
  };
  test::write_raster(dir + "/sixteen.tif", spec, value);
  const Exemplar e = read_painting(dir + "/sixteen.tif");
  for (int y = 0; y < 6; ++y)
    for (int x = 0; x < 8; ++x)
      for (int b = 1; b <= 3; ++b)
        EXPECT_FLOAT_EQ(e.rgb[3 * size_t(y * 8 + x) + size_t(b - 1)],
                        float(value(b, x + 0.5, y + 0.5) / 257));
  spec.type = "Float32";
  test::write_raster(dir + "/float.tif", spec, value);
  EXPECT_NE(
      painting_error(dir + "/float.tif")
          .find("/float.tif: the painting's band 1 is Float32: a painting is 8-bit or 16-bit"),
      std::string::npos);
}

// A painting cut short, or not an image at all: GDAL's reason in the one error, GDAL's own lines
// not printed besides (they were, three of them, before the error).
TEST(ReadPainting, AFileGdalCannotReadIsNamedWithItsReasonAndNothingElsePrinted) {
  const std::string dir = test::temp_dir();
  const std::string whole = test::write_png(dir + "/whole.png", 96, 96, 3, [](int x, int y, int b) {
    return int((uint32_t(x * 7919 + y * 104729 + b * 1299709) * 2654435761u) >> 24);
  });
  const auto size = std::filesystem::file_size(whole);
  const std::string cut = dir + "/cut.png";
  std::filesystem::copy_file(whole, cut);
  std::filesystem::resize_file(cut, size / 2);
  const std::string text = dir + "/text.png";
  std::ofstream(text) << "not an image\n";

  testing::internal::CaptureStderr();
  const std::string cut_error = painting_error(cut);
  const std::string text_error = painting_error(text);
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
  EXPECT_THAT(cut_error, testing::StartsWith(cut + ": GDAL cannot read the painting's pixels: "));
  EXPECT_THAT(cut_error, testing::HasSubstr("libpng"));
  EXPECT_THAT(text_error, testing::StartsWith(text + ": GDAL cannot open the painting: "));
  EXPECT_THAT(text_error, testing::HasSubstr("not recognized as"));
  EXPECT_EQ(painting_error(whole), "no error");
}

}  // namespace
}  // namespace maquette::synthesis
