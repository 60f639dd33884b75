#include "vdb/column_fog.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/error.h"
#include "vdb/fog_tree.h"
#include "vdb/volume_vdb.h"

namespace maquette {
namespace {

constexpr int32_t kLeafDim = int32_t(openvdb::FloatTree::LeafNodeType::DIM);

// A column's voxels beyond this are refused: the grid's coordinates are 32-bit.
constexpr int32_t kVoxelLimit = 1 << 30;

// Blocks of 8 x 8 columns per task: a task's work outweighs its cost, a lake's thousands of
// blocks still make many tasks.
constexpr size_t kBlocksPerTask = 64;

// Block (bi, bj) of 8 x 8 columns: its leaves and tiles appended to `tree`, by increasing k: each
// column's voxels active, a leaf's 8^3 region that all 64 columns fill a tile. A leaf's mask is
// made from its columns (a column's 8 voxels of a leaf are one byte of one 64-bit word of it).
void block_voxels(const FogColumns& body, int32_t bi, int32_t bj, FogTree& tree) {
  const int32_t i0 = bi * kLeafDim, i1 = std::min(body.width, i0 + kLeafDim);
  const int32_t j0 = bj * kLeafDim, j1 = std::min(body.height, j0 + kLeafDim);
  // The columns' union [low, high) and common part [top_low, bottom_high) when all are whole.
  int32_t low = INT32_MAX, high = INT32_MIN, top_low = INT32_MIN, bottom_high = INT32_MAX;
  bool whole = i1 - i0 == kLeafDim && j1 - j0 == kLeafDim;
  for (int32_t j = j0; j < j1; ++j)
    for (int32_t i = i0; i < i1; ++i) {
      const size_t at = size_t(j) * size_t(body.width) + size_t(i);
      if (body.low[at] >= body.high[at]) {
        whole = false;
        continue;
      }
      low = std::min(low, body.low[at]), top_low = std::max(top_low, body.low[at]);
      high = std::max(high, body.high[at]), bottom_high = std::min(bottom_high, body.high[at]);
    }
  if (low >= high) return;
  for (int32_t k0 = low & ~(kLeafDim - 1); k0 < high; k0 += kLeafDim) {
    if (whole && k0 >= top_low && k0 + kLeafDim <= bottom_high) {
      tree.tiles.emplace_back(i0, j0, k0);
      continue;
    }
    FogLeaf leaf{openvdb::Coord(i0, j0, k0)};
    for (int32_t j = j0; j < j1; ++j)
      for (int32_t i = i0; i < i1; ++i) {
        const size_t at = size_t(j) * size_t(body.width) + size_t(i);
        const int32_t z0 = std::max(body.low[at], k0) - k0;
        const int32_t z1 = std::min(body.high[at], k0 + kLeafDim) - k0;
        if (z0 >= z1) continue;
        leaf.mask[size_t(i & 7)] |= ((uint64_t(1) << (z1 - z0)) - 1) << ((j & 7) * 8 + z0);
      }
    if (std::any_of(leaf.mask.begin(), leaf.mask.end(), [](uint64_t w) { return w != 0; }))
      tree.leaves.push_back(leaf);
  }
}

void check(const FogColumns& body, const std::string& where) {
  if (body.width < 0 || body.height < 0)
    throw Error(where + ": " + std::to_string(body.width) + " x " + std::to_string(body.height) +
                " columns");
  const size_t columns = size_t(body.width) * size_t(body.height);
  if (body.low.size() != columns || body.high.size() != columns)
    throw Error(where + ": " + std::to_string(body.low.size()) + " lows and " +
                std::to_string(body.high.size()) + " highs for " + std::to_string(body.width) +
                " x " + std::to_string(body.height) + " columns");
  for (const auto& axis : body.axes)
    for (const double x : axis)
      if (!std::isfinite(x)) throw Error(where + ": a lattice axis is not finite");
  for (const double x : body.centre)
    if (!std::isfinite(x)) throw Error(where + ": the lattice's centre is not finite");
  const auto& [a, b, c] = body.axes;
  const double volume = a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                        a[2] * (b[0] * c[1] - b[1] * c[0]);
  if (!(std::abs(volume) > 0)) throw Error(where + ": the lattice's axes do not span space");
  for (size_t at = 0; at < columns; ++at)
    if (body.low[at] < body.high[at] &&
        (body.low[at] < -kVoxelLimit || body.high[at] > kVoxelLimit))
      throw Error(where + ": column " + std::to_string(at) + " holds voxels " +
                  std::to_string(body.low[at]) + " to " + std::to_string(body.high[at]) +
                  ", beyond +-2^30");
}

FogGrid fog_grid(const FogColumns& body, const std::string& where) {
  check(body, where);
  openvdb::math::Mat4d map = openvdb::math::Mat4d::identity();  // row vectors: index to frame
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) map(r, c) = body.axes[size_t(r)][size_t(c)];
  map.setTranslation(openvdb::Vec3d(body.centre[0], body.centre[1], body.centre[2]));
  const openvdb::FloatGrid::Ptr grid = openvdb::FloatGrid::create(kFogBackground);
  grid->setTransform(openvdb::math::Transform::createLinearTransform(map));
  grid->setGridClass(openvdb::GRID_FOG_VOLUME);
  grid->setName(body.name);
  grid->insertMeta("object_id", openvdb::Int64Metadata(int64_t(body.provenance.object_id)));
  grid->insertMeta("feature_id", openvdb::Int64Metadata(body.provenance.feature_id));
  if (!body.provenance.tool.empty())
    grid->insertMeta("tool", openvdb::StringMetadata(body.provenance.tool));
  // The blocks' leaves and tiles by tasks of consecutive blocks in parallel, joined in the tasks'
  // order and sorted in tree order: the same tree for any thread count.
  const int32_t across = (body.width + kLeafDim - 1) / kLeafDim;
  const int32_t down = (body.height + kLeafDim - 1) / kLeafDim;
  const size_t blocks = size_t(across) * size_t(down);
  std::vector<FogTree> parts((blocks + kBlocksPerTask - 1) / kBlocksPerTask);
  tbb::parallel_for(size_t(0), parts.size(), [&](size_t p) {
    for (size_t b = p * kBlocksPerTask; b < std::min(blocks, (p + 1) * kBlocksPerTask); ++b)
      block_voxels(body, int32_t(b % size_t(across)), int32_t(b / size_t(across)), parts[p]);
  });
  FogGrid fog{grid, {}};
  size_t leaves = 0, tiles = 0;
  for (const FogTree& part : parts) leaves += part.leaves.size(), tiles += part.tiles.size();
  fog.tree.leaves.reserve(leaves);
  fog.tree.tiles.reserve(tiles);
  for (const FogTree& part : parts) {
    fog.tree.leaves.insert(fog.tree.leaves.end(), part.leaves.begin(), part.leaves.end());
    fog.tree.tiles.insert(fog.tree.tiles.end(), part.tiles.begin(), part.tiles.end());
  }
  sort_in_tree_order(fog.tree);
  return fog;
}

}  // namespace

VolumeContent columns_to_fog(const std::vector<FogColumns>& bodies, const EnuOrigin& origin,
                             const std::string& where) {
  openvdb::initialize();
  std::vector<FogGrid> grids;
  for (size_t i = 0; i < bodies.size(); ++i)
    grids.push_back(fog_grid(bodies[i], where + ", body " + std::to_string(i)));
  return encode_volume(grids, origin);
}

}  // namespace maquette
