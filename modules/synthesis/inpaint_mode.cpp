#include "inpaint_mode.h"

#include <algorithm>
#include <cmath>

namespace maquette::synthesis {

void mean_shift_mode(const float* const* values, const double* weights, size_t count, int channels,
                     double* mode, double* next) {
  double variance = 0, total = 0;
  for (size_t j = 0; j < count; ++j) {
    for (int i = 0; i < channels; ++i) variance += weights[j] * std::pow(values[j][i] - mode[i], 2);
    total += weights[j];
  }
  const double kernel = kModeBandwidth * variance / total;
  if (!(kernel > 0)) return;  // the votes agree
  for (int step = 0; step < kModeSteps; ++step) {
    double sum = 0;
    std::fill_n(next, channels, 0.0);
    for (size_t j = 0; j < count; ++j) {
      double d2 = 0;
      for (int i = 0; i < channels; ++i) d2 += std::pow(values[j][i] - mode[i], 2);
      const double k = weights[j] * std::exp(-d2 / (2 * kernel));
      for (int i = 0; i < channels; ++i) next[i] += k * values[j][i];
      sum += k;
    }
    if (!(sum > 0)) return;
    double moved = 0;
    for (int i = 0; i < channels; ++i) {
      moved += std::pow(next[i] / sum - mode[i], 2);
      mode[i] = next[i] / sum;
    }
    if (moved < kModeSettled * kernel) return;
  }
}

}  // namespace maquette::synthesis
