// The painting's segmentation by colour on a tiny analytic case: its majority filter; a class
// image drawn as polygons, against the pixel centres' classes worked out by hand.
#include "../painting.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "core/error.h"
#include "run_cli.h"

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
  // 7, "forest" as 0): the first feature's 2 is refused, naming the type.
  EXPECT_NE(
      message(geojson(polygon(R"({"class": 2})", "[[0, 0], [8, 0], [8, 6], [0, 6], [0, 0]]") +
                      ", " +
                      polygon(R"({"class": "7a"})", "[[0, 0], [4, 0], [4, 6], [0, 6], [0, 0]]")))
          .find("feature 0's class '2' is written as text (the attribute \"class\" is of type "
                "String"),
      std::string::npos);
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

}  // namespace
}  // namespace maquette::synthesis
