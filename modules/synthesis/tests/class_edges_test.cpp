// The exemplar's class edges (class_edges.h) on a hand-built level whose places are worked out
// here: three bands of columns, labels 0, 1 and 2, ten columns each; kClassEdgeReach is 8, so a
// band's places beside its neighbour are its 8 columns nearest it, and none beside the band two
// away. An excluded pixel is neither listed nor a neighbour.
#include "../class_edges.h"

#include <gtest/gtest.h>

#include <vector>

namespace maquette::synthesis {
namespace {

constexpr int kWidth = 30, kHeight = 5;

ExemplarLevel three_bands() {
  ExemplarLevel e;
  e.width = kWidth;
  e.height = kHeight;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) e.labels.push_back(uint8_t(x / 10));
  e.excluded.assign(e.labels.size(), 0);
  // Label 2's pixel in the first band, and one of band 1's: excluded.
  e.labels[size_t(e.index(0, 2))] = 2;
  e.excluded[size_t(e.index(0, 2))] = 1;
  e.excluded[size_t(e.index(15, 4))] = 1;
  for (int32_t i = 0; i < kWidth * kHeight; ++i)
    if (!e.excluded[size_t(i)]) e.allowed.push_back(i);
  return e;
}

// The pixels of columns [x0, x1) of every row, ascending, but (15, 4).
std::vector<int32_t> columns(int x0, int x1) {
  std::vector<int32_t> pixels;
  for (int y = 0; y < kHeight; ++y)
    for (int x = x0; x < x1; ++x)
      if (x != 15 || y != 4) pixels.push_back(y * kWidth + x);
  return pixels;
}

std::vector<int32_t> run_pixels(const std::vector<uint64_t>& places, uint8_t a, uint8_t b) {
  std::vector<int32_t> pixels;
  for (const uint64_t entry : class_edge_run(places, a, b)) {
    EXPECT_EQ(entry >> 40, a);
    EXPECT_EQ((entry >> 32) & 0xff, b);
    pixels.push_back(class_edge_pixel(entry));
  }
  return pixels;
}

TEST(ClassEdges, EachBandsPlacesBesideItsNeighbourAreItsColumnsWithinReach) {
  const ExemplarLevel e = three_bands();
  const std::vector<uint64_t> places = class_edge_places(e);
  EXPECT_EQ(run_pixels(places, 0, 1), columns(10 - kClassEdgeReach, 10));
  EXPECT_EQ(run_pixels(places, 1, 0), columns(10, 10 + kClassEdgeReach));
  EXPECT_EQ(run_pixels(places, 1, 2), columns(20 - kClassEdgeReach, 20));
  EXPECT_EQ(run_pixels(places, 2, 1), columns(20, 20 + kClassEdgeReach));
  EXPECT_TRUE(run_pixels(places, 0, 2).empty());  // the excluded label 2 pixel is no neighbour
  EXPECT_TRUE(run_pixels(places, 2, 0).empty());
  EXPECT_TRUE(run_pixels(places, 0, 0).empty());
  EXPECT_TRUE(run_pixels(places, 3, 1).empty());
  EXPECT_EQ(places.size(), 4 * columns(0, 8).size() - 2);  // (15, 4) is in two runs
}

}  // namespace
}  // namespace maquette::synthesis
