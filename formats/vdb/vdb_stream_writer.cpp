#include "vdb/vdb_stream_writer.h"

#include <openvdb/io/Archive.h>
#include <openvdb/io/GridDescriptor.h>

#include <cstdint>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <vector>

#include "core/error.h"
#include "vdb/leaf_buffers.h"

namespace maquette {
namespace {

namespace io = openvdb::io;

// A grid to write, and the FogTree that stands for its tree when it has one.
struct Entry {
  openvdb::GridBase::ConstPtr grid;
  const FogTree* fog = nullptr;
};

// io::Stream's write (io::Archive::write and writeGrid of OpenVDB 10.0), float grids' leaves
// compressed by leaf_buffers, fog trees' written by write_fog_topology and fog_leaf_buffers.
class StreamWriter : public io::Archive {
 public:
  StreamWriter() {
    setCompression(io::COMPRESS_BLOSC | io::COMPRESS_ACTIVE_MASK);
    setGridStatsMetadataEnabled(false);
  }

  std::string bytes(const std::vector<Entry>& grids) const {
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
    for (const auto& [grid, fog] : grids) ++names[grid->getName()];
    std::set<std::string> unique;
    std::map<const openvdb::TreeBase*, io::GridDescriptor> trees;
    for (const auto& [grid, fog] : grids) {
      std::string name = grid->getName();
      if (name.empty() || names[name] > 1) name = io::GridDescriptor::addSuffix(name, 0);
      for (int n = 1; unique.count(name); ++n)
        name = io::GridDescriptor::addSuffix(grid->getName(), n);
      unique.insert(name);
      io::GridDescriptor gd(name, grid->type(), grid->saveFloatAsHalf());
      const auto tree = trees.find(&grid->baseTree());
      if (fog) {
        write_float_grid(gd, static_cast<const openvdb::FloatGrid&>(*grid), os, stream, fog);
      } else if (isInstancingEnabled() && tree != trees.end() &&
                 tree->second.saveFloatAsHalf() == gd.saveFloatAsHalf()) {
        gd.setInstanceParentName(tree->second.uniqueName());
        writeGridInstance(gd, grid, os, /*seekable=*/false);
      } else {
        const auto floats = openvdb::gridConstPtrCast<openvdb::FloatGrid>(grid);
        if (floats && !floats->saveFloatAsHalf())
          write_float_grid(gd, *floats, os, stream);
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
  // buffers from leaf_buffers. OpenVDB's stream keeps the address of the shared pointer it is given
  // (setStreamMetadataPtr stores &meta), so the file's metadata is restored from `file`, the
  // caller's pointer, which outlives the stream's use: a local copy would leave it dangling.
  void write_float_grid(io::GridDescriptor& gd, const openvdb::FloatGrid& grid, std::ostream& os,
                        io::StreamMetadata::Ptr& file, const FogTree* fog = nullptr) const {
    auto stream = std::make_shared<io::StreamMetadata>(*file);
    stream->setHalfFloat(false);
    stream->gridMetadata() = static_cast<const openvdb::MetaMap&>(grid);
    struct Restore {  // the file's metadata back on the stream however this ends, before `stream`
                      // dies
      std::ostream& os;
      io::StreamMetadata::Ptr& file;
      ~Restore() { io::setStreamMetadataPtr(os, file, /*transfer=*/false); }
    } restore{os, file};
    io::setStreamMetadataPtr(os, stream, /*transfer=*/false);
    gd.writeHeader(os);
    gd.writeStreamPos(os);
    setGridCompression(os, grid);
    const LeafBuffers buffers =
        fog ? fog_leaf_buffers(*fog, io::getDataCompression(os), compression())
            : leaf_buffers(grid.tree(), io::getDataCompression(os), compression());
    openvdb::MetaMap meta(grid);
    meta.insertMeta(openvdb::GridBase::META_FILE_DELAYED_LOAD, buffers.delayed);
    meta.writeMeta(os);
    grid.writeTransform(os);
    if (fog)
      write_fog_topology(os, *fog);
    else
      grid.writeTopology(os);
    for (const std::string& part : buffers.parts)
      os.write(part.data(), std::streamsize(part.size()));
  }
};

}  // namespace

std::string write_vdb_stream(const openvdb::GridPtrVec& grids) {
  std::vector<Entry> entries;
  for (const auto& grid : grids) entries.push_back({grid});
  return StreamWriter().bytes(entries);
}

std::string write_vdb_stream(const std::vector<FogGrid>& grids) {
  std::vector<Entry> entries;
  for (size_t i = 0; i < grids.size(); ++i) {
    if (!grids[i].grid) throw Error("VDB writer: fog grid " + std::to_string(i) + " is null");
    if (grids[i].grid->saveFloatAsHalf())
      throw Error("VDB writer: fog grid " + std::to_string(i) +
                  " is saved as half floats (a fog tree is written as full floats only)");
    entries.push_back({grids[i].grid, &grids[i].tree});
  }
  return StreamWriter().bytes(entries);
}

}  // namespace maquette
