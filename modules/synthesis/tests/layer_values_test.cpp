// inpaint() and clone() on layers other than imagery (inpaint.h LayerValues), against the known
// synthetic truth: a DEM hole in a ramp crossed by a ridge filled within its surroundings' heights
// and without a step at the fill's edge, a terrain patch cloned onto a ramp meeting it with its
// own relief kept; a land-cover fill holding only the classes found outside the hole (averaged
// codes would not), classes cloned whole.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <random>
#include <set>

#include "../clone.h"
#include "../inpaint.h"
#include "../masked_pyramid.h"
#include "../patchmatch.h"
#include "synthetic_images.h"

namespace maquette::synthesis {
namespace {

constexpr int kSide = 128;

// A ramp (2 m per sample east, 1 m south) crossed by a 40 m Gaussian ridge along x = 40 + y / 2,
// with a 3 m ripple: the relief patches can copy.
PatchImage ramp_and_ridge() {
  PatchImage dem(kSide, kSide, 1);
  for (int y = 0; y < kSide; ++y) {
    for (int x = 0; x < kSide; ++x) {
      const double across = (x - 40 - 0.5 * y) / std::sqrt(1.25);
      dem.pixel(x, y)[0] = float(2.0 * x + y + 40 * std::exp(-across * across / (2 * 36.0)) +
                                 3 * std::sin(0.9 * x) * std::cos(0.7 * y));
    }
  }
  return dem;
}

struct HeightFill {
  double low = 1e30, high = -1e30;  // the surroundings' range (within 8 of the hole)
  double fill_low = 1e30, fill_high = -1e30;
  double step = 0;      // mean |change across the region's edge - the truth's there|, m
  double interior = 0;  // the same between neighbours both in the hole
  double rms = 0;       // in the hole against the truth, m
};

HeightFill fill_heights(LayerValues values) {
  const PatchImage truth = ramp_and_ridge();
  const auto hole = test::square_mask(kSide, kSide, 50, 50, 28);
  PatchImage damaged = truth;
  for (size_t i = 0; i < hole.size(); ++i)
    damaged.values[i] = hole[i] != 0 ? 0.0f : truth.values[i];
  InpaintParams params;
  params.values = values;
  const PatchImage filled = inpaint(damaged, hole, params, PatchMatch());
  const auto to_hole = chessboard_distance(hole, kSide, kSide);
  HeightFill r;
  double steps = 0, squares = 0, interior = 0;
  size_t pairs = 0, inside = 0, interior_pairs = 0;
  for (int y = 0; y < kSide; ++y) {
    for (int x = 0; x < kSide; ++x) {
      const size_t i = size_t(y) * kSide + x;
      const float z = filled.values[i];
      if (hole[i] != 0) {
        r.fill_low = std::min(r.fill_low, double(z)),
        r.fill_high = std::max(r.fill_high, double(z));
        squares += (z - truth.values[i]) * (z - truth.values[i]);
        ++inside;
      } else if (to_hole[i] <= 8) {
        r.low = std::min(r.low, double(z)), r.high = std::max(r.high, double(z));
      }
      // The resynthesized region's edge: a pixel within the band and its right or lower
      // neighbour beyond it (or the reverse).
      for (const auto& [dx, dy] : {std::pair{1, 0}, std::pair{0, 1}}) {
        if (x + dx >= kSide || y + dy >= kSide) continue;
        const size_t j = size_t(y + dy) * kSide + x + dx;
        const double error = std::abs((filled.values[j] - z) - (truth.values[j] - truth.values[i]));
        if (hole[i] != 0 && hole[j] != 0) interior += error, ++interior_pairs;
        if ((to_hole[i] <= params.band) == (to_hole[j] <= params.band)) continue;
        steps += error;
        ++pairs;
      }
    }
  }
  r.step = steps / double(pairs);
  r.interior = interior / double(interior_pairs);
  r.rms = std::sqrt(squares / double(inside));
  return r;
}

TEST(InpaintHeights, ARampAndRidgeHoleIsFilledWithinItsSurroundingsWithoutAStep) {
  const HeightFill heights = fill_heights(LayerValues::Heights);
  const HeightFill raw = fill_heights(LayerValues::Continuous);
  std::cout << "heights: range " << heights.fill_low << ".." << heights.fill_high << " in "
            << heights.low << ".." << heights.high << ", step " << heights.step << " m (inside "
            << heights.interior << "), rms " << heights.rms << " m; as colours: range "
            << raw.fill_low << ".." << raw.fill_high << ", step " << raw.step << " m (inside "
            << raw.interior << "), rms " << raw.rms << " m\n";
  EXPECT_GE(heights.fill_low, heights.low);
  EXPECT_LE(heights.fill_high, heights.high);
  // No step: across the edge the fill departs from the truth's changes no more than between two
  // of its own pixels (measured 1.28 and 1.32 m; as colours 2.64 across and 2.29 inside).
  EXPECT_LE(heights.step, 1.1 * heights.interior);
  // The ridge carried through the hole (measured 10.0 m, as colours 24.3 m).
  EXPECT_LE(heights.rms, 12.0);
  EXPECT_LT(heights.rms, raw.rms / 2);
}

// Classes 11, 42 and 90 in the Voronoi cells of 60 random sites.
PatchImage classes_in_cells(int w, int h) {
  std::mt19937 rng(3);
  std::uniform_int_distribution<int> px(0, w - 1), py(0, h - 1), code(0, 2);
  std::vector<std::array<int, 3>> sites(60);
  for (auto& s : sites) s = {px(rng), py(rng), code(rng)};
  const float codes[] = {11, 42, 90};
  PatchImage labels(w, h, 1);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const auto nearest = std::min_element(sites.begin(), sites.end(), [&](auto& a, auto& b) {
        return std::hypot(a[0] - x, a[1] - y) < std::hypot(b[0] - x, b[1] - y);
      });
      labels.pixel(x, y)[0] = codes[(*nearest)[2]];
    }
  }
  return labels;
}

TEST(InpaintClasses, AFillHoldsOnlyTheClassesFoundOutsideTheHole) {
  PatchImage labels = classes_in_cells(96, 96);
  const auto hole = test::square_mask(96, 96, 36, 36, 24);
  for (size_t i = 0; i < hole.size(); ++i) {
    if (hole[i] != 0) labels.values[i] = 7;
  }
  labels.values[5] = NAN;  // nodata kept
  const auto classes_in_hole = [&](LayerValues values) {
    InpaintParams params;
    params.values = values;
    const PatchImage filled = inpaint(labels, hole, params, PatchMatch());
    const auto to_hole = chessboard_distance(hole, 96, 96);
    std::set<float> found;
    size_t changed_beyond_band = 0;
    for (size_t i = 0; i < hole.size(); ++i) {
      if (to_hole[i] <= params.band) {
        found.insert(filled.values[i]);
      } else if (i != 5) {
        changed_beyond_band += filled.values[i] != labels.values[i];
      }
    }
    EXPECT_EQ(changed_beyond_band, 0u);
    EXPECT_TRUE(std::isnan(filled.values[5]));
    return found;
  };
  EXPECT_EQ(classes_in_hole(LayerValues::Classes), (std::set<float>{11, 42, 90}));
  // The same fill averaging the codes makes codes that are no class (the test can fail).
  const auto averaged = classes_in_hole(LayerValues::Continuous);
  std::cout << "classes averaged: " << averaged.size() << " codes\n";
  EXPECT_GT(averaged.size(), 3u);
}

TEST(CloneClasses, ClassesAreCopiedWhole) {
  const PatchImage labels = classes_in_cells(96, 96);
  CloneParams params;
  params.offset_x = 37;
  params.offset_y = 30;
  params.linear = {1.3, 0, 0, 1.3};  // resized: a bilinear copy would mix codes
  params.fill.values = LayerValues::Classes;
  const PatchImage out = clone(labels, test::square_mask(96, 96, 10, 10, 24), params, PatchMatch());
  std::set<float> found(out.values.begin(), out.values.end());
  EXPECT_EQ(found, (std::set<float>{11, 42, 90}));
  // Inside the destination beyond the band: the source's class at the nearest mapped pixel.
  const double c = 10 + 11.5;
  size_t checked = 0;
  for (int y = 0; y < 96; ++y) {
    for (int x = 0; x < 96; ++x) {
      const double sx = c + (x - c - 37) / 1.3, sy = c + (y - c - 30) / 1.3;
      if (sx < 10 + 4 || sx > 33 - 4 || sy < 10 + 4 || sy > 33 - 4) continue;
      EXPECT_EQ(out.pixel(x, y)[0], labels.pixel(int(std::lround(sx)), int(std::lround(sy)))[0]);
      ++checked;
    }
  }
  EXPECT_GT(checked, 300u);
}

TEST(CloneHeights, ATerrainPatchClonedOntoARampMeetsItAndKeepsItsRelief) {
  // The ridge's patch copied 60 samples east onto the bare ramp (60 x 2 m higher there).
  const PatchImage dem = ramp_and_ridge();
  CloneParams params;
  params.offset_x = 60;
  params.fill.values = LayerValues::Heights;
  const auto source = test::square_mask(kSide, kSide, 40, 40, 30);
  const PatchImage out = clone(dem, source, params, PatchMatch());
  // The relief: inside the destination beyond the band, the source's heights plus one offset.
  double low = 1e30, high = -1e30;
  for (int y = 40 + 4; y < 70 - 4; ++y) {
    for (int x = 100 + 4; x < 130 - 4 && x < kSide; ++x) {
      const double offset = out.pixel(x, y)[0] - dem.pixel(x - 60, y)[0];
      low = std::min(low, offset), high = std::max(high, offset);
    }
  }
  std::cout << "clone heights: offset " << low << ".." << high << " m\n";
  EXPECT_LE(high - low, 1e-3);
  // Meeting the ramp: the offset is the mean height difference between the destination and the
  // source along the destination's edge: its samples within 3 (chessboard) of a sample outside
  // it in the image, computed here from the surface, not from clone().
  double sum = 0;
  int n = 0;
  for (int y = 40; y < 70; ++y) {
    for (int x = 100; x < std::min(130, kSide); ++x) {
      bool edge = false;
      for (int dy = -3; dy <= 3 && !edge; ++dy) {
        for (int dx = -3; dx <= 3 && !edge; ++dx) {
          const int nx = x + dx, ny = y + dy;
          const bool in_image = nx >= 0 && nx < kSide && ny >= 0 && ny < kSide;
          edge = in_image && (nx < 100 || nx >= 130 || ny < 40 || ny >= 70);
        }
      }
      if (!edge) continue;
      sum += dem.pixel(x, y)[0] - dem.pixel(x - 60, y)[0];
      ++n;
    }
  }
  EXPECT_NEAR(low, sum / n, 0.01) << n << " edge samples";
}

}  // namespace
}  // namespace maquette::synthesis
