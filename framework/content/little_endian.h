// Little-endian fields of content blobs, written and read byte by byte whatever the host's order.
#pragma once

#include <bit>
#include <cstdint>
#include <string>
#include <type_traits>

namespace maquette::le {

// The unsigned integer of T's width: floats are written as their bits, NaN payloads included.
template <typename T>
using Bits =
    std::conditional_t<sizeof(T) == 1, uint8_t,
                       std::conditional_t<sizeof(T) == 2, uint16_t,
                                          std::conditional_t<sizeof(T) == 4, uint32_t, uint64_t>>>;

template <typename T>
void put(char* out, T value) {
  const auto bits = std::bit_cast<Bits<T>>(value);
  for (size_t b = 0; b < sizeof(T); ++b) out[b] = char(uint8_t(bits >> (8 * b)));
}

template <typename T>
void append(std::string& out, T value) {
  char bytes[sizeof(T)];
  put(bytes, value);
  out.append(bytes, sizeof(T));
}

template <typename T>
T get(const char* in) {
  Bits<T> bits = 0;
  for (size_t b = 0; b < sizeof(T); ++b) bits |= Bits<T>(uint8_t(in[b])) << (8 * b);
  return std::bit_cast<T>(bits);
}

}  // namespace maquette::le
