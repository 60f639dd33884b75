// Grids with known geometry for the volume tests: a sphere level set and a fog volume box, away
// from their frame's origin (a cell's content is offset from the cell's ENU origin).
#pragma once

#include <openvdb/openvdb.h>

#include <string>

#include "content/content.h"

namespace maquette::test {

inline constexpr double kSphereRadius = 10;   // metres
inline constexpr double kSphereVoxel = 0.25;  // metres
inline const openvdb::Vec3d kSphereCentre(1203.1, -347.6, 41.3);

// openvdb::tools::createLevelSetSphere of kSphereRadius at kSphereCentre, named `name`.
openvdb::FloatGrid::Ptr sphere_level_set(const std::string& name);

// A fog volume (density 1 inside, background 0) filling the voxels of index box `box`, voxel
// side `voxel` metres, named `name`.
openvdb::FloatGrid::Ptr fog_box(const openvdb::CoordBBox& box, double voxel,
                                const std::string& name);

// OpenVDB's own writer (io::Stream) of `grids` with encode_volume's options (Blosc, active-mask
// compression, no grid statistics metadata), the oracle of our writer.
std::string openvdb_bytes(const openvdb::GridPtrVec& grids);

// A VDB stream with its header's UUID (random in OpenVDB's, the content's in ours) blanked.
std::string without_uuid(std::string stream);

// "same", or where two streams first differ (a failure prints this, not megabytes of bytes).
std::string compare_bytes(const std::string& a, const std::string& b);

inline const EnuOrigin kVolumeOrigin{-122.3321, 47.6062, 56.0};

}  // namespace maquette::test
