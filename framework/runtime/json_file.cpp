#include "runtime/json_file.h"

#include <fstream>
#include <sstream>

#include "core/error.h"

namespace maquette {

nlohmann::json parse_json(std::string_view text, const std::string& source) {
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    // e.what() is "[json.exception.parse_error.101] parse error at line 3, column 5: ...".
    std::string what = e.what();
    if (const size_t end = what.find("] "); what.starts_with("[json.") && end != std::string::npos)
      what = what.substr(end + 2);
    throw Error(source + ": " + what);
  }
}

std::string read_text_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error("cannot read " + path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace maquette
