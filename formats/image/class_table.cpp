#include "image/class_table.h"

#include <charconv>
#include <string_view>

#include "core/error.h"
#include "core/whole_int.h"

namespace maquette {
namespace {

// Paul Tol's "muted" qualitative scheme plus grey: distinct for colour-blind readers.
constexpr Rgb kPalette[] = {{51, 34, 136},  {136, 204, 238}, {68, 170, 153},  {17, 119, 51},
                            {153, 153, 51}, {221, 204, 119}, {204, 102, 119}, {136, 34, 85},
                            {170, 68, 153}, {221, 221, 221}};

std::optional<Rgb> parse_colour(std::string_view text) {
  if (text.size() != 7 || text[0] != '#') return std::nullopt;
  Rgb rgb{};
  for (size_t k = 0; k < 3; ++k) {
    const char* first = text.data() + 1 + 2 * k;
    if (std::from_chars(first, first + 2, rgb[k], 16).ptr != first + 2) return std::nullopt;
  }
  return rgb;
}

}  // namespace

ClassTable class_table(const LayerInfo& info) {
  ClassTable table;
  const auto it = info.provenance.find("classes");
  if (it == info.provenance.end()) return table;
  const std::string where = "layer '" + info.name + "' provenance.classes";
  if (!it->is_object()) throw Error(where + " is not an object");
  for (const auto& [key, entry] : it->items()) {
    const std::optional<int64_t> value = whole_int<int64_t>(key);
    if (!value) throw Error(where + ": class value '" + key + "' is not an integer");
    ClassEntry& c = table[*value];
    if (!entry.is_object()) continue;
    c.name = entry.value("name", "");
    if (entry.contains("color")) {
      const std::string colour =
          entry["color"].is_string() ? entry["color"].get<std::string>() : "";
      c.colour = parse_colour(colour);
      if (!c.colour) throw Error(where + "[" + key + "].color is not \"#rrggbb\"");
    }
  }
  return table;
}

Rgb class_colour(const ClassTable& table, int64_t value) {
  if (const auto it = table.find(value); it != table.end() && it->second.colour)
    return *it->second.colour;
  constexpr int64_t n = std::size(kPalette);
  return kPalette[((value % n) + n) % n];
}

}  // namespace maquette
