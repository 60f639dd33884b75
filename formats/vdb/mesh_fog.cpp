#include "vdb/mesh_fog.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <tuple>
#include <utility>
#include <vector>

#include "core/error.h"
#include "vdb/volume_vdb.h"

namespace maquette {
namespace {

using Point = std::array<double, 2>;

// Where a triangle crosses the vertical line of a voxel column (index coordinates: voxel (i, j,
// k) centred at (i, j, k)), and how the winding number changes going up through it: +1 through
// a face seen from below (facing down: the ray enters), -1 through one facing up.
struct Crossing {
  std::array<int32_t, 2> column;
  double z;
  int step;
  bool operator<(const Crossing& o) const {
    return std::tie(column, z, step) < std::tie(o.column, o.z, o.step);
  }
};

// The edge function of segment u -> v at p (positive on its left), computed from the segment's
// endpoints in a fixed order whichever way it is walked, so that the two triangles sharing an
// edge see exactly opposite values.
double edge(Point u, Point v, Point p) {
  const bool flip = v < u;
  if (flip) std::swap(u, v);
  const double e = (v[0] - u[0]) * (p[1] - u[1]) - (v[1] - u[1]) * (p[0] - u[0]);
  return flip ? -e : e;
}

// A point on an edge belongs to the triangle on one side of it only: the one for which the edge
// (walked counter-clockwise around it) goes down, or right when horizontal.
bool owns_edge(Point u, Point v) { return v[1] < u[1] || (v[1] == u[1] && v[0] > u[0]); }

// Every triangle's crossings of the voxel columns whose centres its projection holds (vertical
// triangles hold none), sorted by column and height.
std::vector<Crossing> column_crossings(const FogBody& body) {
  const MeshObject& mesh = body.mesh;
  const auto index = [&](uint32_t v) {
    std::array<double, 3> p;
    for (size_t k = 0; k < 3; ++k)
      p[k] = (double(mesh.positions[3 * v + k]) - body.corner[k]) / body.voxel[k] - 0.5;
    return p;
  };
  std::vector<Crossing> out;
  for (size_t t = 0; t < mesh.indices.size(); t += 3) {
    std::array<std::array<double, 3>, 3> c = {index(mesh.indices[t]), index(mesh.indices[t + 1]),
                                              index(mesh.indices[t + 2])};
    const double area = edge({c[0][0], c[0][1]}, {c[1][0], c[1][1]}, {c[2][0], c[2][1]});
    if (area == 0) continue;
    const int step = area > 0 ? -1 : 1;  // counter-clockwise seen from above: facing up
    if (area < 0) std::swap(c[1], c[2]);
    const Point p0{c[0][0], c[0][1]}, p1{c[1][0], c[1][1]}, p2{c[2][0], c[2][1]};
    const double i0 = std::ceil(std::min({p0[0], p1[0], p2[0]}));
    const double i1 = std::floor(std::max({p0[0], p1[0], p2[0]}));
    const double j0 = std::ceil(std::min({p0[1], p1[1], p2[1]}));
    const double j1 = std::floor(std::max({p0[1], p1[1], p2[1]}));
    for (double j = j0; j <= j1; ++j)
      for (double i = i0; i <= i1; ++i) {
        const Point p{i, j};
        const double w0 = edge(p1, p2, p), w1 = edge(p2, p0, p), w2 = edge(p0, p1, p);
        const auto in = [](double w, Point u, Point v) {
          return w > 0 || (w == 0 && owns_edge(u, v));
        };
        if (!in(w0, p1, p2) || !in(w1, p2, p0) || !in(w2, p0, p1)) continue;
        const double z = (w0 * c[0][2] + w1 * c[1][2] + w2 * c[2][2]) / (w0 + w1 + w2);
        out.push_back({{int32_t(i), int32_t(j)}, z, step});
      }
  }
  std::sort(out.begin(), out.end());
  return out;
}

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
  for (size_t t = 0; t < mesh.indices.size(); ++t)
    if (mesh.indices[t] >= vertices)
      throw Error(where + ": triangle " + std::to_string(t / 3) + " has index " +
                  std::to_string(mesh.indices[t]) + " of " + std::to_string(vertices) +
                  " vertices");
  const std::vector<Crossing> crossings = column_crossings(body);
  openvdb::math::Mat4d map = openvdb::math::Mat4d::identity();
  map.preScale(openvdb::Vec3d(body.voxel[0], body.voxel[1], body.voxel[2]));
  map.postTranslate(openvdb::Vec3d(body.corner[0] + body.voxel[0] / 2,
                                   body.corner[1] + body.voxel[1] / 2,
                                   body.corner[2] + body.voxel[2] / 2));
  const openvdb::FloatGrid::Ptr grid = openvdb::FloatGrid::create(0.0f);
  grid->setTransform(openvdb::math::Transform::createLinearTransform(map));
  grid->setGridClass(openvdb::GRID_FOG_VOLUME);
  openvdb::FloatGrid::Accessor voxels = grid->getAccessor();
  // Up each column, the voxels whose centres lie where the winding number is positive.
  for (size_t a = 0; a < crossings.size();) {
    size_t b = a;
    int winding = 0;
    for (; b < crossings.size() && crossings[b].column == crossings[a].column; ++b) {
      const int before = winding;
      winding += crossings[b].step;
      if (before > 0)
        for (int64_t k = int64_t(std::ceil(crossings[b - 1].z)); double(k) < crossings[b].z; ++k)
          voxels.setValueOn({crossings[a].column[0], crossings[a].column[1], int32_t(k)}, 1.0f);
    }
    a = b;
  }
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
