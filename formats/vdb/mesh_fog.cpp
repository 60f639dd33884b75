#include "vdb/mesh_fog.h"

#include <openvdb/tools/LevelSetUtil.h>
#include <openvdb/tools/MeshToVolume.h>

#include <cmath>

#include "core/error.h"
#include "vdb/volume_vdb.h"

namespace maquette {
namespace {

openvdb::FloatGrid::Ptr fog_grid(const FogBody& body, const std::string& where) {
  const MeshObject& mesh = body.mesh;
  for (size_t k = 0; k < 3; ++k) {
    if (!std::isfinite(body.voxel[k]) || !(body.voxel[k] > 0))
      throw Error(where + ": voxel size " + std::to_string(body.voxel[k]) +
                  " m is not finite and positive");
    if (!std::isfinite(body.corner[k]))
      throw Error(where + ": the voxel lattice's corner is not finite");
  }
  const size_t vertices = mesh.positions.size() / 3;
  if (mesh.indices.empty() || mesh.indices.size() % 3 != 0)
    throw Error(where + ": a fog volume needs a mesh of whole triangles, not " +
                std::to_string(mesh.indices.size()) + " indices");
  std::vector<openvdb::Vec3s> points(vertices);
  for (size_t i = 0; i < vertices; ++i)
    points[i] = {mesh.positions[3 * i], mesh.positions[3 * i + 1], mesh.positions[3 * i + 2]};
  std::vector<openvdb::Vec3I> triangles(mesh.indices.size() / 3);
  for (size_t t = 0; t < triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k)
      if (mesh.indices[3 * t + size_t(k)] >= vertices)
        throw Error(where + ": triangle " + std::to_string(t) + " has index " +
                    std::to_string(mesh.indices[3 * t + size_t(k)]) + " of " +
                    std::to_string(vertices) + " vertices");
    triangles[t] = {mesh.indices[3 * t], mesh.indices[3 * t + 1], mesh.indices[3 * t + 2]};
  }
  openvdb::math::Mat4d map = openvdb::math::Mat4d::identity();
  map.preScale(openvdb::Vec3d(body.voxel[0], body.voxel[1], body.voxel[2]));
  map.postTranslate(openvdb::Vec3d(body.corner[0] + body.voxel[0] / 2,
                                   body.corner[1] + body.voxel[1] / 2,
                                   body.corner[2] + body.voxel[2] / 2));
  const openvdb::math::Transform::Ptr transform =
      openvdb::math::Transform::createLinearTransform(map);
  const openvdb::FloatGrid::Ptr grid =
      openvdb::tools::meshToLevelSet<openvdb::FloatGrid>(*transform, points, triangles);
  openvdb::tools::sdfToFogVolume(*grid);
  grid->setName(body.name);
  grid->insertMeta("object_id", openvdb::Int64Metadata(int64_t(mesh.provenance.object_id)));
  grid->insertMeta("feature_id", openvdb::Int64Metadata(mesh.provenance.feature_id));
  if (!mesh.provenance.tool.empty())
    grid->insertMeta("tool", openvdb::StringMetadata(mesh.provenance.tool));
  return grid;
}

}  // namespace

VolumeContent mesh_to_fog(const std::vector<FogBody>& bodies, const EnuOrigin& origin,
                          const std::string& where) {
  openvdb::initialize();
  openvdb::GridPtrVec grids;
  for (size_t i = 0; i < bodies.size(); ++i)
    grids.push_back(fog_grid(bodies[i], where + ", body " + std::to_string(i)));
  return encode_volume(grids, origin);
}

}  // namespace maquette
