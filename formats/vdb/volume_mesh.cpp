#include "vdb/volume_mesh.h"

#include <openvdb/tools/Interpolation.h>
#include <openvdb/tools/VolumeToMesh.h>

#include <algorithm>

#include "core/error.h"
#include "vdb/volume_vdb.h"

namespace maquette {

namespace {

using openvdb::Vec3d;

// Blue, semi-transparent, smooth: glTF's BLEND alpha mode follows from the alpha below 1.
Material water_material() {
  Material water;
  water.name = "water";
  water.base_colour = {0.02f, 0.18f, 0.45f, 0.6f};
  water.roughness = 0.05f;
  return water;
}

// The metadata `key` of `grid` as type `Meta`, or null when absent; an error when of another type.
template <class Meta>
typename Meta::ConstPtr grid_meta(const openvdb::GridBase& grid, const std::string& key,
                                  const std::string& where) {
  const openvdb::Metadata::ConstPtr meta = grid[key];
  if (!meta) return nullptr;
  const auto typed = openvdb::DynamicPtrCast<const Meta>(meta);
  if (!typed) {
    throw Error(where + ": grid '" + grid.getName() + "': metadata '" + key + "' is of type " +
                meta->typeName() + ", not " + Meta::staticTypeName());
  }
  return typed;
}

bool is_water(const openvdb::GridBase& grid, const std::string& where) {
  if (const auto material = grid_meta<openvdb::StringMetadata>(grid, "material", where)) {
    return material->value() == "water";
  }
  return grid.getName() == "water";
}

ObjectProvenance grid_provenance(const openvdb::GridBase& grid, const std::string& where) {
  ObjectProvenance provenance;
  if (const auto id = grid_meta<openvdb::Int64Metadata>(grid, "object_id", where)) {
    provenance.object_id = uint64_t(id->value());
  }
  if (const auto fid = grid_meta<openvdb::Int64Metadata>(grid, "feature_id", where)) {
    provenance.feature_id = fid->value();
  }
  if (const auto tool = grid_meta<openvdb::StringMetadata>(grid, "tool", where)) {
    provenance.tool = tool->value();
  }
  return provenance;
}

// The grid's gradient at world point p: central differences of its trilinear interpolation, half
// the smallest voxel side either side.
template <class GridType>
Vec3d gradient(const openvdb::tools::GridSampler<GridType, openvdb::tools::BoxSampler>& sampler,
               const Vec3d& p, double h) {
  Vec3d g;
  for (int axis = 0; axis < 3; ++axis) {
    Vec3d step(0);
    step[axis] = h;
    g[axis] = (double(sampler.wsSample(p + step)) - double(sampler.wsSample(p - step))) / (2 * h);
  }
  return g;
}

// A triangle's normal scaled by twice its area.
Vec3d face_normal(const std::vector<float>& positions, const uint32_t* triangle) {
  const auto at = [&](uint32_t v) {
    return Vec3d(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]);
  };
  const Vec3d p0 = at(triangle[0]);
  return (at(triangle[1]) - p0).cross(at(triangle[2]) - p0);
}

template <class GridType>
MeshObject mesh_grid(const GridType& grid, const VolumeMeshSettings& settings) {
  // A level set is negative inside and meshed at 0; a fog volume is denser inside than its
  // isovalue. `outward` turns the gradient into the outward direction.
  const bool level_set = grid.getGridClass() == openvdb::GRID_LEVEL_SET;
  const double isovalue = level_set ? 0 : settings.fog_isovalue;
  const double outward = level_set ? 1 : -1;
  std::vector<openvdb::Vec3s> points;
  std::vector<openvdb::Vec3I> triangles;
  std::vector<openvdb::Vec4I> quads;
  openvdb::tools::volumeToMesh(grid, points, triangles, quads, isovalue, settings.adaptivity);

  MeshObject object;
  object.positions.reserve(3 * points.size());
  for (const auto& p : points) object.positions.insert(object.positions.end(), {p[0], p[1], p[2]});
  object.indices.reserve(6 * quads.size() + 3 * triangles.size());
  for (const auto& q : quads) {
    object.indices.insert(object.indices.end(), {q[0], q[1], q[2], q[0], q[2], q[3]});
  }
  for (const auto& t : triangles) object.indices.insert(object.indices.end(), {t[0], t[1], t[2]});

  const openvdb::tools::GridSampler<GridType, openvdb::tools::BoxSampler> sampler(grid);
  const Vec3d voxel = grid.voxelSize();
  const double h = 0.5 * std::min({voxel[0], voxel[1], voxel[2]});
  std::vector<Vec3d> normals(points.size());
  for (size_t v = 0; v < points.size(); ++v) {
    normals[v] = outward * gradient(sampler, Vec3d(points[v]), h);
  }
  // The winding checked against the gradient: volumeToMesh's is fixed for a grid class, so one
  // sum over the whole surface decides for every triangle at once.
  double agreement = 0;
  std::vector<Vec3d> face_sums(points.size(), Vec3d(0));
  for (size_t t = 0; t < object.indices.size(); t += 3) {
    const uint32_t* triangle = &object.indices[t];
    const Vec3d n = face_normal(object.positions, triangle);
    agreement += n.dot(normals[triangle[0]] + normals[triangle[1]] + normals[triangle[2]]);
    for (int k = 0; k < 3; ++k) face_sums[triangle[k]] += n;
  }
  const double winding = agreement < 0 ? -1 : 1;
  if (winding < 0) {
    for (size_t t = 0; t < object.indices.size(); t += 3) {
      std::swap(object.indices[t + 1], object.indices[t + 2]);
    }
  }
  object.normals.reserve(3 * points.size());
  for (size_t v = 0; v < points.size(); ++v) {
    // Where the gradient vanishes (a saddle, a flat plateau of a fog volume), the normal is the
    // area-weighted mean of the triangles around the vertex (face_sums, as wound).
    Vec3d n = normals[v].lengthSqr() > 0 ? normals[v] : winding * face_sums[v];
    n.normalize();
    object.normals.insert(object.normals.end(), {float(n[0]), float(n[1]), float(n[2])});
  }
  return object;
}

}  // namespace

MeshContent volume_to_mesh(const VolumeContent& volume, const VolumeMeshSettings& settings,
                           const std::string& where) {
  MeshContent mesh;
  mesh.origin = volume.origin;
  for (const auto& grid : decode_volume(volume, where)) {
    MeshObject object;
    if (const auto f = openvdb::GridBase::grid<openvdb::FloatGrid>(grid)) {
      object = mesh_grid(*f, settings);
    } else if (const auto d = openvdb::GridBase::grid<openvdb::DoubleGrid>(grid)) {
      object = mesh_grid(*d, settings);
    } else {
      throw Error(where + ": grid '" + grid->getName() + "' holds " + grid->valueType() +
                  " values: only float and double grids (level sets, fog volumes) are meshed");
    }
    if (object.indices.empty()) continue;
    object.provenance = grid_provenance(*grid, where);
    if (is_water(*grid, where)) {
      if (mesh.materials.empty()) mesh.materials.push_back(water_material());
      object.material = 0;
    }
    mesh.objects.push_back(std::move(object));
  }
  return mesh;
}

}  // namespace maquette
