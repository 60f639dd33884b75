// Outside models (for `maquette ingest --as model`): a .glb, or a .gltf whose buffers
// and images are files beside it or data URIs, plain or Draco-compressed, read into MeshContent.
// Every node of the default scene (all root nodes when there is none) is drawn with its transforms
// composed (matrix or translation, rotation, scale), in double; each primitive a node draws is one
// object, in the order nodes are visited (depth first, children in their order). Positions and
// normals go from glTF's y-up axes to the content's x east, y north, z up (gltf/enu_axes.h): the
// model's origin is the content's, its up is up.
#pragma once

#include <string>

#include "content/content.h"

namespace maquette {

// Throws maquette::Error naming the file and the fault: not glTF (bad magic, not JSON), no mesh,
// a buffer declaring more than 1 GiB (refused before it is read), accessors or indices out of
// range, a primitive that is not triangles, a missing buffer or image file.
MeshContent read_gltf_model(const std::string& path);

}  // namespace maquette
