// Reading JSON documents with errors that name the source, line, column and field, and quoting
// values in error messages.
#pragma once

#include <concepts>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

namespace maquette {

// Deeper nesting is refused: no document the program reads needs it, and printing or copying a
// value recurses once per level.
inline constexpr int kMaxJsonDepth = 128;

// Throws maquette::Error "SOURCE: parse error at line L, column C: ...", and naming the field
// (as steps[0].params.x) for a number out of double's range or nesting deeper than
// kMaxJsonDepth.
nlohmann::json parse_json(std::string_view text, const std::string& source);
// Throws maquette::Error naming the file and why it cannot be read (missing, permission).
std::string read_text_file(const std::string& path);
// read_text_file, then parse_json.
nlohmann::json read_json_file(const std::string& path);

// A value quoted in an error message: its text up to 60 characters, or the first 60 and "...
// (N characters)", so that a huge bad value does not flood the message.
std::string excerpt(std::string_view text);
// A JSON value's text, shortened (a template so that strings are not taken for JSON values).
template <typename Json>
requires std::same_as<Json, nlohmann::json> std::string excerpt(const Json& value) {
  return excerpt(std::string_view(value.dump()));
}

}  // namespace maquette
