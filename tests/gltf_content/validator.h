// The Khronos glTF validator (npm gltf-validator, installed by tests/tiles3d's build) on one GLB.
#pragma once

#include <optional>
#include <string>

namespace maquette::test {

struct ValidatorReport {
  int errors = 0, warnings = 0;
  std::string messages;  // each error and warning: code, message, JSON pointer
};

// Nothing when the validator is not installed (npm absent at configure time).
std::optional<ValidatorReport> validate_glb(const std::string& path);

}  // namespace maquette::test
