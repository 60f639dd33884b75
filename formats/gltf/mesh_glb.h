// The payload of a mesh layer's blob (content/content_blob.h): the cell's MeshContent as one GLB
// (formats/gltf/README.md, "Mesh layers"):
// - frame: the content's east-north-up frame with glTF's y-up axes, glTF (x, y, z) = (east, up,
//   -north), as the exports write (gltf/local_frame.h); the origin itself stays in the envelope;
// - one node and one mesh, one primitive per group of objects sharing a material and an
//   attribute set (fewer primitives draw faster than one per object), Draco-compressed
//   (KHR_draco_mesh_compression, required): positions quantized to a step of at most
//   `position_error` (bits from the primitive's extent), normals and uvs to their bits;
// - PBR metallic-roughness materials, base-colour images embedded as they were given
//   (bufferView and mimeType; WebP through EXT_texture_webp, then required); objects without a
//   material (-1) get one more, the last: "default grey" (base colour 0.6, not metallic,
//   roughness 1, extras {"maquette_default_material": true}), not glTF's default material, a
//   white metal that three.js draws black where its sun does not reach; decode_mesh_glb reads
//   the material so marked back as -1;
// - per-object provenance: each vertex's _FEATURE_ID_0 (EXT_mesh_features) is its object's row
//   in the GLB's one property table (EXT_structural_metadata, class "object": object_id UINT64,
//   feature_id INT64 (no data: -1), tool STRING, attributes STRING holding the JSON object;
//   string offsets UINT8, UINT16 or UINT32, the fewest bytes holding them).
// The same content gives the same bytes.
#pragma once

#include <string>
#include <string_view>

#include "content/content.h"

namespace maquette {

struct MeshGlbSettings {
  double position_error = 0.001;  // metres: the largest quantization step of positions
  int normal_bits = 10;           // octahedral quantization (Draco)
  int texcoord_bits = 12;         // over the primitive's range of uvs
};

// Throws maquette::Error naming the object (index and id) at fault: positions not a whole number
// of finite vertices, normals or uvs not one per vertex, indices not whole triangles or out of
// range, no triangles, a material out of range, more than 2^24 objects; and the material at
// fault: a factor outside 0..1, an image neither JPEG, PNG nor WebP.
std::string encode_mesh_glb(const MeshContent& content, const MeshGlbSettings& settings = {});

class GlbBuffer;  // gltf/glb_writer.h

// The GLB's EXT_structural_metadata object (schema and property table, its columns appended to
// `buffer`) as encode_mesh_glb writes it, for GLBs of the same content written otherwise
// (benchmarks/content's plain GLBs given to gltf-transform). Each primitive then declares its
// `_FEATURE_ID_0` with mesh_feature_ids.
nlohmann::json mesh_metadata(const MeshContent& content, GlbBuffer& buffer);
// A primitive's EXT_mesh_features object: `_FEATURE_ID_0` holds rows of property table 0,
// `count` of them drawn by the primitive.
nlohmann::json mesh_feature_ids(size_t count);

// `content` as the store's blob of a mesh or model layer: the envelope (content/content_blob.h:
// kind mesh, the content's origin, objects and triangles counted) around encode_mesh_glb's GLB
// at the default settings. Throws as encode_mesh_glb and wrap_content do.
std::string mesh_content_blob(const MeshContent& content);

// The content back: objects in their order with their materials and provenance; each object's
// vertices in the order its triangles first use them (Draco reorders triangles and vertices, so
// they come back as the same triangles, not the same index lists). Throws maquette::Error naming
// `where` (e.g. "layer buildings, cell N3021") and the fault.
MeshContent decode_mesh_glb(std::string_view glb, const EnuOrigin& origin,
                            const std::string& where);

// Draco's quantization bits for positions spanning `extent` metres along their widest axis: the
// fewest (at most 30) whose step, extent / (2^bits - 1), is at most settings.position_error, so a
// decoded coordinate is within half of it. 1 mm over 1 km: 20 bits.
int position_bits(double extent, const MeshGlbSettings& settings);

}  // namespace maquette
