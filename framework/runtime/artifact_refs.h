// Artifacts in a step's params: {"$artifact": "NAME"} anywhere in "params" stands for the JSON
// artifact NAME of the store (written by an earlier step, e.g. texture.fit's model, or already
// there), {"$artifact": "NAME", "pointer": "/centres"} for a part of it (a JSON Pointer, RFC
// 6901). Such a value is validated against the operator's schema once the runner has pasted the
// artifact in, just before the step runs.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "store/store.h"

namespace maquette {

// {"$artifact": "NAME"} (a non-empty string), optionally with "pointer" (a string), and nothing
// else.
bool is_artifact_ref(const nlohmann::json& value);

// The artifacts `params` refers to: (field path as in messages, "params.model", artifact name).
std::vector<std::pair<std::string, std::string>> artifact_refs(const nlohmann::json& params);

// `params` with every reference replaced by the artifact's JSON document (or the part its pointer
// designates). Throws maquette::Error prefixed with `context` naming the field when the artifact
// is missing or not JSON, or the pointer is malformed or designates nothing.
nlohmann::json paste_artifacts(const nlohmann::json& params, const Store& store,
                               const std::string& context);

}  // namespace maquette
