// The model of a step's params ("model": the document, or "model_file": its path), parsed once
// per distinct document: the runner calls an operator for every cell with the same params, and
// parsing 256-bin tables each time would cost as much as rendering a small tile. The cache only
// memoises a pure function of the document.
#pragma once

#include <memory>
#include <string>

#include "model.h"

namespace maquette::texture {

std::shared_ptr<const Model> model_from_params(const json& params, const std::string& op_name);

// What can be told when the pipeline is read (an operator's check_params): exactly one of
// "model" and "model_file", and an inline model that parses. A model_file is read when the step
// runs (an earlier step, texture.fit's "out", may write it).
void check_model_params(const json& params, const std::string& op_name);

}  // namespace maquette::texture
