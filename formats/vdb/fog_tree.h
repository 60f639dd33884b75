// A fog volume's float tree as flat arrays, without an openvdb::FloatTree (README.md, "Fog
// volumes of voxel columns"): what columns_to_fog builds (no leaf allocated and freed one by one,
// no leaf read back to be written) and the stream writer writes (vdb_stream_writer.h).
#pragma once

#include <openvdb/openvdb.h>

#include <array>
#include <cstdint>
#include <ostream>
#include <vector>

namespace maquette {

// A leaf of 8^3 voxels: its origin (each coordinate a multiple of 8) and its value mask, as
// OpenVDB's LeafNode<float, 3> holds it (voxel (x, y, z) of the leaf at bit 64 x + 8 y + z).
struct FogLeaf {
  openvdb::Coord origin;
  std::array<uint64_t, 8> mask{};
};

// The tree of a float grid whose active voxels are all kFogDensity and whose other values all
// kFogBackground: the leaves (at least one active voxel each) and the origins of the active tiles
// of a leaf's size (8^3 voxels of kFogDensity, a tile of the leaf's parent node), no origin twice.
// It stands for the openvdb::FloatTree of background kFogBackground with these leaves added
// (Tree::addLeaf, each value kFogDensity where the mask is on) and these tiles added at level 1
// (Tree::addTile), nothing else.
struct FogTree {
  std::vector<FogLeaf> leaves;
  std::vector<openvdb::Coord> tiles;
};

inline constexpr float kFogDensity = 1.0f;
inline constexpr float kFogBackground = 0.0f;  // one address in every translation unit

// Puts the leaves and the tiles of `tree` each in the order OpenVDB's tree holds them (the
// root's children by their origins, each internal node's children by their offsets in it), which
// is the order in which Tree::writeTopology and Tree::writeBuffers write them. Time O(n log n).
void sort_in_tree_order(FogTree& tree);

// The bytes Tree::writeTopology (not as half floats) writes for the openvdb::FloatTree `tree`
// stands for, on `os` (its data compression set, io::setDataCompression), which is left with the
// grid background pointer set (io::setGridBackgroundValuePtr) to kFogBackground, as OpenVDB's
// root node leaves it. Precondition: `tree` in tree order (sort_in_tree_order), no origin twice:
// else an Error naming the first origin out of order.
void write_fog_topology(std::ostream& os, const FogTree& tree);

}  // namespace maquette
