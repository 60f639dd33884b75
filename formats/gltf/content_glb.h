// A cell's 3D content (gltf/content_layer.h) as a GLB in the export's frame: a mesh, or a
// prototype mesh drawn once per instance (EXT_mesh_gpu_instancing: TRANSLATION, ROTATION,
// SCALE; each instance upright on the ellipsoid at its point, turned by its heading). Meshes are
// Draco-compressed (positions quantized to bits.position over their extent); prototypes (a few
// dozen vertices) and instance attributes stay plain floats.
#pragma once

#include <array>
#include <vector>

#include "gltf/content_layer.h"
#include "gltf/draco_encode.h"
#include "gltf/local_frame.h"

namespace maquette {

struct ContentGlb {
  std::vector<char> bytes;
  // What the content covers: west, south, east, north (radians), min, max height (metres).
  std::array<double, 6> region{};
};

ContentGlb content_glb(const ContentTile& content, const LocalFrame& frame,
                       const QuantizationBits& bits, bool draco, const std::string& name);

}  // namespace maquette
