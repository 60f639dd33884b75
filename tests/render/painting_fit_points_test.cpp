// The painting's control points file (formats/render/painting_fit_points.h): a file read back as
// written, and every kind of bad input refused with the file, the field and the value named.
#include "render/painting_fit_points.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/error.h"

namespace maquette {
namespace {

const char* kGood = R"({"width": 400, "height": 300, "points": [
  {"name": "summit", "x": 10.5, "y": 20, "lon": 7.5, "lat": 46.25, "height": 2100.5},
  {"x": 400, "y": 0, "lon": -180, "lat": 90},
  {"x": 0, "y": 300, "lon": 180, "lat": -90},
  {"x": 200, "y": 150, "lon": 0, "lat": 0, "height": -30}]})";

TEST(PaintingPoints, ReadsTheFile) {
  const auto path = std::filesystem::temp_directory_path() / "painting_points_test.json";
  std::ofstream(path) << kGood;
  const PaintingPoints p = read_painting_points(path.string());
  std::filesystem::remove(path);
  EXPECT_EQ(p.width, 400);
  EXPECT_EQ(p.height, 300);
  ASSERT_EQ(p.points.size(), 4u);
  EXPECT_EQ(p.points[0].name, "points[0] (summit)");
  EXPECT_EQ(p.points[0].x, 10.5);
  EXPECT_EQ(p.points[0].y, 20);
  EXPECT_EQ(p.points[0].lon, 7.5);
  EXPECT_EQ(p.points[0].lat, 46.25);
  EXPECT_EQ(p.points[0].height, 2100.5);
  EXPECT_EQ(p.points[1].name, "points[1]");
  EXPECT_FALSE(p.points[1].height);
  EXPECT_EQ(p.points[3].height, -30);
}

void expect_error(const std::string& text, const std::string& message) {
  try {
    parse_painting_points(text, "clicks.json");
    ADD_FAILURE() << "accepted: " << text;
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), message);
  }
}

std::string with(const std::string& from, const std::string& to) {
  std::string text = kGood;
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

TEST(PaintingPoints, BadInputIsNamed) {
  EXPECT_THROW(read_painting_points("/nonexistent/clicks.json"), Error);
  try {
    parse_painting_points("{\"width\": ", "clicks.json");
    ADD_FAILURE();
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()).rfind("clicks.json: parse error at line 1, column 11", 0), 0u)
        << e.what();
  }
  // Quoting a value nested a million deep overflowed the stack (fuzz/corpus/control_points).
  const std::string deep = std::string(1000000, '[') + std::string(1000000, ']');
  try {
    parse_painting_points(with("\"lat\": 46.25", "\"lat\": " + deep), "clicks.json");
    ADD_FAILURE() << "accepted a latitude nested a million deep";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("points[0].lat[0][0]"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("nested deeper than 128 levels"), std::string::npos);
  }
  expect_error("[1]", "clicks.json: the top level is not an object");
  expect_error(with("\"width\": 400", "\"width\": 0"),
               "clicks.json: width 0 is outside [1, 65536]");
  expect_error(with("\"height\": 300", "\"height\": 300.5"),
               "clicks.json: height 300.5 is not a whole number of pixels");
  expect_error(with("\"width\": 400", "\"width\": \"400\""),
               "clicks.json: width \"400\" is not a finite number");
  expect_error(with("\"x\": 10.5", "\"x\": 400.5"),
               "clicks.json: points[0] (summit).x 400.5 is outside [0, 400]");
  expect_error(with("\"lat\": 90", "\"lat\": 91"),
               "clicks.json: points[1].lat 91 is outside [-90, 90]");
  expect_error(with("\"lon\": 0,", "\"lon\": -181,"),
               "clicks.json: points[3].lon -181 is outside [-180, 180]");
  expect_error(with("\"lon\": 0,", ""), "clicks.json: points[3].lon is missing");
  expect_error(with("\"height\": -30", "\"height\": null"),
               "clicks.json: points[3].height null is not a finite number");
  expect_error(with("\"name\": \"summit\"", "\"name\": 3"),
               "clicks.json: points[0].name 3 is not a string");
  expect_error(R"({"width": 4, "height": 3, "points": {}})", "clicks.json: points is not an array");
  expect_error(R"({"width": 4, "height": 3})", "clicks.json: points is missing");
  expect_error(R"({"width": 4, "height": 3, "points": [{"x": 1, "y": 1, "lon": 0, "lat": 0}]})",
               "clicks.json: points has 1 points: the camera needs at least 4");
  expect_error(R"({"width": 4, "height": 3, "points": [5]})",
               "clicks.json: points[0] 5 is not an object");
  // A misspelt field was ignored: the point took the DEM's height, the file its default.
  expect_error(with("\"height\": 2100.5", "\"heigth\": 2100.5"),
               "clicks.json: points[0] (summit) has an unknown field \"heigth\" (expected: x, y, "
               "lon, lat, height, name)");
  expect_error(with("\"width\": 400", "\"width\": 400, \"crs\": \"EPSG:4326\""),
               "clicks.json: the top level has an unknown field \"crs\" (expected: width, height, "
               "points)");
}

}  // namespace
}  // namespace maquette
