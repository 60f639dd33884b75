// A plant's colour from the orthophoto (vegetation_plant.h): the mean of the 3 x 3 pixels around
// it, by hand; a plant rounding to a pixel just beyond the tile (on its edge) takes the nearest
// pixel's neighbourhood, never reading beyond the one-pixel halo.
#include "../vegetation_plant.h"

#include <gtest/gtest.h>

namespace maquette::structures {
namespace {

// A 4 x 4 RGB tile with a halo of 1: red 10 x col + row (halo included), green 100, blue 0.
Tile<float> tile() {
  Tile<float> t(4, 3, 1);
  for (int r = -1; r <= 4; ++r)
    for (int c = -1; c <= 4; ++c) {
      t.at(c, r, 0) = float(10 * c + r + 20);
      t.at(c, r, 1) = 100;
      t.at(c, r, 2) = 0;
    }
  return t;
}

TEST(VegetationPlantColour, MeanOfTheThreeByThreePixels) {
  // Around (1, 2): red 10 x (0 + 1 + 2) / 3 + (1 + 2 + 3) / 3 + 20 = 32.
  EXPECT_EQ(neighbourhood_colour(tile(), 1, 2), 0xff000000u | (100u << 8) | 32u);
}

TEST(VegetationPlantColour, BeyondTheTileIsTheNearestPixel) {
  const Tile<float> t = tile();
  EXPECT_EQ(neighbourhood_colour(t, -1, 2), neighbourhood_colour(t, 0, 2));
  EXPECT_EQ(neighbourhood_colour(t, 4, 4), neighbourhood_colour(t, 3, 3));
  EXPECT_EQ(neighbourhood_colour(t, 2, -1), neighbourhood_colour(t, 2, 0));
}

}  // namespace
}  // namespace maquette::structures
