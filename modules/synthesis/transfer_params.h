// The params synthesis.transfer and synthesis.assess share: the exemplar (the painting, its
// classes, exclusions, altitude, scale, analysis) and how the target's land cover and DEM become
// the synthesis's guides (README: synthesis.transfer).
#pragma once

#include <array>
#include <bitset>
#include <cstdint>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "store/store.h"
#include "synthesis.h"

namespace maquette::synthesis {

// JSON Schema "properties" of those params: "painting", "labels", "classes", "exclusion",
// "exclude_classes", "landcover_classes", "altitude_range", "painting_altitude",
// "exemplar_scale", "k".
nlohmann::json exemplar_params_schema();

// JSON Schema "properties" of the further exemplars searched with the first (README:
// "Several paintings"): "exemplars" (an array, each item an object of "painting", "labels",
// "classes", "exclusion", "exclude_classes", "landcover_classes" and "painting_altitude", the
// first exemplar's fields, "painting" and "landcover_classes" required) and "harmonize" ("none",
// "reinhard", "histogram"; default "reinhard": harmonize.h).
nlohmann::json further_exemplars_schema();

// A further exemplar's painting classes as the combined exemplar's labels: each class its
// "landcover_classes" (`further`) gives a target value takes the first painting's class for that
// value (`first`, class_table), so that both paintings' pixels of a target class share one label;
// classes of one set in `further` (class_groups) go together; classes it does not name are not
// in the map (the caller excludes them). Throws maquette::Error naming `where` (e.g.
// "synthesis.transfer.exemplars[0]"), the field, the target value and the classes at fault when
// a target value is not in `first`, or one class (or set) of `further` serves target values the
// first painting gives different classes.
std::map<uint8_t, uint8_t> further_classes(const nlohmann::json& first,
                                           const nlohmann::json& further, const std::string& op,
                                           const std::string& where);

// synthesis.transfer's params schema: an object of exemplar_params_schema(),
// further_exemplars_schema() and synthesis_params_schema(), "painting" and "landcover_classes"
// required, no other field.
nlohmann::json transfer_params_schema();

// JSON Schema "properties" of the synthesis's weights and choices (SynthesisParams): "w_label",
// "w_altitude", "w_repetition", "coherence", "jitter", "seed".
nlohmann::json synthesis_params_schema();

// SynthesisParams from params validated against synthesis_params_schema() (defaults filled) and
// holding "landcover_classes"; throws maquette::Error as check_fields_without_effect and
// line_labels do (maquette-paint's params too).
SynthesisParams synthesis_params(const nlohmann::json& params);

// Throws maquette::Error naming `op` and the field when a field is given that what it weighs
// does not read: with "patch_passes" 0, "line_classes" not empty, "patch_search", "patch_edges"
// or "patch_balance" (those present) other than its default; with "w_spread" 0, "spread_typical"
// (present) other than 1.
void check_fields_without_effect(const nlohmann::json& params, const std::string& op);

// The params (validated, defaults filled in) of the synthesis.transfer that made `layer`, from
// its provenance; none when the layer was made otherwise, or by params this version no longer
// reads.
std::optional<nlohmann::json> transfer_params_of(const LayerInfo& layer);

// The target labels of "line_classes": each painting class as the table gives it (its set's
// smallest class, class_groups). Throws maquette::Error naming `op` when a class is in no value
// of "landcover_classes" (no target pixel has it): the field would do nothing.
std::bitset<256> line_labels(const nlohmann::json& params, const std::string& op);

// Target land-cover value -> painting class, from "landcover_classes" (each value a painting
// class, or an array of them taken as one: the array's smallest class stands for the set, see
// class_groups). Throws maquette::Error naming `op`, the field and the key or value at fault.
std::map<int, uint8_t> class_table(const nlohmann::json& table, const std::string& op);

// The painting classes "landcover_classes" takes as one: class -> the smallest class of its set
// (the exemplar's pixels are relabelled so, so that a target class may take any of its set's
// pixels and label consistency counts through the table). Classes in no array map to
// themselves. Throws maquette::Error naming `op` and the key when a class is in two different
// sets.
std::map<uint8_t, uint8_t> class_groups(const nlohmann::json& table, const std::string& op);

// Throws maquette::Error naming `op`, the value and the layer when a land-cover value of `table`
// is no sample the layer can hold (300 in a uint8 layer): that entry would match no pixel, a typo
// passed in silence.
void check_table_fits(const std::map<int, uint8_t>& table, const LayerInfo& landcover,
                      const std::string& op);

// The painting class that land-cover sample `value` asks for: kUnknownLabel when it is NaN or
// not in the table.
uint8_t painting_class(const std::map<int, uint8_t>& table, float value);

// "altitude_range" [low, high] metres when given; throws maquette::Error naming `op` unless
// high > low, and when one part of the altitude guide comes without the others (the range, the
// `dem` input, `dem_given`, and the painting's "painting_altitude"): never silently dropped.
std::optional<std::array<double, 2>> altitude_range(const nlohmann::json& params,
                                                    const std::string& op, bool dem_given);

// params[field] as [low, high] with high > low (and low > 0 when `positive`); throws
// maquette::Error naming `op`, the field and the value otherwise.
std::array<double, 2> range_param(const nlohmann::json& params, const std::string& field,
                                  const std::string& op, bool positive = false);

// A DEM height mapped onto the range: 0 at low, 1 at high, clamped (NaN stays NaN).
float altitude_guide(float metres, const std::array<double, 2>& range);

}  // namespace maquette::synthesis
