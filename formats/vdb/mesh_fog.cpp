#include "vdb/mesh_fog.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <span>
#include <sstream>
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
// Ordered by column and height (a total order: any sort gives the same sequence).
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

// The crossings of triangles [first, last) with the voxel columns whose centres their
// projections hold (vertical triangles hold none), in triangle order.
void column_crossings(const FogBody& body, size_t first, size_t last, std::vector<Crossing>& out) {
  const MeshObject& mesh = body.mesh;
  const auto index = [&](uint32_t v) {
    std::array<double, 3> p;
    for (size_t k = 0; k < 3; ++k)
      p[k] = (double(mesh.positions[3 * v + k]) - body.corner[k]) / body.voxel[k] - 0.5;
    return p;
  };
  for (size_t t = 3 * first; t < 3 * last; t += 3) {
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
}

// Every triangle's crossings (found by blocks of triangles in parallel), grouped by the 8 x 8
// block of columns of a VDB leaf: blocks[b] is [starts[b], starts[b + 1]), unsorted.
struct BlockCrossings {
  std::vector<Crossing> crossings;
  std::vector<size_t> starts;
};

BlockCrossings block_crossings(const FogBody& body) {
  constexpr size_t kTriangles = 8192;
  const size_t triangles = body.mesh.indices.size() / 3;
  std::vector<std::vector<Crossing>> found((triangles + kTriangles - 1) / kTriangles);
  tbb::parallel_for(size_t(0), found.size(), [&](size_t b) {
    column_crossings(body, b * kTriangles, std::min(triangles, (b + 1) * kTriangles), found[b]);
  });
  // A counting sort by block over the blocks' bounding box.
  std::array<int32_t, 2> low{INT32_MAX, INT32_MAX}, high{INT32_MIN, INT32_MIN};
  for (const auto& part : found)
    for (const Crossing& c : part)
      for (size_t k = 0; k < 2; ++k) {
        low[k] = std::min(low[k], c.column[k] >> 3);
        high[k] = std::max(high[k], c.column[k] >> 3);
      }
  const size_t across = high[0] < low[0] ? 0 : size_t(high[0] - low[0] + 1);
  const auto block = [&](const Crossing& c) {
    return size_t((c.column[1] >> 3) - low[1]) * across + size_t((c.column[0] >> 3) - low[0]);
  };
  BlockCrossings out;
  out.starts.assign(across == 0 ? 1 : across * size_t(high[1] - low[1] + 1) + 1, 0);
  for (const auto& part : found)
    for (const Crossing& c : part) ++out.starts[block(c) + 1];
  for (size_t b = 1; b < out.starts.size(); ++b) out.starts[b] += out.starts[b - 1];
  out.crossings.resize(out.starts.back());
  std::vector<size_t> next(out.starts.begin(), out.starts.end() - 1);
  for (const auto& part : found)
    for (const Crossing& c : part) out.crossings[next[block(c)]++] = c;
  return out;
}

using Leaf = openvdb::FloatTree::LeafNodeType;

// The leaves of one 8 x 8 block of columns (its crossings, sorted here): up each column, the
// voxels whose centres lie where the winding number is positive, set active at 1 in leaves made
// here (no per-voxel descent of the tree), by increasing k.
std::vector<Leaf*> block_leaves(std::span<Crossing> crossings) {
  std::sort(crossings.begin(), crossings.end());
  std::map<int32_t, Leaf*> leaves;  // by k >> 3
  for (size_t a = 0; a < crossings.size();) {
    size_t b = a;
    int winding = 0;
    for (; b < crossings.size() && crossings[b].column == crossings[a].column; ++b) {
      const int before = winding;
      winding += crossings[b].step;
      if (before <= 0) continue;
      Leaf* leaf = nullptr;  // the leaf of voxel k, looked up when k enters another
      for (int64_t k = int64_t(std::ceil(crossings[b - 1].z)); double(k) < crossings[b].z; ++k) {
        const openvdb::Coord xyz(crossings[a].column[0], crossings[a].column[1], int32_t(k));
        if (!leaf || (k & (Leaf::DIM - 1)) == 0) {
          Leaf*& slot = leaves[int32_t(k) >> 3];
          if (!slot) slot = new Leaf(xyz & ~openvdb::Int32(Leaf::DIM - 1), 0.0f, false);
          leaf = slot;
        }
        leaf->setValueOn(Leaf::coordToOffset(xyz), 1.0f);
      }
    }
    a = b;
  }
  std::vector<Leaf*> out;
  for (const auto& [k, leaf] : leaves) out.push_back(leaf);
  return out;
}

// Throws unless every vertex is finite and its voxel index coordinates (and so every column and
// voxel set) fit OpenVDB's 32-bit coordinates: a body too large for its voxels (a huge lake, tiny
// voxels) would otherwise wrap around.
void check_index_range(const FogBody& body, const std::string& where) {
  constexpr double kLimit = std::numeric_limits<int32_t>::max();
  const std::vector<float>& positions = body.mesh.positions;
  for (size_t k = 0; k < 3; ++k) {
    double lo = INFINITY, hi = -INFINITY;
    for (size_t v = k; v < positions.size(); v += 3) {
      if (!std::isfinite(positions[v]))
        throw Error(where + ": vertex " + std::to_string(v / 3) + " is not finite");
      lo = std::min(lo, double(positions[v]));
      hi = std::max(hi, double(positions[v]));
    }
    const double first = (lo - body.corner[k]) / body.voxel[k] - 0.5;
    const double last = (hi - body.corner[k]) / body.voxel[k] - 0.5;
    if (first < -kLimit || last > kLimit) {
      std::ostringstream m;
      m.precision(10);
      m << where << ": the mesh spans " << lo << " to " << hi << " m along "
        << "xyz"[k] << ", voxels " << first << " to " << last << " from the lattice's corner "
        << body.corner[k] << " m with voxels of " << body.voxel[k]
        << " m: beyond a grid's 32-bit voxel coordinates (larger voxels, or a smaller body)";
      throw Error(m.str());
    }
  }
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
  check_index_range(body, where);
  BlockCrossings crossings = block_crossings(body);
  openvdb::math::Mat4d map = openvdb::math::Mat4d::identity();
  map.preScale(openvdb::Vec3d(body.voxel[0], body.voxel[1], body.voxel[2]));
  map.postTranslate(openvdb::Vec3d(body.corner[0] + body.voxel[0] / 2,
                                   body.corner[1] + body.voxel[1] / 2,
                                   body.corner[2] + body.voxel[2] / 2));
  const openvdb::FloatGrid::Ptr grid = openvdb::FloatGrid::create(0.0f);
  grid->setTransform(openvdb::math::Transform::createLinearTransform(map));
  grid->setGridClass(openvdb::GRID_FOG_VOLUME);
  // The leaves block by block in parallel, added to the tree in the blocks' order (the tree is
  // sorted by coordinates whatever the order: the same bytes for any thread count).
  const std::vector<size_t>& starts = crossings.starts;
  std::vector<std::vector<Leaf*>> leaves(starts.size() - 1);
  tbb::parallel_for(size_t(0), leaves.size(), [&](size_t b) {
    leaves[b] =
        block_leaves(std::span(crossings.crossings).subspan(starts[b], starts[b + 1] - starts[b]));
  });
  for (const auto& block : leaves)
    for (Leaf* leaf : block) grid->tree().addLeaf(leaf);
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
