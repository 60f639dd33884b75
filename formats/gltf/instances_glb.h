// One cell's instances (content.h: InstancesContent) as a GLB: each prototype's objects written
// once, each drawn once per instance of that prototype in the cell (EXT_mesh_gpu_instancing,
// in extensionsRequired: TRANSLATION, ROTATION, SCALE, and the instance's colour as `_COLOR_0`,
// RGBA8 normalized, multiplying the object's material as glTF's COLOR_0 does, base-colour texture
// included). The objects of one prototype share one set of instance accessors, and each of its
// materials is written once with its base-colour image (JPEG, PNG, or WebP through
// EXT_texture_webp, then required) and the content's sampler (gltf/glb_writer.h). Prototypes with
// no instance in the cell are left out.
//
// The frame is the content's east-north-up frame with glTF's axes (x east, y up, z south), named
// in the asset's extras as export_glb's frames are ({"origin": {"lon", "lat", "height"},
// "axes"}); positions are floats from the cell's origin, so they need no node translation.
//
// Prototype meshes are plain floats, not Draco-compressed. Measured on the built-ins, a GLB holding
// all three carries 113 KB of prototype geometry plain, 11.6 KB with Draco (draco_encoder -qp 14
// -qn 10 -cl 7), and 44 bytes per instance either way, so in cells of up to about 2,500
// instances the prototypes outweigh them and Draco would pay. It is not used yet because
// gltf/draco_encode.h quantizes a mesh from its minimum corner c, which becomes its node's
// translation, and a node's translation moves every instance with it; a Draco prototype needs c
// left out of the node and folded into each instance's translation instead (t + R S c).
#pragma once

#include <vector>

#include "content/content.h"

namespace maquette {

// `prototypes[i]` is the model of `content.prototypes[i]` (e.g. builtin_prototype(name)), in its
// own frame (x east, y north, z up, base at the origin), with its materials (checked as
// gltf/mesh_glb.h's encoder checks them: e.g. decoded from a model layer). Throws
// maquette::Error when there is no instance (glTF has no empty scene), the columns' sizes disagree
// with the count, an instance names a prototype index out of range, or a prototype is missing.
std::vector<char> instances_glb(const InstancesContent& content,
                                const std::vector<const MeshContent*>& prototypes);

}  // namespace maquette
