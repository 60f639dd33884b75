#include "water_columns.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/parallel_chunks.h"

namespace maquette::deform {
namespace {

// Wet pixels per parallel task.
constexpr size_t kChunk = 16384;

// A voxel index in the lattice's range (vdb/column_fog.h refuses a column beyond +-2^30).
int32_t voxel_index(double k) { return int32_t(std::clamp(k, -2.0e9, 2.0e9)); }

}  // namespace

FogColumns lake_columns(const BasinRaster& basin, const WaterBody& body,
                        const PixelLattice& lattice, std::span<const std::array<double, 3>> surface,
                        int voxels_deep) {
  using V = std::array<double, 3>;
  const auto& [seed, a, along_row] = lattice;
  const V b{-along_row[0], -along_row[1], -along_row[2]};
  const V cross{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  const double norm = std::hypot(cross[0], cross[1], cross[2]);
  const V up{cross[0] / norm, cross[1] / norm, cross[2] / norm};
  const int64_t width = basin.width;
  const size_t wet = body.wet.size();
  // Each wet pixel's surface height over the plane, and the chunks' bounding boxes, in parallel;
  // the mean summed in order (the same bits for any threads).
  std::vector<double> height(wet);
  std::vector<std::array<int64_t, 4>> boxes((wet + kChunk - 1) / kChunk);
  parallel_chunks(wet, kChunk, [&](size_t first, size_t last) {
    int64_t c0 = width, r0 = basin.height, c1 = -1, r1 = -1;  // inclusive
    for (size_t w = first; w < last; ++w) {
      const int64_t col = body.wet[w] % width, row = body.wet[w] / width;
      c0 = std::min(c0, col), c1 = std::max(c1, col), r0 = std::min(r0, row),
      r1 = std::max(r1, row);
      const V& p = surface[w];
      height[w] = (p[0] - seed[0]) * up[0] + (p[1] - seed[1]) * up[1] + (p[2] - seed[2]) * up[2];
    }
    boxes[first / kChunk] = {c0, r0, c1, r1};
  });
  int64_t col0 = width, row0 = basin.height, col1 = -1, row1 = -1;
  for (const auto& box : boxes)
    col0 = std::min(col0, box[0]), row0 = std::min(row0, box[1]), col1 = std::max(col1, box[2]),
    row1 = std::max(row1, box[3]);
  double mean = 0;
  for (const double h : height) mean += h;
  mean /= double(wet);
  FogColumns fog;
  fog.width = int32_t(col1 - col0 + 1);
  fog.height = int32_t(row1 - row0 + 1);
  fog.low.assign(size_t(fog.width) * size_t(fog.height), 0);
  fog.high.assign(fog.low.size(), 0);
  const double dz = double(*std::max_element(body.depth.begin(), body.depth.end())) / voxels_deep;
  // Voxel k of a column is centred at height base + k * dz: voxel -1's top face at the mean, so
  // that a lake of flat surface fills whole leaves (k -8 to -1, -16 to -9, ...).
  const double base = mean + dz / 2;
  parallel_chunks(wet, kChunk, [&](size_t first, size_t last) {
    for (size_t w = first; w < last; ++w) {
      const int64_t col = body.wet[w] % width, row = body.wet[w] / width;
      const size_t at = size_t(row1 - row) * size_t(fog.width) + size_t(col - col0);
      // Centres strictly between the bed and the surface: low <= k < high.
      fog.high[at] = voxel_index(std::ceil((height[w] - base) / dz));
      fog.low[at] = voxel_index(std::floor((height[w] - double(body.depth[w]) - base) / dz) + 1);
    }
  });
  const double dc = double(col0 - body.seed % width), dr = double(row1 - body.seed / width);
  for (size_t x = 0; x < 3; ++x) {
    fog.centre[x] = seed[x] + dc * a[x] + dr * along_row[x] + base * up[x];
    fog.axes[0][x] = a[x];
    fog.axes[1][x] = b[x];
    fog.axes[2][x] = dz * up[x];
  }
  fog.name = "water";
  return fog;
}

}  // namespace maquette::deform
