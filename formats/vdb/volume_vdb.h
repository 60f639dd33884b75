// Volumes as the store holds them (content.h, VolumeContent): OpenVDB grids in a cell's
// east-north-up frame (metres; each grid's transform maps its index space into that frame),
// written as one openvdb::io::Stream whose bytes depend on the grids only (README.md): the same
// grids give the same bytes in any process, on any thread count.
#pragma once

#include <openvdb/openvdb.h>

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "content/content.h"
#include "vdb/vdb_stream_writer.h"

namespace maquette {

// Where the header of a VDB stream holds its UUID (36 ASCII characters, 8-4-4-4-12 hex digits):
// after the magic (8 bytes), the file format version and the library's major and minor versions
// (3 x u32) and the "has grid offsets" flag (1 byte). OpenVDB writes a random one;
// encode_volume writes a name-based UUID (version 5, SHA-1) of all the other bytes instead, which
// decode_volume checks: a checksum of the stream.
inline constexpr size_t kVdbUuidOffset = 21;
inline constexpr size_t kVdbUuidBytes = 36;

// The grids (none null) as a VDB stream, Blosc-compressed with active-mask compression
// (OpenVDB's default), no grid statistics metadata (file_bbox_*, file_mem_bytes, ...: the
// in-memory size depends on the library build, not on the grids), the grids' own metadata,
// names and transforms kept, in the given order. Throws maquette::Error for a null grid.
VolumeContent encode_volume(const openvdb::GridPtrVec& grids, const EnuOrigin& origin);

// The same for the grids fog grids stand for (vdb_stream_writer.h), without building their trees:
// the same bytes as encode_volume of those grids.
VolumeContent encode_volume(const std::vector<FogGrid>& grids, const EnuOrigin& origin);

// The grids of a volume written by encode_volume, in the order written. Throws maquette::Error
// naming `where` (e.g. "layer lakes, cell N3021") for bytes that are not one whole such stream:
// not a VDB, any byte changed or missing (the UUID disagrees), and, in a stream whose UUID
// agrees, what OpenVDB refuses (an unknown grid type, ...), a truncated grid, trailing bytes.
openvdb::GridPtrVec decode_volume(const VolumeContent& volume, const std::string& where);

// What `maquette info` counts: grids as objects, their active voxels (active tiles counted
// voxel by voxel); no triangles.
ContentStats volume_stats(const openvdb::GridPtrVec& grids);

// Each grid's anchor (content/content.h): the centre of the bounding box of its active voxels,
// in the volume's frame (metres, through the grid's transform), or nothing for a grid without
// active voxels.
std::vector<std::optional<std::array<double, 3>>> volume_anchors(const openvdb::GridPtrVec& grids);

}  // namespace maquette
