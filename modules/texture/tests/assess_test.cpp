// texture.assess's comparison at the observed map's minimum mapping unit: the predicted classes
// after the majority filter (params.predicted_majority_radius), the classes as rendered reported
// beside them, on a two-class map with isolated wrong pixels counted by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "texture_module.h"

namespace maquette::texture {
namespace {

using namespace texture_test;

constexpr int kSize = 32, kLevel = 10, kHalo = 16;  // texture.assess's halo
constexpr int kRadius = 2;

// Cells 2 x 2; the observed class 0 west of global column kSplit, 1 from it; the prediction
// the same but for one pixel in every 5 x 5 block, given the other class.
constexpr uint32_t kFirstCol = 520, kFirstRow = 500;
constexpr int64_t kSplit = int64_t(kFirstCol) * kSize + 20;
int observed(int64_t col) { return col < kSplit ? 0 : 1; }
bool speck(int64_t col, int64_t row) { return col % 5 == 2 && row % 5 == 2; }

Tile<float> classes_of(CellId cell, bool predicted) {
  Tile<float> t(kSize, 1, 0);
  for (int r = 0; r < kSize; ++r)
    for (int c = 0; c < kSize; ++c) {
      const int64_t gc = global_col(cell, kSize, c), gr = global_row(cell, kSize, r);
      t.at(c, r) = float(predicted && speck(gc, gr) ? 1 - observed(gc) : observed(gc));
    }
  return t;
}

std::vector<CellId> cells() {
  std::vector<CellId> out;
  for (uint32_t r = 0; r < 2; ++r)
    for (uint32_t c = 0; c < 2; ++c)
      out.push_back(CellId::FromFaceColRow(2, kLevel, kFirstCol + c, kFirstRow + r));
  return out;
}

json assess(int radius, int predicted_halo = kHalo) {
  return run_reduce(
      "texture.assess", cells(), kSize,
      [&](CellId c) {
        CellData d;
        d.inputs.emplace("classes",
                         with_halo(c, kSize, kHalo, [](CellId n) { return classes_of(n, false); }));
        d.inputs.emplace("predicted", with_halo(c, kSize, predicted_halo,
                                                [](CellId n) { return classes_of(n, true); }));
        return d;
      },
      {{"predicted_majority_radius", radius}});
}

TEST(Assess, PredictedClassesAtTheObservedMinimumMappingUnit) {
  // The hand count: the specks are the only disagreement; Cohen's kappa from the 2 x 2 table.
  double n = 0, wrong = 0, obs[2] = {0, 0}, pred[2] = {0, 0};
  for (const CellId c : cells())
    for (int r = 0; r < kSize; ++r)
      for (int col = 0; col < kSize; ++col) {
        const int64_t gc = global_col(c, kSize, col), gr = global_row(c, kSize, r);
        const int o = observed(gc), p = speck(gc, gr) ? 1 - o : o;
        ++n, wrong += o != p, ++obs[o], ++pred[p];
      }
  const double accuracy = 1 - wrong / n;
  const double chance = (obs[0] * pred[0] + obs[1] * pred[1]) / (n * n);
  const double kappa = (accuracy - chance) / (1 - chance);
  ASSERT_GT(wrong, 0);

  const json plain = assess(0);
  EXPECT_NEAR(plain["accuracy"].get<double>(), accuracy, 1e-12) << plain;
  EXPECT_NEAR(plain["kappa"].get<double>(), kappa, 1e-12) << plain;
  EXPECT_FALSE(plain.contains("unfiltered"));

  // A 5 x 5 window holds at most one speck, and beside the split at least 3 of its 5 columns
  // are the pixel's own class: the filter gives back the observed map exactly.
  const json filtered = assess(kRadius);
  EXPECT_EQ(filtered["accuracy"].get<double>(), 1) << filtered;
  EXPECT_EQ(filtered["kappa"].get<double>(), 1) << filtered;
  EXPECT_EQ(filtered["confusion"],
            json::parse("[[" + std::to_string(uint64_t(obs[0])) + ", 0, 0], [0, " +
                        std::to_string(uint64_t(obs[1])) + ", 0]]"));
  EXPECT_EQ(filtered["unfiltered"]["confusion"], plain["confusion"]);
  EXPECT_NEAR(filtered["unfiltered"]["kappa"].get<double>(), kappa, 1e-12);
  EXPECT_EQ(filtered["unfiltered"]["producers_accuracy"], plain["producers_accuracy"]);

  try {
    assess(kRadius, 1);
    FAIL();
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(),
                 "texture.assess: inputs.predicted: halo 1 is narrower than "
                 "params.predicted_majority_radius 2");
  }
}

}  // namespace
}  // namespace maquette::texture
