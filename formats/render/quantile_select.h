// The display stretch's quantiles (image/stretch.h quantile_range: the values at ranks
// floor(q (n - 1)) of the n finite values) found by a radix select instead of two nth_elements
// over all the values: one pass counts the values by the top 16 bits of an order-preserving key
// of their bits, which names the bucket holding each rank and its rank in there; a second pass
// gathers those buckets' values, and nth_element orders only them. The same values as
// quantile_range (an order statistic is one value: -0 and +0 compare equal and stretch alike), in
// two passes over the values without reordering them.
#pragma once

#include <vector>

#include "image/stretch.h"

namespace maquette {

StretchRange select_quantile_range(const std::vector<float>& values, double q0, double q1);

}  // namespace maquette
