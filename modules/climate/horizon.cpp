#include "horizon.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace maquette::climate {
namespace {

// A march's sample `z` for a pixel at height z0: its march ends at a sample without data, else
// its best tangent rises to the sample's.
inline void take(float z, float z0, float drop, float inv_d, float& alive, float& best) {
  const float a = alive * float(z == z);
  alive = a;
  const float t = (z - drop - z0) * inv_d;
  best = (a > 0.f) & (t > best) ? t : best;
}

}  // namespace

HorizonAngles::HorizonAngles(int directions, double max_distance_m)
    : directions_(directions), max_distance_(max_distance_m) {}

void HorizonAngles::compute(const DilatedDem& surfaces, float zmax, const std::vector<char>& used,
                            const PixelFrame& frame, int col0, int row0,
                            std::vector<float>& out) const {
  constexpr int B = kBlock;
  const Tile<float>& dem = surfaces.level(0);
  const int h = dem.halo(), n = dem.size();
  out.assign(size_t(B) * B * size_t(directions_), float(-M_PI / 2));
  // Per pixel: its height, the tangent of the highest elevation angle so far, and 1 while its
  // march goes on (0 once it has left the halo or met a sample without data).
  std::array<float, B * B> z0, best, alive;
  for (int r = 0; r < B; ++r)
    for (int c = 0; c < B; ++c) z0[size_t(r * B + c)] = dem.at(col0 + c, row0 + r);
  for (int k = 0; k < directions_; ++k) {
    if (!used[size_t(k)]) continue;
    const March m = march(frame, 360.0 * k / directions_);
    const bool along_row = std::abs(m.dcol) >= std::abs(m.drow);  // the longer axis
    best.fill(-INFINITY);
    for (int i = 0; i < B * B; ++i) alive[size_t(i)] = std::isnan(z0[size_t(i)]) ? 0.f : 1.f;
    // `step` counts march steps of one pixel along the longer axis; samples are taken at every
    // one of them up to kFineSteps, then at every 2nd up to 2 kFineSteps, every 4th up to
    // 4 kFineSteps, ...: a sample followed by a gap of 2^l reads the level-l maxima, which
    // reach half the gap around it (and so half the previous gap, never longer).
    int level = 0, samples = 0;
    for (int step = 1; step * m.metres <= max_distance_; step += 1 << level) {
      if (level < surfaces.levels() && step >= kFineSteps << level) ++level;
      const Tile<float>& surface = surfaces.level(level);
      const double x = step * m.dcol, y = step * m.drow, fx = std::floor(x), fy = std::floor(y);
      int dc = int(fx), dr = int(fy);
      // Steps are whole pixels along the longer axis (march(): +-1), so the bilinear sample is
      // linear across it: between two rows or along one, the second of weight w. A pixel whose
      // weight is below float's resolution is not read (a neighbour without data must not end
      // the march): marches along an axis or a diagonal are off whole pixels by rounding only
      // (cos 90 deg is 6e-17), w is then ~1e-15 or rounds to 1 (the second pixel alone).
      float w = float(along_row ? y - fy : x - fx);
      if (w == 1) {
        (along_row ? dr : dc) += 1;
        w = 0;
      }
      if (1 - w == 1) w = 0;
      const int right = !along_row && w > 0, below = along_row && w > 0;
      const double d = step * m.metres;
      const float drop = float(d * d / (2 * kEarthRadius)), inv_d = float(1 / d);
      // Block columns whose samples lie in the tile and its halo; others stop.
      const int c_lo = std::max(0, -h - col0 - dc), c_hi = std::min(B, n + h - right - col0 - dc);
      // Whether a march may still rise, checked at every 4th sample (the check costs as much).
      const bool check = ++samples % 4 == 0;
      int any = !check;  // an int: its reduction vectorizes
      for (int r = 0; r < B; ++r) {
        const int row = row0 + r + dr;
        float* __restrict on = &alive[size_t(r * B)];
        if (row < -h || row + below >= n + h || c_lo >= c_hi) {
          std::fill(on, on + B, 0.f);
          continue;
        }
        std::fill(on, on + c_lo, 0.f);
        std::fill(on + std::max(c_lo, c_hi), on + B, 0.f);
        // Block column c (c_lo <= c < c_hi) reads the pixel of column col0 + dc + c, inside the
        // tile and its halo: `first` and `second` point at column c_lo's (column 0's may not
        // exist).
        const float* __restrict first = &surface.at(col0 + dc + c_lo, row);
        const float* __restrict z_0 = &z0[size_t(r * B)];
        float* __restrict b = &best[size_t(r * B)];
        if (w > 0) {
          const float* __restrict second =
              below ? &surface.at(col0 + dc + c_lo, row + 1) : first + 1;
          for (int c = c_lo; c < c_hi; ++c)
            take((1 - w) * first[c - c_lo] + w * second[c - c_lo], z_0[c], drop, inv_d, on[c],
                 b[c]);
        } else {
          for (int c = c_lo; c < c_hi; ++c) take(first[c - c_lo], z_0[c], drop, inv_d, on[c], b[c]);
        }
        if (check)
          for (int c = 0; c < B; ++c)
            any |= int(on[c] > 0.f) & int((zmax - drop - z_0[c]) * inv_d > b[c]);
      }
      if (!any) break;
    }
    for (int i = 0; i < B * B; ++i)
      out[size_t(i) * size_t(directions_) + size_t(k)] = std::atan(best[size_t(i)]);
  }
}

}  // namespace maquette::climate
