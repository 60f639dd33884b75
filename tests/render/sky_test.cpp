// The sky's colours (render/sky.h) against the tests' own pinhole (test_camera.h): the elevation
// of each pixel's ray graded from the haze at the horizon to the zenith's blue 30 degrees up; and
// a row drawn by runs against its colour computed at every pixel.
#include "render/sky.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <numbers>
#include <vector>

#include "test_camera.h"

namespace maquette {
namespace {

struct Case {
  double heading, pitch, fov;
  int width, height;
};

TEST(Sky, RowsByRunsAreTheGradientOfEachPixelsElevation) {
  for (const Case& c :
       {Case{30, -10, 60, 801, 300}, Case{200, 0, 90, 640, 480}, Case{-75, 25, 120, 500, 500},
        Case{10, -89, 40, 300, 201}, Case{0, 80, 170, 1000, 200}}) {
    CameraSpec spec;
    spec.eye = {-113, 37, 2000};
    spec.heading = c.heading;
    spec.pitch = c.pitch;
    spec.fov = c.fov;
    spec.width = c.width;
    spec.height = c.height;
    const PinholeCamera camera(spec);
    test::TestCamera own;
    own.heading = c.heading;
    own.pitch = c.pitch;
    own.fov = c.fov;
    own.width = c.width;
    own.height = c.height;
    std::vector<uint8_t> row(3 * size_t(c.width));
    size_t pixels = 0, same = 0, off_by_more = 0, not_per_pixel = 0;
    for (int r = 0; r < c.height; ++r) {
      sky_row(camera, r, row.data());
      for (int col = 0; col < c.width; ++col) {
        const auto per_pixel = sky_colour(camera, col + 0.5, r + 0.5);
        const auto ray = own.ray(col, r);
        const double elevation = std::atan2(ray[2], std::hypot(ray[0], ray[1]));
        const double t = std::clamp(elevation / (std::numbers::pi / 6), 0.0, 1.0);
        bool equal = true;
        for (size_t k = 0; k < 3; ++k) {
          const uint8_t got = row[3 * size_t(col) + k];
          not_per_pixel += got != per_pixel[k];
          const double want = kHazeColour[k] + (kZenithColour[k] - kHazeColour[k]) * t;
          off_by_more += std::abs(got - want) > 0.5 + 1e-9;
          equal = equal && got == uint8_t(std::lround(want));
        }
        same += equal;
        ++pixels;
      }
    }
    EXPECT_EQ(not_per_pixel, 0u) << "heading " << c.heading << " pitch " << c.pitch;
    // The two pinholes differ in the last bits: a colour on a rounding boundary may differ by 1.
    EXPECT_EQ(off_by_more, 0u) << "heading " << c.heading << " pitch " << c.pitch;
    EXPECT_GE(double(same), 0.999 * double(pixels)) << "heading " << c.heading;
  }
}

}  // namespace
}  // namespace maquette
