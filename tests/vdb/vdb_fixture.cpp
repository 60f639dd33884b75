#include "vdb_fixture.h"

#include <openvdb/tools/LevelSetSphere.h>

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

}  // namespace maquette::test
