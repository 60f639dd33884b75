// whole_int: an integer read from text that holds nothing else.
#pragma once

#include <charconv>
#include <optional>
#include <string_view>
#include <system_error>

namespace maquette {

// The integer `text` spells in full (decimal digits, an optional leading '-'), or nullopt when
// `text` is empty, holds anything else (spaces, a '+', "2x") or a value beyond T's range.
template <class T>
std::optional<T> whole_int(std::string_view text) {
  T value{};
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (text.empty() || error != std::errc() || stop != end) return std::nullopt;
  return value;
}

}  // namespace maquette
