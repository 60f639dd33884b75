// The painting's segmentation by colour on a tiny analytic case: its majority filter.
#include "../painting.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace maquette::synthesis
