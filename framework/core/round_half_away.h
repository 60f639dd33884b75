// std::lround's rounding (halves away from zero), inline. glibc's lround is a function call the
// compiler does not inline on baseline x86-64, and the renderer rounds several times per pixel.
#pragma once

#include <cstdint>

namespace maquette {

// std::llround(x) for any finite x with |x| < 2^63: x - trunc(x) is exact, so the comparison
// with one half is. Precondition: x finite and |x| < 2^63 (as for std::llround).
inline int64_t round_half_away(double x) {
  const auto whole = int64_t(x);  // towards zero
  const double rest = x - double(whole);
  return whole + int64_t(rest >= 0.5) - int64_t(rest <= -0.5);  // no branch to mispredict
}

}  // namespace maquette
