// Validation of a step's "params" against its operator's JSON Schema (the draft 7 subset of
// OperatorSpec::params_schema: type, properties, required, enum, minimum, maximum, default, items,
// minItems, maxItems, additionalProperties false).
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

namespace maquette {

// Returns `params` with defaults filled in. Throws maquette::Error prefixed with `context` (e.g.
// "step 2 (terrain.derive)") naming the field path and the bad value:
//   step 2 (terrain.derive): params.z_factor: expected a number, got "abc"
nlohmann::json validate_params(const nlohmann::json& schema, const nlohmann::json& params,
                               const std::string& context);

// Schemas of bounded numeric parameters and of strings with a default, for operators'
// params_schema.
nlohmann::json number_param(double min, double max, double def, const std::string& description);
nlohmann::json integer_param(int64_t min, int64_t max, int64_t def, const std::string& description);
nlohmann::json string_param(const std::string& def, const std::string& description);

}  // namespace maquette
