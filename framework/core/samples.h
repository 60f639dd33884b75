// Sample-level helpers shared by tile conversions and the store: dispatch from a runtime DType
// to its C++ type, conversion from double with rounding and clamping, and the nodata test.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>

#include "core/tile.h"

namespace maquette {

// Calls f(std::type_identity<T>{}) with the sample type T of `t`, so that one generic lambda
// handles all seven dtypes.
template <typename F>
decltype(auto) visit_dtype(DType t, F&& f) {
  switch (t) {
    case DType::U8:
      return f(std::type_identity<uint8_t>{});
    case DType::U16:
      return f(std::type_identity<uint16_t>{});
    case DType::I16:
      return f(std::type_identity<int16_t>{});
    case DType::U32:
      return f(std::type_identity<uint32_t>{});
    case DType::I32:
      return f(std::type_identity<int32_t>{});
    case DType::F32:
      return f(std::type_identity<float>{});
    case DType::F64:
      return f(std::type_identity<double>{});
  }
  __builtin_unreachable();  // DType values come from parse_dtype or validated blob headers
}

// v as a T: rounded half away from zero and clamped for integer types (NaN becomes 0).
template <typename T>
T cast_sample(double v) {
  if constexpr (std::is_floating_point_v<T>) {
    // Converting a double beyond T's range is undefined behaviour: saturate to +-infinity.
    if (std::abs(v) > double(std::numeric_limits<T>::max()) && std::isfinite(v))
      return v > 0 ? std::numeric_limits<T>::infinity() : -std::numeric_limits<T>::infinity();
    return static_cast<T>(v);
  } else {
    if (std::isnan(v)) return T{0};
    const double r = std::round(v);
    if (r <= double(std::numeric_limits<T>::min())) return std::numeric_limits<T>::min();
    if (r >= double(std::numeric_limits<T>::max())) return std::numeric_limits<T>::max();
    return static_cast<T>(r);
  }
}

// Whether sample v equals the nodata value. Float samples compare in their own precision, so a
// float32 tile matches a nodata like 3.4e38 that is not exactly representable.
template <typename T>
bool is_nodata(T v, double nodata) {
  if constexpr (std::is_floating_point_v<T>)
    return v == static_cast<T>(nodata);
  else
    return double(v) == nodata;
}

// Whether sample v is missing: NaN (float types) or equal to the nodata value, if any.
template <typename T>
bool is_missing(T v, const double* nodata) {
  if constexpr (std::is_floating_point_v<T>)
    if (std::isnan(v)) return true;
  return nodata && is_nodata(v, *nodata);
}

}  // namespace maquette
