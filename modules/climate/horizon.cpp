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
  const Tile<float>& dem = surfaces.level(0, Axis::Col);
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
    const Axis axis = std::abs(m.dcol) >= std::abs(m.drow) ? Axis::Col : Axis::Row;
    best.fill(-INFINITY);
    for (int i = 0; i < B * B; ++i) alive[size_t(i)] = std::isnan(z0[size_t(i)]) ? 0.f : 1.f;
    // `step` counts march steps of one pixel along the longer axis; samples are taken at every
    // one of them up to kFineSteps, then at every 2nd up to 2 kFineSteps, every 4th up to
    // 4 kFineSteps, ...: a sample followed by a gap of 2^l reads the level-l maxima, which
    // reach half the gap on either side (and so half the previous gap, never longer).
    int level = 0, samples = 0;
    for (int step = 1; step * m.metres <= max_distance_; step += 1 << level) {
      if (level < surfaces.levels() && step >= kFineSteps << level) ++level;
      const Tile<float>& surface = surfaces.level(level, axis);
      const double x = step * m.dcol, y = step * m.drow, fx = std::floor(x), fy = std::floor(y);
      const int dc = int(fx), dr = int(fy);
      const float tx = float(x - fx), ty = float(y - fy);
      const double d = step * m.metres;
      const float drop = float(d * d / (2 * kEarthRadius)), inv_d = float(1 / d);
      // Block columns whose four samples lie in the tile and its halo; others stop.
      const int c_lo = std::max(0, -h - col0 - dc), c_hi = std::min(B, n + h - 1 - col0 - dc);
      // Whether a march may still rise, checked at every 4th sample (the check costs as much).
      const bool check = ++samples % 4 == 0;
      int any = !check;  // an int: its reduction vectorizes
      for (int r = 0; r < B; ++r) {
        const int row = row0 + r + dr;
        float* __restrict on = &alive[size_t(r * B)];
        if (row < -h || row + 1 >= n + h || c_lo >= c_hi) {
          std::fill(on, on + B, 0.f);
          continue;
        }
        std::fill(on, on + c_lo, 0.f);
        std::fill(on + std::max(c_lo, c_hi), on + B, 0.f);
        const float* __restrict top = &surface.at(col0 + dc, row);
        const float* __restrict bottom = &surface.at(col0 + dc, row + 1);
        const float* __restrict z_0 = &z0[size_t(r * B)];
        float* __restrict b = &best[size_t(r * B)];
        // Steps are whole pixels along the longer axis (march(): +-1), so the bilinear sample
        // is linear across it: between two rows, or along one.
        if (axis == Axis::Col)
          for (int c = c_lo; c < c_hi; ++c)
            take((1 - ty) * top[c] + ty * bottom[c], z_0[c], drop, inv_d, on[c], b[c]);
        else
          for (int c = c_lo; c < c_hi; ++c)
            take((1 - tx) * top[c] + tx * top[c + 1], z_0[c], drop, inv_d, on[c], b[c]);
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
