// Reading JSON documents with errors that name the source, line and column.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

namespace maquette {

// Throws maquette::Error "SOURCE: parse error at line L, column C: ...".
nlohmann::json parse_json(std::string_view text, const std::string& source);
// Throws maquette::Error naming the file when it cannot be read.
std::string read_text_file(const std::string& path);

}  // namespace maquette
