#include "transfer_params.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include "core/error.h"
#include "core/samples.h"
#include "core/whole_int.h"
#include "exemplar.h"
#include "patch_pass.h"
#include "runtime/params_schema.h"

namespace maquette::synthesis {

nlohmann::json exemplar_params_schema() {
  using json = nlohmann::json;
  return {
      {"painting",
       {{"type", "string"},
        {"description",
         "the painting (8-bit or 16-bit grey, RGB(A) or palette image; transparent pixels never "
         "copied; relative to the working directory)"}}},
      {"labels",
       {{"type", "string"},
        {"description",
         "hand-drawn class image (one 8-bit band, the painting's size, classes 0..254; or "
         "polygons in painting pixels, x right and y down, with an integer \"class\", the later "
         "drawn over the earlier, e.g. GeoJSON); else classes by colour"}}},
      {"classes",
       {{"type", "integer"},
        {"minimum", 1},
        {"maximum", 254},
        {"default", 6},
        {"description", "k of the automatic segmentation by colour (k-means in CIELAB)"}}},
      {"exclusion",
       {{"type", "string"},
        {"description", "mask of the painting never copied (non-zero: excluded)"}}},
      {"exclude_classes",
       {{"type", "array"},
        {"items", {{"type", "integer"}, {"minimum", 0}, {"maximum", 254}}},
        {"default", json::array()},
        {"description", "painting classes never copied (sky, frame)"}}},
      {"landcover_classes",
       {{"type", "object"},
        {"description",
         "target land-cover value (a string key) -> painting class, or an array of painting "
         "classes taken as one (a class in one set only); other values match any class; each class "
         "named must have pixels to copy"}}},
      {"altitude_range",
       {{"type", "array"},
        {"items", {{"type", "number"}}},
        {"description", "[low, high] metres of the DEM mapped to altitude 0..1"}}},
      {"painting_altitude",
       {{"type", "string"},
        {"description",
         "the painting's altitude: a grey image (its size), or \"rows\" (high at the top)"}}},
      {"exemplar_scale",
       {{"type", "integer"},
        {"enum", {1, 2, 4, 8}},
        {"default", 2},
        {"description", "painting pixels per exemplar pixel (a side): coarser strokes, faster"}}},
      {"k",
       {{"type", "integer"},
        {"minimum", 1},
        {"maximum", 8},
        {"default", 2},
        {"description", "k-coherence candidates per neighbour"}}}};
}

nlohmann::json further_exemplars_schema() {
  using json = nlohmann::json;
  const json first = exemplar_params_schema();
  json item = {{"type", "object"},
               {"additionalProperties", false},
               {"required", {"painting", "landcover_classes"}},
               {"properties", json::object()}};
  for (const char* field : {"painting", "labels", "classes", "exclusion", "exclude_classes",
                            "landcover_classes", "painting_altitude"})
    item["properties"][field] = first.at(field);
  item["properties"]["landcover_classes"]["description"] =
      "target land-cover value -> this painting's class (or set of classes); every value must be "
      "in the first painting's table; classes not named here are never copied";
  return {{"exemplars",
           {{"type", "array"},
            {"items", item},
            {"description",
             "further paintings searched with the first, each with its own class image, "
             "exclusions, class table and altitude (given for all paintings or none)"}}},
          {"harmonize",
           {{"type", "string"},
            {"enum", {"none", "reinhard", "histogram"}},
            {"default", "reinhard"},
            {"description",
             "each target class's colours of the further paintings matched to the first's, in "
             "CIELAB: mean and deviation (reinhard) or histogram, or none"}}}};
}

nlohmann::json synthesis_params_schema() {
  using json = nlohmann::json;
  const auto weight = [](double fallback, const char* description) {
    return json{
        {"type", "number"}, {"minimum", 0}, {"default", fallback}, {"description", description}};
  };
  const auto whole = [](int low, std::optional<int> high, int fallback, const char* description) {
    json out = {{"type", "integer"}, {"minimum", low}, {"default", fallback}};
    if (high) out["maximum"] = *high;
    out["description"] = description;
    return out;
  };
  return {
      {"w_label", weight(2.0, "weight of the 3 x 3 neighbourhood's label mismatch")},
      {"w_altitude", weight(1.0,
                            "weight of the altitude mismatch (with dem, altitude_range and "
                            "painting_altitude)")},
      {"w_repetition", weight(0.3, "penalty on a source patch used again nearby")},
      {"w_usage", weight(0.05, "weight of the exemplar pixels' measured over-use")},
      {"w_spread", weight(0.15,
                          "weight of each block's preference among the exemplar's "
                          "regions")},
      {"spread_typical",
       {{"type", "number"},
        {"minimum", 0},
        {"maximum", 1},
        {"default", 1.0},
        {"description",
         "the central share of each class's exemplar regions, by lightness, that blocks may "
         "prefer (w_spread): below 1 a pale or dark patch of the painting is never preferred, so "
         "strong block preferences paint no blotches of it"}}},
      {"coherence", weight(0.5,
                           "a candidate that is no neighbour's source shifted costs 1 + "
                           "coherence times more")},
      {"jitter", whole(0, 4, 1, "jitter of the exemplar coordinates at each level, pixels")},
      {"patch_passes", whole(0, kMaxPatchPasses, 0,
                             "passes at the finest level taking, among the copies under way "
                             "around each pixel, the one whose 5 x 5 patch fits best")},
      {"patch_balance", weight(0.0, "the patch passes' histogram balance, an exponent (0: none)")},
      {"patch_search", whole(0, kMaxPatchSearch, 0,
                             "places the patch passes draw around a pixel's source where the "
                             "target's classes meet")},
      {"patch_edges", whole(0, kMaxPatchEdges, 0,
                            "places the patch passes draw where the target's classes meet from "
                            "the painting's own edges between the two classes")},
      {"line_classes",
       {{"type", "array"},
        {"items", {{"type", "integer"}, {"minimum", 0}, {"maximum", 254}}},
        {"default", json::array()},
        {"description",
         "painting classes of lines (roads, tracks, streams): where one is thinner than the "
         "patch passes' 5 x 5 window its pixels keep their source through them, so the lines stay "
         "dark and whole (with patch_passes)"}}},
      {"vote_radius", whole(0, kVoteRadius, 1,
                            "radius of the finest level's vote among overlapping patches "
                            "(0: none)")},
      {"vote_balance", weight(0.0, "the vote's histogram balance, an exponent (0: none)")},
      {"seed", whole(0, std::nullopt, 0, "of the jitter and the random candidates")}};
}

nlohmann::json transfer_params_schema() {
  nlohmann::json schema = {{"type", "object"},
                           {"additionalProperties", false},
                           {"required", {"painting", "landcover_classes"}},
                           {"properties", exemplar_params_schema()}};
  schema["properties"].update(further_exemplars_schema());
  schema["properties"].update(synthesis_params_schema());
  return schema;
}

SynthesisParams synthesis_params(const nlohmann::json& params) {
  SynthesisParams sp;
  sp.w_label = params.at("w_label").get<double>();
  sp.w_altitude = params.at("w_altitude").get<double>();
  sp.w_repetition = params.at("w_repetition").get<double>();
  sp.w_usage = params.at("w_usage").get<double>();
  sp.w_spread = params.at("w_spread").get<double>();
  sp.spread_typical = params.at("spread_typical").get<double>();
  sp.coherence = params.at("coherence").get<double>();
  sp.jitter = params.at("jitter").get<int>();
  sp.patch_passes = params.at("patch_passes").get<int>();
  sp.patch_balance = params.at("patch_balance").get<double>();
  sp.patch_search = params.at("patch_search").get<int>();
  sp.patch_edges = params.at("patch_edges").get<int>();
  sp.vote_radius = params.at("vote_radius").get<int>();
  sp.vote_balance = params.at("vote_balance").get<double>();
  sp.seed = params.at("seed").get<uint64_t>();
  check_fields_without_effect(params, "synthesis.transfer");
  sp.line_classes = line_labels(params, "synthesis.transfer");
  return sp;
}

void check_fields_without_effect(const nlohmann::json& params, const std::string& op) {
  if (params.contains("spread_typical") && params.at("spread_typical").get<double>() != 1 &&
      params.at("w_spread").get<double>() == 0)
    throw Error(op + ".spread_typical: " + params.at("spread_typical").dump() +
                " chooses the regions the blocks prefer, and w_spread is 0: give w_spread or "
                "leave out spread_typical");
  if (params.at("patch_passes").get<int>() != 0) return;
  if (!params.at("line_classes").empty())
    throw Error(op + ".line_classes " + params.at("line_classes").dump() +
                " keep lines through the patch passes, and patch_passes is 0: give patch_passes "
                "or leave line_classes out");
  const nlohmann::json schema = synthesis_params_schema();
  for (const char* field : {"patch_search", "patch_edges", "patch_balance"})
    if (params.contains(field) && params.at(field) != schema.at(field).at("default"))
      throw Error(op + "." + field + ": " + params.at(field).dump() +
                  " is a field of the patch passes, and patch_passes is 0: give patch_passes or "
                  "leave out " +
                  field);
}

std::bitset<256> line_labels(const nlohmann::json& params, const std::string& op) {
  std::bitset<256> out;
  const auto classes = params.at("line_classes").get<std::vector<int>>();
  if (classes.empty()) return out;
  const auto groups = class_groups(params.at("landcover_classes"), op);
  for (const int c : classes) {
    const auto it = groups.find(uint8_t(c));
    if (it == groups.end())
      throw Error(op + ".line_classes: painting class " + std::to_string(c) +
                  " is in no value of landcover_classes: no target pixel has it");
    out.set(it->second);
  }
  return out;
}

namespace {

// The painting classes of one "landcover_classes" value: an integer or a non-empty array of them,
// each 0..254, sorted.
std::vector<uint8_t> table_classes(const nlohmann::json& value, const std::string& where) {
  const auto fail = [&] {
    return Error(where + ": " + value.dump() +
                 " is not a painting class 0..254 nor a non-empty array of them");
  };
  const auto one = [&](const nlohmann::json& v) {
    if (!v.is_number_integer() || v.get<int>() < 0 || v.get<int>() >= kUnknownLabel) throw fail();
    return uint8_t(v.get<int>());
  };
  std::vector<uint8_t> out;
  if (value.is_array())
    for (const auto& v : value) out.push_back(one(v));
  else
    out.push_back(one(value));
  if (out.empty()) throw fail();
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// Every table entry's classes, by target value; throws on an empty table (every pixel would take
// any class) and on a key that is no integer or a negative one.
std::map<int, std::vector<uint8_t>> table_entries(const nlohmann::json& table,
                                                  const std::string& op) {
  if (table.empty())
    throw Error(op + ".landcover_classes: {}: map at least one land-cover value to a painting " +
                "class (with none, every pixel would take any class)");
  std::map<int, std::vector<uint8_t>> out;
  for (const auto& [key, value] : table.items()) {
    const std::optional<int> target = whole_int<int>(key);
    if (!target)
      throw Error(op + ".landcover_classes: key '" + key + "' is not an integer class value");
    if (*target < 0)
      throw Error(op + ".landcover_classes: key '" + key +
                  "': land-cover values are 0 or more (it would match no pixel)");
    out[*target] = table_classes(value, op + ".landcover_classes." + key);
  }
  return out;
}

}  // namespace

std::map<int, uint8_t> class_table(const nlohmann::json& table, const std::string& op) {
  std::map<int, uint8_t> out;
  for (const auto& [target, classes] : table_entries(table, op)) out[target] = classes.front();
  return out;
}

std::map<uint8_t, uint8_t> class_groups(const nlohmann::json& table, const std::string& op) {
  std::map<uint8_t, uint8_t> out;
  std::map<uint8_t, std::vector<uint8_t>> group_of;
  for (const auto& [target, classes] : table_entries(table, op))
    for (const uint8_t c : classes) {
      const auto [it, fresh] = group_of.emplace(c, classes);
      if (!fresh && it->second != classes)
        throw Error(op + ".landcover_classes." + std::to_string(target) + ": painting class " +
                    std::to_string(c) + " is in two different sets of classes (" +
                    nlohmann::json(it->second).dump() + " and " + nlohmann::json(classes).dump() +
                    "): a class is in one set, given whole wherever it appears");
      out[c] = classes.front();
    }
  return out;
}

std::map<uint8_t, uint8_t> further_classes(const nlohmann::json& first,
                                           const nlohmann::json& further, const std::string& op,
                                           const std::string& where) {
  const auto first_table = class_table(first, op);
  const std::string field = where + ".landcover_classes";
  const auto groups = class_groups(further, where);
  std::map<uint8_t, std::pair<uint8_t, int>> label_of;  // set -> first's class, a target value
  for (const auto& [target, set] : class_table(further, where)) {
    const auto it = first_table.find(target);
    if (it == first_table.end())
      throw Error(field + "." + std::to_string(target) + ": target value " +
                  std::to_string(target) +
                  " is not in the first painting's landcover_classes: a further painting serves "
                  "the first's target classes");
    const auto [seen, fresh] = label_of.emplace(set, std::pair{it->second, target});
    if (!fresh && seen->second.first != it->second)
      throw Error(field + "." + std::to_string(target) + ": painting class " + std::to_string(set) +
                  " serves target values " + std::to_string(seen->second.second) + " and " +
                  std::to_string(target) + ", which the first painting gives different classes (" +
                  std::to_string(seen->second.first) + " and " + std::to_string(it->second) +
                  "): one class of a further painting serves one class of the first");
  }
  std::map<uint8_t, uint8_t> out;
  for (const auto& [c, set] : groups) out[c] = label_of.at(set).first;
  return out;
}

void check_table_fits(const std::map<int, uint8_t>& table, const LayerInfo& landcover,
                      const std::string& op) {
  const auto [low, high] = visit_dtype(landcover.dtype, []<typename T>(std::type_identity<T>) {
    return std::pair{double(std::numeric_limits<T>::lowest()),
                     double(std::numeric_limits<T>::max())};
  });
  for (const auto& [value, label] : table)
    if (value < low || value > high)
      throw Error(op + ".landcover_classes: land-cover value " + std::to_string(value) +
                  " is outside what layer '" + landcover.name + "' holds (" +
                  std::string(dtype_name(landcover.dtype)) + ", " + std::to_string(int64_t(low)) +
                  ".." + std::to_string(int64_t(high)) +
                  "): no pixel would take its class");  // an integer type: a float holds any key
}

uint8_t painting_class(const std::map<int, uint8_t>& table, float value) {
  const auto it = std::isnan(value) ? table.end() : table.find(int(std::lround(value)));
  return it == table.end() ? kUnknownLabel : it->second;
}

std::optional<std::array<double, 2>> altitude_range(const nlohmann::json& params,
                                                    const std::string& op, bool dem_given) {
  if (params.contains("altitude_range") != dem_given)
    throw Error(op + (dem_given ? ": inputs.dem is given without altitude_range (the heights"
                                  " mapped to the guide's 0..1): give both or neither"
                                : ".altitude_range is given without inputs.dem: give both or"
                                  " neither"));
  // The painting's altitude is the guide's other half: without it the target's is never
  // matched, and it alone matches nothing.
  if (params.contains("painting_altitude") != dem_given)
    throw Error(op + (dem_given ? ": inputs.dem and altitude_range are given without "
                                  "painting_altitude (the painting's altitude: a grey image or "
                                  "\"rows\"): give the three or none"
                                : ".painting_altitude is given without inputs.dem and "
                                  "altitude_range: give the three or none"));
  if (!dem_given) {
    // A weight of a guide that is absent weighs nothing: said rather than ignored (the params
    // come with their defaults filled in, so only a weight other than the default is seen).
    const nlohmann::json unset = synthesis_params_schema().at("w_altitude").at("default");
    if (params.contains("w_altitude") && params.at("w_altitude") != unset)
      throw Error(op + ".w_altitude " + params.at("w_altitude").dump() +
                  " weighs the altitude guide, which is not given: give inputs.dem, "
                  "altitude_range and painting_altitude, or leave w_altitude out");
    return std::nullopt;
  }
  return range_param(params, "altitude_range", op);
}

std::array<double, 2> range_param(const nlohmann::json& params, const std::string& field,
                                  const std::string& op, bool positive) {
  const auto range = params.at(field).get<std::vector<double>>();
  if (range.size() != 2 || !(range[1] > range[0]) || (positive && !(range[0] > 0)))
    throw Error(op + "." + field + ": expected [low, high] with " +
                (positive ? "0 < low < high" : "high > low") + ", got " + params.at(field).dump());
  return {range[0], range[1]};
}

float altitude_guide(float metres, const std::array<double, 2>& range) {
  return float(std::clamp((double(metres) - range[0]) / (range[1] - range[0]), 0.0, 1.0));
}

std::optional<nlohmann::json> transfer_params_of(const LayerInfo& layer) {
  const nlohmann::json& made_by = layer.provenance;
  if (made_by.value("operator", "") != "synthesis.transfer" || !made_by.contains("params"))
    return std::nullopt;
  try {
    return validate_params(transfer_params_schema(), made_by.at("params"), "synthesis.transfer");
  } catch (const Error&) {
    return std::nullopt;
  }
}

}  // namespace maquette::synthesis
