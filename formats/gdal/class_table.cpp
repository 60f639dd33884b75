#include "gdal/class_table.h"

#include <gdal_priv.h>

#include <cstdio>
#include <regex>

#include "core/error.h"
#include "core/json_file.h"

namespace maquette {

nlohmann::json band_class_table(GDALRasterBand& band) {
  char** names = band.GetCategoryNames();
  const int named = CSLCount(names);
  const GDALColorTable* colours = band.GetColorTable();
  nlohmann::json table = nlohmann::json::object();
  const int n = named > 0 ? named : colours ? colours->GetColorEntryCount() : 0;
  for (int i = 0; i < n; ++i) {
    nlohmann::json entry = nlohmann::json::object();
    if (named > 0) {
      if (!names[i] || !*names[i]) continue;
      entry["name"] = names[i];
    }
    if (colours && i < colours->GetColorEntryCount()) {
      const GDALColorEntry* c = colours->GetColorEntry(i);
      if (named == 0 && c->c4 == 0) continue;
      char hex[8];
      std::snprintf(hex, sizeof hex, "#%02x%02x%02x", c->c1 & 0xff, c->c2 & 0xff, c->c3 & 0xff);
      entry["color"] = hex;
    }
    table[std::to_string(i)] = entry;
  }
  return table;
}

nlohmann::json parse_class_table(const std::string& text_or_path) {
  const bool inline_json = !text_or_path.empty() && text_or_path.front() == '{';
  const std::string where = inline_json ? "--classes" : text_or_path;
  const nlohmann::json j =
      parse_json(inline_json ? text_or_path : read_text_file(text_or_path), where);
  if (!j.is_object()) throw Error(where + ": expected an object of classes");
  static const std::regex kColour("#[0-9a-fA-F]{6}"), kKey("-?[0-9]+");
  for (const auto& [key, value] : j.items()) {
    if (!std::regex_match(key, kKey))
      throw Error(where + ": class key '" + excerpt(key) + "' is not an integer value");
    if (!value.is_object()) throw Error(where + ": class " + key + ": expected an object");
    if (value.contains("name") && !value["name"].is_string())
      throw Error(where + ": class " + key + ".name: expected a string");
    if (value.contains("color") && (!value["color"].is_string() ||
                                    !std::regex_match(value["color"].get<std::string>(), kColour)))
      throw Error(where + ": class " + key + ".color: expected \"#rrggbb\", got " +
                  excerpt(value["color"]));
  }
  return j;
}

}  // namespace maquette
