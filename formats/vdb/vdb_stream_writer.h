// OpenVDB's stream writer with float grids' leaves compressed once and in parallel (README.md,
// "Encoding"): what encode_volume writes its grids with.
#pragma once

#include <openvdb/openvdb.h>

#include <string>
#include <vector>

#include "vdb/fog_tree.h"

namespace maquette {

// The bytes of openvdb::io::Stream's write of `grids` (none null) with Blosc and active-mask
// compression and no grid statistics metadata, its header's UUID OpenVDB's random one, for any
// thread count. Float grids (not saved as half floats) are written here: each leaf's buffer (value
// mask, Blosc-compressed values) made by OpenVDB's LeafNode::writeBuffers into parts of
// consecutive leaves in parallel (TBB), their delayed-load metadata (each leaf's mask kind and
// compressed size, which OpenVDB 10's writer finds by compressing every leaf a second time, before
// writing) read from those bytes, then the grid's descriptor, metadata, transform and topology by
// OpenVDB's own calls and the parts in the tree's order. Other grids are written by OpenVDB's
// io::Archive itself. Time: one compression of each leaf, spread over the cores; memory: the
// compressed leaves twice (the parts and the stream). Throws openvdb::Exception as OpenVDB's
// writer does, and maquette::Error if a leaf's bytes are not laid out as OpenVDB 10 writes them.
std::string write_vdb_stream(const openvdb::GridPtrVec& grids);

// A float grid whose tree is a FogTree (fog_tree.h): `grid` gives its name, class, metadata and
// transform, `tree` its voxels (the grid's own tree is not read).
struct FogGrid {
  openvdb::FloatGrid::ConstPtr grid;
  FogTree tree;  // in tree order (sort_in_tree_order)
};

// The bytes of io::Stream's write, as above, of the grids the FogGrids stand for (each grid with
// the openvdb::FloatTree its FogTree stands for; none an instance of another): the topology
// written from the tree's origins and masks (write_fog_topology), the leaves' buffers from their
// masks (fog_leaf_buffers), no tree built. Throws maquette::Error for a null grid, one saved as
// half floats, or a tree out of tree order or with an origin twice.
std::string write_vdb_stream(const std::vector<FogGrid>& grids);

}  // namespace maquette
