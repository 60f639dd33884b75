// Validation of a step's "params" against its operator's JSON Schema (the draft 7 subset of
// OperatorSpec::params_schema: type, properties, required, enum, minimum, maximum, default, items,
// minItems, maxItems, additionalProperties false).
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
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

// What a string param names (the schema keyword "names"), checked by the planner (run_plan.h)
// before anything runs, a dry run too:
// - Artifact, Layer: an artifact or a layer the step reads from the store or an earlier step's
//   output (by name, as climate.regionalize's "fit"): it must be there, and no output of the step
//   may have its name (the step would replace what it reads);
// - OutputFile: a file the operator writes, relative to the working directory: refused when it is
//   the pipeline's store or file (it would replace it).
// An empty value names nothing. `def`: the default, none for a required param.
enum class NamedKind { Artifact, Layer, OutputFile };
nlohmann::json named_param(NamedKind kind, const std::optional<std::string>& def,
                           const std::string& description);
// The kind a param's schema names, if it names one.
std::optional<NamedKind> named_kind(const nlohmann::json& param_schema);

}  // namespace maquette
