// std::lround's rounding (halves away from zero), inline. glibc's lround is a function call the
// compiler does not inline on baseline x86-64, and the renderer rounds several times per pixel.
#pragma once

#include <cmath>
#include <cstdint>

namespace maquette {

// std::llround(x) for any finite x with |x| < 2^63: x plus the largest double below one half, with
// x's sign, truncated. That sum rounds to the next whole number exactly when x's fraction is at
// least one half (below 1/2 the sum stays below it, and 1 - 2^-54 rounds to 1 as a tie to even);
// one addition and one conversion (the sign by bit masks). Precondition: x finite and
// |x| < 2^63 (as for std::llround).
inline int64_t round_half_away(double x) {
  return int64_t(x + std::copysign(0.49999999999999994, x));
}

}  // namespace maquette
