// Land-cover class tables: {"11": {"name": "Open water", "color": "#466b9f"}, ...}.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

class GDALRasterBand;

namespace maquette {

// The class table of a band: category names and colour table entries (without names, the
// opaque colour entries; with names, the named entries). An empty object when it has neither.
nlohmann::json band_class_table(GDALRasterBand& band);

// A --classes value: inline JSON (starting with '{') or a JSON file. Keys must be integers,
// values objects with an optional "name" string and an optional "color" "#rrggbb"; throws
// maquette::Error naming the key and field.
nlohmann::json parse_class_table(const std::string& text_or_path);

}  // namespace maquette
