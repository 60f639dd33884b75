#include "vdb/column_fog.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/error.h"
#include "vdb/volume_vdb.h"

namespace maquette {
namespace {

using Leaf = openvdb::FloatTree::LeafNodeType;
constexpr int32_t kLeafDim = int32_t(Leaf::DIM);

// A column's voxels beyond this are refused: the grid's coordinates are 32-bit.
constexpr int32_t kVoxelLimit = 1 << 30;

// What a block of 8 x 8 columns adds to the tree: its leaves, and the origins of its 8^3 regions
// that every column fills (active tiles: no leaf to allocate, clear and write).
struct Block {
  std::vector<Leaf*> leaves;
  std::vector<openvdb::Coord> tiles;
};

// Block (bi, bj): each column's voxels set active at 1, in leaves by increasing k, or in a tile
// where all 64 columns fill the leaf's 8 voxels. A leaf's mask is made first (a column's 8 voxels
// of a leaf are one byte of one 64-bit word of it), then its values written once from the mask:
// no leaf is filled with the background first.
Block block_voxels(const FogColumns& body, int32_t bi, int32_t bj) {
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
  Block out;
  if (low >= high) return out;
  for (int32_t k0 = low & ~(kLeafDim - 1); k0 < high; k0 += kLeafDim) {
    if (whole && k0 >= top_low && k0 + kLeafDim <= bottom_high) {
      out.tiles.emplace_back(i0, j0, k0);
      continue;
    }
    std::array<uint64_t, Leaf::SIZE / 64> words{};
    for (int32_t j = j0; j < j1; ++j)
      for (int32_t i = i0; i < i1; ++i) {
        const size_t at = size_t(j) * size_t(body.width) + size_t(i);
        const int32_t z0 = std::max(body.low[at], k0) - k0;
        const int32_t z1 = std::min(body.high[at], k0 + kLeafDim) - k0;
        if (z0 >= z1) continue;
        const openvdb::Index base = openvdb::Index(((i & 7) << 6) | ((j & 7) << 3));
        words[base >> 6] |= ((uint64_t(1) << (z1 - z0)) - 1) << ((base & 63) + openvdb::Index(z0));
      }
    if (std::all_of(words.begin(), words.end(), [](uint64_t w) { return w == 0; })) continue;
    auto leaf = std::make_unique<Leaf>(openvdb::PartialCreate(), openvdb::Coord(i0, j0, k0));
    leaf->buffer().allocate();
    float* values = leaf->buffer().data();
    for (openvdb::Index n = 0; n < Leaf::SIZE; ++n)
      values[n] = float((words[n >> 6] >> (n & 63)) & 1);
    for (openvdb::Index w = 0; w < words.size(); ++w)
      leaf->getValueMask().getWord<uint64_t>(w) = words[w];
    out.leaves.push_back(leaf.get());
    leaf.release();
  }
  return out;
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

openvdb::FloatGrid::Ptr fog_grid(const FogColumns& body, const std::string& where) {
  check(body, where);
  openvdb::math::Mat4d map = openvdb::math::Mat4d::identity();  // row vectors: index to frame
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) map(r, c) = body.axes[size_t(r)][size_t(c)];
  map.setTranslation(openvdb::Vec3d(body.centre[0], body.centre[1], body.centre[2]));
  const openvdb::FloatGrid::Ptr grid = openvdb::FloatGrid::create(0.0f);
  grid->setTransform(openvdb::math::Transform::createLinearTransform(map));
  grid->setGridClass(openvdb::GRID_FOG_VOLUME);
  // The blocks' leaves and tiles in parallel, added to the tree in the blocks' order (the tree is
  // sorted by coordinates whatever the order: the same bytes for any thread count).
  const int32_t across = (body.width + kLeafDim - 1) / kLeafDim;
  const int32_t down = (body.height + kLeafDim - 1) / kLeafDim;
  std::vector<Block> blocks(size_t(across) * size_t(down));
  tbb::parallel_for(size_t(0), blocks.size(), [&](size_t b) {
    blocks[b] = block_voxels(body, int32_t(b % size_t(across)), int32_t(b / size_t(across)));
  });
  for (const Block& block : blocks) {
    for (Leaf* leaf : block.leaves) grid->tree().addLeaf(leaf);
    for (const openvdb::Coord& tile : block.tiles) grid->tree().addTile(1, tile, 1.0f, true);
  }
  grid->setName(body.name);
  grid->insertMeta("object_id", openvdb::Int64Metadata(int64_t(body.provenance.object_id)));
  grid->insertMeta("feature_id", openvdb::Int64Metadata(body.provenance.feature_id));
  if (!body.provenance.tool.empty())
    grid->insertMeta("tool", openvdb::StringMetadata(body.provenance.tool));
  return grid;
}

}  // namespace

VolumeContent columns_to_fog(const std::vector<FogColumns>& bodies, const EnuOrigin& origin,
                             const std::string& where) {
  openvdb::initialize();
  openvdb::GridPtrVec grids;
  for (size_t i = 0; i < bodies.size(); ++i)
    grids.push_back(fog_grid(bodies[i], where + ", body " + std::to_string(i)));
  return encode_volume(grids, origin);
}

}  // namespace maquette
