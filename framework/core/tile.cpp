#include "core/tile.h"

#include <array>
#include <cstring>
#include <string>

#include "core/error.h"
#include "core/samples.h"

namespace maquette {
namespace {

constexpr std::array<std::string_view, 7> kDTypeNames = {"uint8", "uint16",  "int16",  "uint32",
                                                         "int32", "float32", "float64"};

void check_bytes(const RawTile& raw) {
  if (raw.bytes.size() != raw.sample_count() * dtype_size(raw.dtype))
    throw Error("raw tile holds " + std::to_string(raw.bytes.size()) + " bytes, expected " +
                std::to_string(raw.sample_count() * dtype_size(raw.dtype)) + " for " +
                std::to_string(raw.size) + "x" + std::to_string(raw.size) + "x" +
                std::to_string(raw.channels) + " " + std::string(dtype_name(raw.dtype)));
}

}  // namespace

size_t dtype_size(DType t) {
  return visit_dtype(t, []<typename T>(std::type_identity<T>) { return sizeof(T); });
}

std::string_view dtype_name(DType t) { return kDTypeNames.at(size_t(t)); }

DType parse_dtype(std::string_view name) {
  for (size_t i = 0; i < kDTypeNames.size(); ++i)
    if (kDTypeNames[i] == name) return DType(i);
  throw Error("unknown dtype '" + std::string(name) +
              "' (expected uint8, uint16, int16, uint32, int32, float32 or float64)");
}

int log2_tile_size(int size) {
  for (int k = 0; k <= 12; ++k)
    if (size == 1 << k) return k;
  const bool power_of_two = size > 0 && (size & (size - 1)) == 0;
  throw Error(
      "tile size " + std::to_string(size) +
      (power_of_two ? " is above the largest, 4096" : " is not a power of two in [1, 4096]"));
}

void check_overview_tile_size(int size) {
  if (size < 2 || size > 4096 || (size & (size - 1)) != 0)
    throw Error("tile size " + std::to_string(size) +
                " is not a power of two in [2, 4096] (a layer's overviews halve its tiles)");
}

template <typename T>
Tile<T> to_tile(const RawTile& raw, const double* nodata) {
  check_bytes(raw);
  auto out = Tile<T>::uninitialized(raw.size, raw.channels);  // every sample written below
  std::span<T> dst = out.data();
  visit_dtype(raw.dtype, [&]<typename S>(std::type_identity<S>) {
    for (size_t i = 0; i < dst.size(); ++i) {
      S s;
      std::memcpy(&s, raw.bytes.data() + i * sizeof(S), sizeof(S));
      if (std::is_floating_point_v<T> && nodata && is_nodata(s, *nodata))
        dst[i] = std::numeric_limits<T>::quiet_NaN();
      else
        dst[i] = cast_sample<T>(double(s));
    }
  });
  return out;
}

template <typename T>
RawTile from_tile(const Tile<T>& tile, DType dtype, const double* nodata) {
  RawTile raw{dtype, tile.size(), tile.channels(), {}};
  raw.bytes.resize(raw.sample_count() * dtype_size(dtype));
  visit_dtype(dtype, [&]<typename S>(std::type_identity<S>) {
    std::byte* dst = raw.bytes.data();
    for (int r = 0; r < tile.size(); ++r)
      for (int c = 0; c < tile.size(); ++c)
        for (int k = 0; k < tile.channels(); ++k, dst += sizeof(S)) {
          double v = double(tile.at(c, r, k));
          if (std::isnan(v) && nodata) v = *nodata;
          const S s = cast_sample<S>(v);
          std::memcpy(dst, &s, sizeof(S));
        }
  });
  return raw;
}

#define MAQUETTE_INSTANTIATE_TILE(T)                          \
  template Tile<T> to_tile<T>(const RawTile&, const double*); \
  template RawTile from_tile<T>(const Tile<T>&, DType, const double*);
MAQUETTE_INSTANTIATE_TILE(uint8_t)
MAQUETTE_INSTANTIATE_TILE(uint16_t)
MAQUETTE_INSTANTIATE_TILE(int16_t)
MAQUETTE_INSTANTIATE_TILE(uint32_t)
MAQUETTE_INSTANTIATE_TILE(int32_t)
MAQUETTE_INSTANTIATE_TILE(float)
MAQUETTE_INSTANTIATE_TILE(double)
#undef MAQUETTE_INSTANTIATE_TILE

}  // namespace maquette
