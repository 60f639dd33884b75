// 3D content as the store holds it (layers of kind mesh, instances and volume; store/README.md):
// what operators write and exports read, per cell. Objects are in a local east-north-up frame at
// an origin of the cell, given in double precision, so positions of float32 keep centimetres
// anywhere on the globe (1 cm at 10 km from the origin is 2^-20 relative: float32 has 2^-24).
//
// An object belongs to exactly one cell at its layer's level: the cell holding its anchor (a
// mesh object's first vertex, an instance's position, a volume grid's centre: the centre of the
// bounding box of its active voxels), whatever it overlaps; the cell's tile
// then has a bounding volume grown to hold it. Coarser levels hold simplified content
// (content_overviews.h).
//
// This header is the data model only: encodings are in content_blob.h (the envelope),
// instances_codec.h (instances, lossless), gltf/mesh_glb.h (meshes as GLB, Draco) and
// vdb/volume_vdb.h (OpenVDB grids).
#pragma once

#include <array>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace maquette {

enum class ContentKind : uint8_t { Mesh = 1, Instances = 2, Volume = 3 };

// The origin of a content's east-north-up frame: a point on or near the WGS84 ellipsoid.
// x east, y north, z up (metres), as GeographicLib::LocalCartesian.
struct EnuOrigin {
  double lon = 0, lat = 0;  // degrees
  double height = 0;        // metres above the ellipsoid
  bool operator==(const EnuOrigin&) const = default;
};

// Where an object came from: the feature (stroke) and the tool (operator) that made it.
struct ObjectProvenance {
  uint64_t object_id = 0;   // unique within the layer (e.g. a hash of the feature id and index)
  int64_t feature_id = -1;  // the features layer's fid, -1 when none
  std::string tool;         // e.g. "structures.buildings"
  nlohmann::json attributes = nlohmann::json::object();  // e.g. {"height": 12.5}
  bool operator==(const ObjectProvenance&) const = default;
};

// PBR metallic-roughness, as glTF 2.0's material.
struct Material {
  std::string name;
  std::array<float, 4> base_colour{1, 1, 1, 1};  // linear RGBA factor
  float metallic = 0, roughness = 1;
  std::string image;       // base-colour texture: encoded JPEG, PNG or WebP bytes; empty: none
  std::string image_mime;  // "image/jpeg", "image/png", "image/webp"
  bool double_sided = false;
  bool operator==(const Material&) const = default;
};

// One object: a triangle mesh with one material.
struct MeshObject {
  ObjectProvenance provenance;
  int material = -1;              // index into MeshContent::materials, -1: default grey
  std::vector<float> positions;   // x, y, z per vertex, metres in the content's ENU frame
  std::vector<float> normals;     // unit x, y, z per vertex, or empty
  std::vector<float> uvs;         // u, v per vertex (glTF: v down from the image's top), or empty
  std::vector<uint32_t> indices;  // triangles, counter-clockwise seen from outside
};

struct MeshContent {
  EnuOrigin origin;
  std::vector<Material> materials;
  std::vector<MeshObject> objects;
};

// Instances of prototype models, column by column (one entry per instance in each).
struct InstancesContent {
  EnuOrigin origin;
  // Prototype names: "builtin:conifer", "builtin:broadleaf", "builtin:shrub", or a model layer
  // (`maquette ingest --as model`, store/README.md "Model layers").
  std::vector<std::string> prototypes;
  std::vector<uint16_t> prototype;           // index into prototypes
  std::vector<float> position;               // x, y, z, metres in the ENU frame (the base)
  std::vector<float> rotation;               // unit quaternion x, y, z, w (glTF order)
  std::vector<float> scale;                  // x, y, z
  std::vector<uint32_t> colour;              // RGBA8 (R in the low byte), multiplies the model's
  std::vector<ObjectProvenance> provenance;  // per instance, or empty
  size_t size() const { return prototype.size(); }
};

// OpenVDB grids (level sets or fog volumes) in the content's ENU frame, as one .vdb stream.
struct VolumeContent {
  EnuOrigin origin;
  std::string vdb;  // the grids as written by openvdb::io::Stream (vdb/volume_vdb.h)
};

// What `maquette info` reports per layer, summed over cells; kept in the blob's envelope so
// that it is read without decoding.
struct ContentStats {
  uint64_t objects = 0;    // mesh objects, instances, or grids
  uint64_t triangles = 0;  // meshes
  uint64_t voxels = 0;     // volumes: active voxels
  bool operator==(const ContentStats&) const = default;
};

}  // namespace maquette
