#include "vdb/volume_vdb.h"

#include <openvdb/io/Stream.h>

#include <boost/uuid/name_generator_sha1.hpp>
#include <boost/uuid/nil_generator.hpp>
#include <boost/uuid/uuid_io.hpp>
#include <sstream>

#include "core/error.h"

namespace maquette {

namespace {

constexpr size_t kVdbHeaderBytes = kVdbUuidOffset + kVdbUuidBytes;
constexpr std::string_view kVdbMagic{" BDV\0\0\0\0", 8};

// The UUID encode_volume writes: name-based (version 5, SHA-1, nil namespace) of every byte of
// the stream but the UUID's own.
std::string content_uuid(std::string_view stream) {
  std::string name(stream.substr(0, kVdbUuidOffset));
  name += stream.substr(kVdbHeaderBytes);
  const boost::uuids::name_generator_sha1 generate(boost::uuids::nil_uuid());
  return boost::uuids::to_string(generate(name.data(), name.size()));
}

}  // namespace

VolumeContent encode_volume(const openvdb::GridPtrVec& grids, const EnuOrigin& origin) {
  openvdb::initialize();
  for (size_t i = 0; i < grids.size(); ++i) {
    if (!grids[i]) throw Error("encode_volume: grid " + std::to_string(i) + " is null");
  }
  std::ostringstream out(std::ios::binary);
  openvdb::io::Stream stream(out);
  stream.setCompression(openvdb::io::COMPRESS_BLOSC | openvdb::io::COMPRESS_ACTIVE_MASK);
  stream.setGridStatsMetadataEnabled(false);
  stream.write(grids);
  VolumeContent volume{origin, std::move(out).str()};
  // OpenVDB drew a random UUID: the content's instead (README.md).
  volume.vdb.replace(kVdbUuidOffset, kVdbUuidBytes, content_uuid(volume.vdb));
  return volume;
}

openvdb::GridPtrVec decode_volume(const VolumeContent& volume, const std::string& where) {
  openvdb::initialize();
  const auto refuse = [&](const std::string& why) {
    return Error(where + ": the volume is not a whole VDB stream (" +
                 std::to_string(volume.vdb.size()) + " bytes): " + why);
  };
  const std::string_view vdb = volume.vdb;
  if (vdb.size() < kVdbHeaderBytes || !vdb.starts_with(kVdbMagic)) throw refuse("no VDB header");
  // The UUID doubles as a checksum: OpenVDB never reads bytes that are not the ones written.
  if (vdb.substr(kVdbUuidOffset, kVdbUuidBytes) != content_uuid(vdb)) {
    throw refuse(
        "its bytes are not those written (the UUID in its header is not theirs): "
        "corrupted or truncated");
  }
  std::istringstream in(volume.vdb, std::ios::binary);
  openvdb::GridPtrVecPtr grids;
  try {
    openvdb::io::Stream stream(in, /*delayLoad=*/false);
    grids = stream.getGrids();
  } catch (const std::exception& e) {  // openvdb::Exception, std::bad_alloc of a corrupted size
    throw refuse(e.what());
  }
  if (in.fail()) throw refuse("truncated");
  if (in.peek() != std::char_traits<char>::eof()) {
    throw refuse(std::to_string(volume.vdb.size() - size_t(in.tellg())) +
                 " bytes after its last grid");
  }
  return grids ? *grids : openvdb::GridPtrVec{};
}

std::vector<std::optional<std::array<double, 3>>> volume_anchors(const openvdb::GridPtrVec& grids) {
  std::vector<std::optional<std::array<double, 3>>> anchors;
  for (const auto& grid : grids) {
    const openvdb::CoordBBox box = grid->evalActiveVoxelBoundingBox();
    if (grid->activeVoxelCount() == 0 || box.empty()) {
      anchors.emplace_back();
      continue;
    }
    const openvdb::Vec3d centre = grid->indexToWorld(box.getCenter());
    anchors.push_back(std::array<double, 3>{centre.x(), centre.y(), centre.z()});
  }
  return anchors;
}

ContentStats volume_stats(const openvdb::GridPtrVec& grids) {
  ContentStats stats;
  stats.objects = grids.size();
  for (const auto& grid : grids) stats.voxels += grid->activeVoxelCount();
  return stats;
}

}  // namespace maquette
