// What the instances tests share: a seeded forest of the built-in prototypes, the GLB of a content
// with its built-in models, and the Khronos glTF validator's verdict on a file.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "content/content.h"
#include "gpu_instancing_check.h"

namespace maquette::test {

// `count` instances of the three built-in prototypes, seeded: positions within 500 m of the
// origin, turned about the vertical by any angle and tilted a little, scaled 1 to 20 m (a little
// unevenly), colours near white.
InstancesContent forest(size_t count, uint32_t seed);

// instances_glb of `content`, whose prototypes are all built in.
std::vector<char> builtin_instances_glb(const InstancesContent& content);

// Writes `bytes` to `path` (its folder created).
void write_bytes(const std::string& path, const std::vector<char>& bytes);

// The validator's report of the errors in the .glb files under `dir` ("" when none), or nullopt
// when the validator is not installed (no npm at configure time).
std::optional<std::string> validator_errors(const std::string& dir);

}  // namespace maquette::test
