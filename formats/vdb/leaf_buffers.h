// A float tree's leaves' buffers as OpenVDB 10's writer writes them, made in parallel, with the
// delayed-load metadata it adds for them (vdb_stream_writer.h's part; README.md, "Encoding").
#pragma once

#include <openvdb/io/DelayedLoadMetadata.h>
#include <openvdb/openvdb.h>

#include <cstdint>
#include <string>
#include <vector>

#include "vdb/fog_tree.h"

namespace maquette {

struct LeafBuffers {
  std::vector<std::string> parts;  // consecutive leaves' bytes, in the tree's leaf order
  openvdb::io::DelayedLoadMetadata delayed;
};

// The bytes Tree::writeBuffers writes for `tree` (not saved as half floats) on a stream of
// `compression` (io::setDataCompression), in parts of 64 leaves made in parallel (TBB): each
// leaf's LeafNode::writeBuffers, except for a leaf whose active values are one value and whose
// inactive values are the background, bit for bit (a fog volume's usual leaf), when the stream
// compresses by active mask: its value mask, the mask kind "no inactive values" and the stream
// of its active values, which depends on their count and value only, compressed once per count
// and value met. `delayed`: what OpenVDB's writer records as file_delayed_load for the archive's
// `archive_compression`, each leaf's mask kind and, when that compresses (Blosc or zip), its
// compressed size, read from the leaf's bytes (none for a tree without leaves). The same bytes
// for any thread count. Throws maquette::Error if a leaf's bytes are not laid out as OpenVDB 10
// writes them.
LeafBuffers leaf_buffers(const openvdb::FloatTree& tree, uint32_t compression,
                         uint32_t archive_compression);

// The same for the openvdb::FloatTree that `tree` (in tree order: sort_in_tree_order) stands for,
// from its masks alone: every leaf is uniform, its stream compressed once per count of active
// voxels met. Throws maquette::Error unless `compression` compresses by active mask.
LeafBuffers fog_leaf_buffers(const FogTree& tree, uint32_t compression,
                             uint32_t archive_compression);

}  // namespace maquette
