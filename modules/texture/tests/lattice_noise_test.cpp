// The noise cached on a global pixel lattice (lattice_noise.h) against exact evaluation of the
// same octaves at every pixel, and its independence of the tiling.
#include "../lattice_noise.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "../field.h"

namespace maquette::texture {
namespace {

constexpr int kRing = 1, kPositionRing = kRing + kNoiseLatticeReach;

struct Planes {
  PixelPositions position;
  NoiseGeometry geometry;
};

// The planes of a tile of `size` on `cell` (refine 0), as render_tile lays them out (the
// geometry's `position` is set where it is used: Planes is returned by value).
Planes planes(CellId cell, int size) {
  return {PixelPositions(default_grid(), cell, size, 0, kPositionRing),
          {size, kRing, global_col(cell, size, 0), global_row(cell, size, 0),
           default_grid().level_info(cell.level(), size).pixel_m, nullptr}};
}

// Every pixel of the planes, row by row.
std::vector<float> lattice_noise(const NoiseField& field, const Planes& p) {
  NoiseGeometry geometry = p.geometry;
  geometry.position = &p.position;
  LatticeNoise noise(field, geometry);
  const int side = p.geometry.size + 2 * kRing;
  std::vector<float> out(size_t(side) * size_t(side));
  for (int r = -kRing; r < p.geometry.size + kRing; ++r)
    noise.row(r, -kRing, p.geometry.size + kRing - 1, &out[size_t(r + kRing) * size_t(side)]);
  return out;
}

// Octaves of at least 2 pixels evaluated exactly at the pixel, normalised by all the amplitudes.
float exact(const NoiseField& field, const Vec3d& position, double pixel_m) {
  double sum = 0;
  for (int o = 0; o < field.octaves(); ++o)
    if (field.wavelength_m(o) >= 2 * pixel_m) sum += field.amplitude(o) * field.octave(o, position);
  return float(std::clamp(sum / field.norm(), -1.0, 1.0));
}

// Pixels of 8.8 m (level 14 cell, 64 pixels): wavelengths from 3 to 34 pixels, so lattices of
// spacing 1 to 8 and an anti-aliased octave.
TEST(LatticeNoise, WithinToleranceOfExactEvaluation) {
  const Planes p = planes(CellId::FromFaceColRow(2, 14, 7700, 8100), 64);
  ASSERT_NEAR(p.geometry.pixel_m, 8.79, 0.01);
  const int side = 64 + 2 * kRing;
  for (const NoiseParams& params :
       {NoiseParams{3, 3, 300, 0.5}, NoiseParams{20, 3, 200, 0.5}, NoiseParams{5, 5, 300, 0.6}}) {
    const NoiseField field(params);
    const std::vector<float> cached = lattice_noise(field, p);
    double worst = 0, sum_sq = 0;
    for (int r = 0; r < side; ++r)
      for (int c = 0; c < side; ++c) {
        const Vec3d x = p.position.at(c - kRing, r - kRing);
        const double d =
            cached[size_t(r) * size_t(side) + size_t(c)] - exact(field, x, p.geometry.pixel_m);
        worst = std::max(worst, std::abs(d));
        sum_sq += d * d;
      }
    // The per-octave budget bounds the error by 0.06; measured: 0.009 to 0.017 (rms <= 0.004).
    EXPECT_LT(worst, 0.03) << params.wavelength_m;
    EXPECT_GT(worst, 0) << "interpolated somewhere";  // a lattice coarser than the pixels
    EXPECT_LT(std::sqrt(sum_sq / double(side * side)), 0.006) << params.wavelength_m;
  }
}

// With pixel_m = 0 every octave is evaluated at every pixel: NoiseField itself.
TEST(LatticeNoise, ExactWithoutPixelSize) {
  Planes p = planes(CellId::FromFaceColRow(2, 14, 7700, 8100), 16);
  p.geometry.pixel_m = 0;
  const NoiseField field({4, 4, 50, 0.5});
  const std::vector<float> cached = lattice_noise(field, p);
  for (int r = 0; r < 18; ++r)
    for (int c = 0; c < 18; ++c)
      ASSERT_EQ(cached[size_t(r) * 18 + size_t(c)], field(p.position.at(c - kRing, r - kRing)));
}

// Lattice nodes are evaluated a batch at a time (8 points at once with AVX2, the rest padded):
// every octave gives the same bits at a point whichever batch the point is in.
TEST(LatticeNoise, SameBitsInABatchAsAlone) {
  const NoiseField field({9, 3, 300, 0.5});
  const PixelPositions positions(default_grid(), CellId::FromFaceColRow(2, 14, 7700, 8100), 64, 0,
                                 0);
  Points p;
  for (int k = 0; k < 11; ++k) p.push_back(positions.at(5 * k, 3 * k));
  for (int o = 0; o < field.octaves(); ++o) {
    std::vector<float> batch(p.size());
    field.octave(o, p.from(0), int(p.size()), batch.data());
    for (size_t k = 0; k < p.size(); ++k) {
      const Vec3d alone{p.axis[0][k], p.axis[1][k], p.axis[2][k]};
      ASSERT_EQ(batch[k], field.octave(o, alone)) << o << " " << k;
      ASSERT_NE(batch[k], 0.0f);  // not on a lattice point of the noise: a value to compare
    }
  }
}

// A pixel has the same noise, to the bit, whichever tile computes it: a tile of 64 and the 4
// tiles of 32 one level finer cover the same pixels, and so do two neighbouring tiles' rings.
TEST(LatticeNoise, SameBitsForAnyTiling) {
  const NoiseField field({7, 3, 300, 0.5});
  const CellId parent = CellId::FromFaceColRow(2, 14, 7700, 8100);
  const std::vector<float> whole = lattice_noise(field, planes(parent, 64));
  for (int k = 0; k < 4; ++k) {
    const CellId child =
        CellId::FromFaceColRow(2, 15, 2 * 7700 + uint32_t(k % 2), 2 * 8100 + uint32_t(k / 2));
    const std::vector<float> part = lattice_noise(field, planes(child, 32));
    for (int r = -kRing; r < 32 + kRing; ++r)
      for (int c = -kRing; c < 32 + kRing; ++c) {
        const int pr = r + 32 * (k / 2), pc = c + 32 * (k % 2);
        ASSERT_EQ(part[size_t(r + kRing) * 34 + size_t(c + kRing)],
                  whole[size_t(pr + kRing) * 66 + size_t(pc + kRing)])
            << k << " " << c << " " << r;
      }
  }
}

}  // namespace
}  // namespace maquette::texture
