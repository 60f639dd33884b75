#include "vdb/volume_vdb.h"

#include <openssl/evp.h>
#include <openvdb/io/Stream.h>

#include <algorithm>
#include <array>
#include <boost/uuid/uuid.hpp>
#include <boost/uuid/uuid_io.hpp>
#include <cstdint>
#include <memory>
#include <sstream>
#include <utility>

#include "core/error.h"

namespace maquette {

namespace {

constexpr size_t kVdbHeaderBytes = kVdbUuidOffset + kVdbUuidBytes;
constexpr std::string_view kVdbMagic{" BDV\0\0\0\0", 8};

// The UUID encode_volume writes: name-based (RFC 4122 version 5: SHA-1 of the nil namespace's
// 16 zero bytes and the name, nil namespace) of every byte of the stream but the UUID's own.
// OpenSSL's SHA-1 (the processor's SHA instructions where it has them) over the two parts in
// place: the same UUID as Boost's name generator, without its copy of the stream and ~10x faster.
std::string content_uuid(std::string_view stream) {
  const std::unique_ptr<EVP_MD_CTX, decltype(&EVP_MD_CTX_free)> sha1(EVP_MD_CTX_new(),
                                                                     &EVP_MD_CTX_free);
  const std::array<unsigned char, 16> nil{};
  std::array<unsigned char, EVP_MAX_MD_SIZE> digest{};
  unsigned int size = 0;
  if (!sha1 || !EVP_DigestInit_ex(sha1.get(), EVP_sha1(), nullptr) ||
      !EVP_DigestUpdate(sha1.get(), nil.data(), nil.size()) ||
      !EVP_DigestUpdate(sha1.get(), stream.data(), kVdbUuidOffset) ||
      !EVP_DigestUpdate(sha1.get(), stream.data() + kVdbHeaderBytes,
                        stream.size() - kVdbHeaderBytes) ||
      !EVP_DigestFinal_ex(sha1.get(), digest.data(), &size))
    throw Error("VDB stream's UUID: OpenSSL's SHA-1 failed");
  boost::uuids::uuid uuid;
  std::copy_n(digest.begin(), uuid.size(), uuid.begin());
  uuid.data[6] = uint8_t((uuid.data[6] & 0x0F) | 0x50);  // version 5
  uuid.data[8] = uint8_t((uuid.data[8] & 0x3F) | 0x80);  // RFC 4122 variant
  return boost::uuids::to_string(uuid);
}

// The volume of `stream`, its random UUID replaced with the content's (README.md).
VolumeContent named(const EnuOrigin& origin, std::string stream) {
  VolumeContent volume{origin, std::move(stream)};
  volume.vdb.replace(kVdbUuidOffset, kVdbUuidBytes, content_uuid(volume.vdb));
  return volume;
}

}  // namespace

VolumeContent encode_volume(const openvdb::GridPtrVec& grids, const EnuOrigin& origin) {
  openvdb::initialize();
  for (size_t i = 0; i < grids.size(); ++i) {
    if (!grids[i]) throw Error("encode_volume: grid " + std::to_string(i) + " is null");
  }
  return named(origin, write_vdb_stream(grids));
}

VolumeContent encode_volume(const std::vector<FogGrid>& grids, const EnuOrigin& origin) {
  openvdb::initialize();
  return named(origin, write_vdb_stream(grids));
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
