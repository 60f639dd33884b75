// The skyline as a coherence break (synthesis.h): a sky pixel beside the land is not matched
// across the depth break, so it is not drawn to the painting's sky beside the painting's land
// (the grey halo along the skyline of the Zion panorama painted from Bruegel, session 21).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "../pixel_hash.h"
#include "../synthesis.h"
#include "painted_exemplar.h"

namespace maquette::synthesis {
namespace {

constexpr int kSide = 128, kSkyRows = 64, kHazeRows = 4;

// Sky (class 0) over land (class 1): a cream sky whose bottom kHazeRows rows, along the
// painting's horizon, are grey (its haze); dark green land with a texture.
Exemplar sky_over_land() {
  return test::painted_exemplar(kSide, kSide, false, [](Exemplar& e, int x, int y, size_t i) {
    const float noise = float(splitmix64_mix(i) % 21) - 10.0f;
    const bool sky = y < kSkyRows, haze = sky && y >= kSkyRows - kHazeRows;
    e.labels[i] = sky ? 0 : 1;
    const float grey = haze ? 130 : 215;
    e.rgb[3 * i] = sky ? grey + noise : 50 + 20 * std::sin(x * 0.8f) + noise;
    e.rgb[3 * i + 1] = sky ? grey - 8 + noise : 80 + noise;
    e.rgb[3 * i + 2] = sky ? grey - 25 + noise : 40 + noise;
  });
}

constexpr PixelRect kOut{0, 0, 192, 192};
constexpr int64_t kSkyline = 96;  // target rows above it are sky

TargetGuides skyline_guides() {
  const int64_t halo = synthesis_halo();
  TargetGuides g;
  g.rect = {kOut.col0 - halo, kOut.row0 - halo, kOut.width + 2 * halo, kOut.height + 2 * halo};
  const size_t n = size_t(g.rect.width) * size_t(g.rect.height);
  g.labels.resize(n);
  g.depth.resize(n);
  for (int64_t r = 0; r < g.rect.height; ++r)
    for (int64_t c = 0; c < g.rect.width; ++c) {
      const size_t i = size_t(r) * size_t(g.rect.width) + size_t(c);
      const bool sky = g.rect.row0 + r < kSkyline;
      g.labels[i] = sky ? 0 : 1;
      g.depth[i] = sky ? std::numeric_limits<float>::infinity() : 5000.0f;
    }
  return g;
}

TEST(AcrossDepthBreak, TheSkyBesideASkylineIsNotDrawnToThePaintingsSkyBesideItsLand) {
  const ExemplarPyramid pyramid = analyse_exemplar(sky_over_land(), kLevels, 2);
  const auto src = synthesize(pyramid, skyline_guides(), {}, kOut);
  // Sky pixels 1-4 rows above the skyline copied from the painting's grey haze; the haze is
  // kHazeRows / kSkyRows (1/16) of the painting's sky. Before the neighbours across the break
  // were left out of the cost: 726 of the 768 (the label cost and the colour cost both favour
  // the painting's sky beside its land); now 3.
  int beside = 0, haze = 0;
  for (int64_t r = kSkyline - 4; r < kSkyline; ++r)
    for (int64_t c = 0; c < kOut.width; ++c) {
      const int32_t s = src[size_t(r * kOut.width + c)];
      ++beside;
      haze += s / kSide >= kSkyRows - kHazeRows && s / kSide < kSkyRows;
    }
  EXPECT_LT(double(haze) / beside, 2.0 / 16.0) << haze << " of " << beside;
}

}  // namespace
}  // namespace maquette::synthesis
