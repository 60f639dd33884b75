#include "gltf/draco_encode.h"

#include <draco/compression/encode.h>
#include <draco/mesh/mesh.h>

#include "core/error.h"

namespace maquette {
namespace {

// Draco's speed 3 matches draco_transcoder's default compression level (7).
constexpr int kSpeed = 3;

int add_attribute(draco::Mesh& mesh, draco::GeometryAttribute::Type type, int components,
                  const std::vector<float>& values) {
  draco::GeometryAttribute ga;
  ga.Init(type, nullptr, uint8_t(components), draco::DT_FLOAT32, false,
          int64_t(sizeof(float)) * components, 0);
  const size_t n = values.size() / size_t(components);
  const int id = mesh.AddAttribute(ga, true, uint32_t(n));
  draco::PointAttribute* att = mesh.attribute(id);
  for (size_t i = 0; i < n; ++i)
    att->SetAttributeValue(draco::AttributeValueIndex(uint32_t(i)),
                           &values[i * size_t(components)]);
  return int(att->unique_id());
}

}  // namespace

DracoPrimitive encode_draco(const TerrainMesh& mesh, const Lattice& lattice,
                            const QuantizationBits& bits) {
  draco::Mesh dm;
  dm.set_num_points(uint32_t(mesh.vertex_count()));
  DracoPrimitive out;
  const std::vector<float> positions(mesh.positions.begin(), mesh.positions.end());  // exact
  out.position_id = add_attribute(dm, draco::GeometryAttribute::POSITION, 3, positions);
  if (!mesh.normals.empty())
    out.normal_id = add_attribute(dm, draco::GeometryAttribute::NORMAL, 3, mesh.normals);
  if (!mesh.texcoords.empty())
    out.texcoord_id = add_attribute(dm, draco::GeometryAttribute::TEX_COORD, 2, mesh.texcoords);
  for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
    dm.AddFace({draco::PointIndex(mesh.indices[t]), draco::PointIndex(mesh.indices[t + 1]),
                draco::PointIndex(mesh.indices[t + 2])});

  draco::Encoder encoder;
  encoder.SetSpeedOptions(kSpeed, kSpeed);
  const float origin[3] = {0, 0, 0};  // the mesh's offset
  encoder.SetAttributeExplicitQuantization(draco::GeometryAttribute::POSITION, lattice.bits, 3,
                                           origin, lattice.range());
  encoder.SetAttributeQuantization(draco::GeometryAttribute::NORMAL, bits.normal);
  encoder.SetAttributeQuantization(draco::GeometryAttribute::TEX_COORD, bits.texcoord);
  draco::EncoderBuffer buffer;
  const draco::Status status = encoder.EncodeMeshToBuffer(dm, &buffer);
  if (!status.ok()) throw Error("Draco encoding failed: " + status.error_msg_string());
  out.data.assign(buffer.data(), buffer.data() + buffer.size());
  return out;
}

}  // namespace maquette
