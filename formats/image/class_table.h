// Class tables of categorical layers (land cover), as ingest records them in the layer's
// provenance: provenance["classes"] = {"<value>": {"name": "...", "color": "#rrggbb"}}.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>

#include "store/store.h"

namespace maquette {

using Rgb = std::array<uint8_t, 3>;

struct ClassEntry {
  std::string name;
  std::optional<Rgb> colour;
};
using ClassTable = std::map<int64_t, ClassEntry>;

// The layer's class table, empty when it has none; throws maquette::Error naming the layer and
// the entry for a non-integer value or a colour that is not "#rrggbb".
ClassTable class_table(const LayerInfo& info);

// The class's own colour, else a fixed qualitative palette colour chosen by the value.
Rgb class_colour(const ClassTable& table, int64_t value);

}  // namespace maquette
