#include "nearest_field.h"

#include <cmath>
#include <limits>

#include "core/avx2_clones.h"

namespace maquette::synthesis {

NearestField empty_field(const PatchCentres& queries) {
  NearestField field;
  field.index.assign(queries.member.size(), -1);
  for (int y = 0; y < queries.height; ++y) {
    for (int x = 0; x < queries.width; ++x) {
      if (!queries.has(x, y)) continue;
      field.index[size_t(y) * queries.width + x] = int32_t(field.query_x.size());
      field.query_x.push_back(x);
      field.query_y.push_back(y);
    }
  }
  field.match_x.assign(field.size(), -1);
  field.match_y.assign(field.size(), -1);
  field.cost.assign(field.size(), std::numeric_limits<float>::infinity());
  return field;
}

// Each row's squared differences summed in 8 interleaved lanes, then the lanes in a fixed order:
// a vectorizable sum whose bits do not depend on the machine or the thread.
MAQUETTE_AVX2_CLONES float patch_distance(const PatchImage& query, int qx, int qy,
                                          const PatchImage& reference, int rx, int ry, int patch,
                                          float bound) {
  constexpr int kLanes = 8;
  const int half = patch / 2;
  const int row_values = patch * query.channels;
  float sum = 0;
  for (int dy = -half; dy <= half; ++dy) {
    const float* a = query.pixel(qx - half, qy + dy);
    const float* b = reference.pixel(rx - half, ry + dy);
    float lanes[kLanes] = {};
    int i = 0;
    for (; i + kLanes <= row_values; i += kLanes) {
      for (int k = 0; k < kLanes; ++k) {
        const float d = a[i + k] - b[i + k];
        lanes[k] += d * d;
      }
    }
    for (int k = 0; i < row_values; ++i, ++k) {
      const float d = a[i] - b[i];
      lanes[k] += d * d;
    }
    sum += ((lanes[0] + lanes[1]) + (lanes[2] + lanes[3])) +
           ((lanes[4] + lanes[5]) + (lanes[6] + lanes[7]));
    if (sum > bound) return sum;
  }
  // A NaN cost would never be replaced (no d < NaN): a patch over a NaN is infinitely far.
  return std::isnan(sum) ? std::numeric_limits<float>::infinity() : sum;
}

}  // namespace maquette::synthesis
