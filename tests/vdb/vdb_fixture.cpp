#include "vdb_fixture.h"

#include <openvdb/io/Stream.h>
#include <openvdb/tools/LevelSetSphere.h>

#include <algorithm>
#include <sstream>

#include "vdb/volume_vdb.h"

namespace maquette::test {

openvdb::FloatGrid::Ptr sphere_level_set(const std::string& name) {
  openvdb::initialize();
  auto grid = openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(
      float(kSphereRadius), openvdb::Vec3f(kSphereCentre), float(kSphereVoxel));
  grid->setName(name);
  return grid;
}

openvdb::FloatGrid::Ptr fog_box(const openvdb::CoordBBox& box, double voxel,
                                const std::string& name) {
  openvdb::initialize();
  auto grid = openvdb::FloatGrid::create(0.0f);
  grid->setTransform(openvdb::math::Transform::createLinearTransform(voxel));
  grid->setGridClass(openvdb::GRID_FOG_VOLUME);
  grid->fill(box, 1.0f, /*active=*/true);
  grid->setName(name);
  return grid;
}

std::string openvdb_bytes(const openvdb::GridPtrVec& grids) {
  std::ostringstream out(std::ios::binary);
  openvdb::io::Stream stream(out);
  stream.setCompression(openvdb::io::COMPRESS_BLOSC | openvdb::io::COMPRESS_ACTIVE_MASK);
  stream.setGridStatsMetadataEnabled(false);
  stream.write(grids);
  return without_uuid(std::move(out).str());
}

std::string without_uuid(std::string stream) {
  return stream.replace(kVdbUuidOffset, kVdbUuidBytes, kVdbUuidBytes, '-');
}

std::string compare_bytes(const std::string& a, const std::string& b) {
  if (a == b) return "same";
  const auto [i, j] = std::mismatch(a.begin(), a.end(), b.begin(), b.end());
  return "first difference at byte " + std::to_string(i - a.begin()) + " of " +
         std::to_string(a.size()) + " and " + std::to_string(b.size());
}

}  // namespace maquette::test
