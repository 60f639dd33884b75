// A checker of EXT_mesh_gpu_instancing, which the Khronos glTF validator does not check: for every
// node using it, the node has a mesh; TRANSLATION and SCALE are VEC3 floats, ROTATION is VEC4 of
// floats or normalized signed bytes or shorts, other attributes are named with a leading "_"; all
// attributes have the same count; each accessor lies within its bufferView, each bufferView within
// the GLB's BIN chunk; rotations are unit quaternions (| |q| - 1 | <= 1e-3), translations finite,
// scales finite and non-zero.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace maquette::test {

// A GLB's two chunks.
struct GlbChunks {
  nlohmann::json json;
  std::string bin;
};

// Throws std::runtime_error when `bytes` is not a GLB (header, chunk types and lengths).
GlbChunks split_glb(std::string_view bytes);

// Accessor `index`'s values, component by component (normalized integers mapped as glTF does);
// throws std::runtime_error when it does not lie within the BIN chunk.
std::vector<double> accessor_values(const GlbChunks& glb, size_t index);

// What is wrong with the glTF's EXT_mesh_gpu_instancing, one sentence naming the node, attribute,
// accessor and instance at fault per problem; empty when nothing is.
std::vector<std::string> gpu_instancing_problems(const GlbChunks& glb);

}  // namespace maquette::test
