#include "vdb/vdb_stream_writer.h"

#include <openvdb/io/Archive.h>
#include <openvdb/io/DelayedLoadMetadata.h>
#include <openvdb/io/GridDescriptor.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <string_view>
#include <vector>

#include "core/error.h"

namespace maquette {
namespace {

namespace io = openvdb::io;
using Leaf = openvdb::FloatTree::LeafNodeType;

// Leaves per part: a part's work (~64 leaves' compression) outweighs a task's cost, and a lake's
// thousands of leaves still make many parts to share.
constexpr size_t kLeavesPerPart = 64;

// A float leaf's buffer as LeafNode::writeBuffers writes it (io::writeCompressedValues): its value
// mask, the mask compression kind (one byte), the inactive values that kind names (0 to 2
// floats), the mask selecting between two inactive values when the kind has one, the values'
// byte count (int64, negative when Blosc could not compress them and they are stored raw), the
// values. Returns the kind and what OpenVDB's delayed-load metadata records as the compressed size:
// the byte count's magnitude and its own 8 bytes.
std::pair<int8_t, int64_t> delayed_load_entry(std::string_view leaf) {
  const size_t mask_bytes = Leaf::NodeMaskType::memUsage();
  const auto refuse = [&] {
    return Error("VDB writer: a leaf's " + std::to_string(leaf.size()) +
                 " bytes are not laid out as OpenVDB 10 writes them");
  };
  if (leaf.size() < mask_bytes + 1) throw refuse();
  const int8_t kind = int8_t(leaf[mask_bytes]);
  size_t at = mask_bytes + 1;
  if (kind == io::NO_MASK_AND_ONE_INACTIVE_VAL || kind == io::MASK_AND_ONE_INACTIVE_VAL)
    at += sizeof(float);
  if (kind == io::MASK_AND_TWO_INACTIVE_VALS) at += 2 * sizeof(float);
  if (kind == io::MASK_AND_NO_INACTIVE_VALS || kind == io::MASK_AND_ONE_INACTIVE_VAL ||
      kind == io::MASK_AND_TWO_INACTIVE_VALS)
    at += mask_bytes;
  int64_t count = 0;
  if (leaf.size() < at + sizeof count) throw refuse();
  std::memcpy(&count, leaf.data() + at, sizeof count);
  const int64_t bytes = std::abs(count) + int64_t(sizeof count);
  if (leaf.size() != at + size_t(bytes)) throw refuse();
  return {kind, bytes};
}

// A float tree's leaves' buffers, in the tree's order, made in parallel with the stream's
// `compression`, and the delayed-load metadata that OpenVDB's writer adds for them (sizes when
// the archive's `archive_compression` compresses).
struct LeafBuffers {
  std::vector<std::string> parts;
  io::DelayedLoadMetadata delayed;
};

LeafBuffers leaf_buffers(const openvdb::FloatTree& tree, uint32_t compression,
                         uint32_t archive_compression) {
  // getNodes lists the leaves in the order Tree::writeBuffers writes them (the root's children in
  // order, each internal node's children in order): OpenVDB's leaf index.
  std::vector<const Leaf*> leaves;
  tree.getNodes(leaves);
  LeafBuffers out;
  out.parts.resize((leaves.size() + kLeavesPerPart - 1) / kLeavesPerPart);
  std::vector<std::pair<int8_t, int64_t>> entries(leaves.size());
  tbb::parallel_for(size_t(0), out.parts.size(), [&](size_t p) {
    std::ostringstream part(std::ios::binary);
    io::setDataCompression(part, compression);
    io::setGridBackgroundValuePtr(part, &tree.background());
    const size_t first = p * kLeavesPerPart, end = std::min(leaves.size(), first + kLeavesPerPart);
    std::vector<size_t> starts;
    for (size_t l = first; l < end; ++l) {
      starts.push_back(size_t(part.tellp()));
      leaves[l]->writeBuffers(part, /*toHalf=*/false);
    }
    starts.push_back(size_t(part.tellp()));
    out.parts[p] = std::move(part).str();
    const std::string_view bytes = out.parts[p];
    for (size_t l = first; l < end; ++l)
      entries[l] = delayed_load_entry(
          bytes.substr(starts[l - first], starts[l - first + 1] - starts[l - first]));
  });
  if (leaves.empty()) return out;  // OpenVDB leaves a tree without leaves' metadata empty
  out.delayed.resizeMask(leaves.size());
  const bool sizes = archive_compression & (io::COMPRESS_BLOSC | io::COMPRESS_ZIP);
  if (sizes) out.delayed.resizeCompressedSize(leaves.size());
  for (size_t l = 0; l < leaves.size(); ++l) {
    out.delayed.setMask(l, entries[l].first);
    if (sizes) out.delayed.setCompressedSize(l, entries[l].second);
  }
  return out;
}

// io::Stream's write (io::Archive::write and writeGrid of OpenVDB 10.0), float grids' leaves
// compressed by leaf_buffers.
class StreamWriter : public io::Archive {
 public:
  StreamWriter() {
    setCompression(io::COMPRESS_BLOSC | io::COMPRESS_ACTIVE_MASK);
    setGridStatsMetadataEnabled(false);
  }

  std::string bytes(const openvdb::GridPtrVec& grids) const {
    std::ostringstream os(std::ios::binary);
    auto stream = std::make_shared<io::StreamMetadata>();
    io::setStreamMetadataPtr(os, stream, /*transfer=*/false);
    io::setDataCompression(os, compression());
    io::setWriteGridStatsMetadata(os, isGridStatsMetadataEnabled());
    writeHeader(os, /*seekable=*/false);
    openvdb::MetaMap().writeMeta(os);
    const int32_t count = int32_t(grids.size());
    os.write(reinterpret_cast<const char*>(&count), sizeof count);
    // Unique names as OpenVDB makes them: a suffix for an empty or repeated name.
    std::map<std::string, int> names;
    for (const auto& grid : grids) ++names[grid->getName()];
    std::set<std::string> unique;
    std::map<const openvdb::TreeBase*, io::GridDescriptor> trees;
    for (const auto& grid : grids) {
      std::string name = grid->getName();
      if (name.empty() || names[name] > 1) name = io::GridDescriptor::addSuffix(name, 0);
      for (int n = 1; unique.count(name); ++n)
        name = io::GridDescriptor::addSuffix(grid->getName(), n);
      unique.insert(name);
      io::GridDescriptor gd(name, grid->type(), grid->saveFloatAsHalf());
      const auto tree = trees.find(&grid->baseTree());
      if (isInstancingEnabled() && tree != trees.end() &&
          tree->second.saveFloatAsHalf() == gd.saveFloatAsHalf()) {
        gd.setInstanceParentName(tree->second.uniqueName());
        writeGridInstance(gd, grid, os, /*seekable=*/false);
      } else {
        const auto floats = openvdb::gridConstPtrCast<openvdb::FloatGrid>(grid);
        if (floats && !floats->saveFloatAsHalf())
          write_float_grid(gd, *floats, os);
        else
          writeGrid(gd, grid, os, /*seekable=*/false);
        trees[&grid->baseTree()] = gd;
      }
      io::setDataCompression(os, compression());
    }
    return std::move(os).str();
  }

 private:
  // Archive::writeGrid's steps for a non-seekable stream, the delayed-load metadata and the
  // buffers from leaf_buffers.
  void write_float_grid(io::GridDescriptor& gd, const openvdb::FloatGrid& grid,
                        std::ostream& os) const {
    io::StreamMetadata::Ptr file = io::getStreamMetadataPtr(os);
    auto stream = std::make_shared<io::StreamMetadata>(*file);
    stream->setHalfFloat(false);
    stream->gridMetadata() = static_cast<const openvdb::MetaMap&>(grid);
    io::setStreamMetadataPtr(os, stream, /*transfer=*/false);
    gd.writeHeader(os);
    gd.writeStreamPos(os);
    setGridCompression(os, grid);
    const LeafBuffers buffers =
        leaf_buffers(grid.tree(), io::getDataCompression(os), compression());
    openvdb::MetaMap meta(grid);
    meta.insertMeta(openvdb::GridBase::META_FILE_DELAYED_LOAD, buffers.delayed);
    meta.writeMeta(os);
    grid.writeTransform(os);
    grid.writeTopology(os);
    for (const std::string& part : buffers.parts)
      os.write(part.data(), std::streamsize(part.size()));
    io::setStreamMetadataPtr(os, file, /*transfer=*/false);
  }
};

}  // namespace

std::string write_vdb_stream(const openvdb::GridPtrVec& grids) {
  return StreamWriter().bytes(grids);
}

}  // namespace maquette
