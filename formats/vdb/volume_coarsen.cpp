#include "vdb/volume_coarsen.h"

#include <openvdb/tools/Composite.h>
#include <openvdb/tools/GridTransformer.h>

#include <algorithm>
#include <map>

#include "content/enu_transform.h"
#include "core/error.h"
#include "vdb/volume_vdb.h"

namespace maquette {
namespace {

// A child's grid with the transform that maps its index space into the parent's frame.
struct Part {
  openvdb::GridBase::ConstPtr grid;
  openvdb::math::Transform::Ptr to_parent;
};

openvdb::math::Transform::Ptr moved_transform(const openvdb::GridBase& grid,
                                              const EnuTransform& to_parent) {
  const auto m = to_parent.matrix();
  // OpenVDB multiplies row vectors: its matrix is the transpose of the column-vector one.
  openvdb::Mat4d rigid;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) rigid(j, i) = m[size_t(4 * i + j)];
  auto xform = grid.transform().copy();
  xform->postMult(rigid);
  return xform;
}

template <class GridT>
openvdb::GridBase::Ptr merged(const std::vector<Part>& parts, double voxel) {
  const auto& first = static_cast<const GridT&>(*parts.front().grid);
  const bool level_set = first.getGridClass() == openvdb::GRID_LEVEL_SET;
  typename GridT::Ptr out;
  for (const Part& part : parts) {
    const auto moved =
        openvdb::GridBase::constGrid<GridT>(part.grid->copyGridReplacingTransform(part.to_parent));
    // A level set's background is its band's half width in metres: the same band in voxels
    // twice as large is twice as wide.
    const auto background =
        level_set ? typename GridT::ValueType(2 * moved->background()) : moved->background();
    auto resampled = GridT::create(background);
    resampled->setTransform(openvdb::math::Transform::createLinearTransform(voxel));
    resampled->setGridClass(first.getGridClass());
    openvdb::tools::resampleToMatch<openvdb::tools::BoxSampler>(*moved, *resampled);
    if (!out)
      out = resampled;
    else if (level_set)
      openvdb::tools::csgUnion(*out, *resampled);
    else
      openvdb::tools::compMax(*out, *resampled);
  }
  out->insertMeta(first);
  out->setName(first.getName());
  out->setGridClass(first.getGridClass());
  return out;
}

}  // namespace

openvdb::GridPtrVec coarsen_volumes(std::span<const VolumeContent> children,
                                    const ContentLevel& level, const std::string& where) {
  std::vector<std::string> names;  // in order of first appearance
  std::map<std::string, std::vector<Part>> parts;
  for (const VolumeContent& child : children) {
    const EnuTransform to_parent(child.origin, level.origin);
    for (const auto& grid : decode_volume(child, where)) {
      if (!grid->isType<openvdb::FloatGrid>() && !grid->isType<openvdb::DoubleGrid>())
        throw Error(where + ": grid '" + grid->getName() + "' is a " + grid->type() +
                    ", not a float or double scalar grid");
      auto& group = parts[grid->getName()];
      if (group.empty())
        names.push_back(grid->getName());
      else if (group.front().grid->type() != grid->type() ||
               group.front().grid->getGridClass() != grid->getGridClass())
        throw Error(where + ": grids named '" + grid->getName() +
                    "' differ in type or class between children");
      group.push_back({grid, moved_transform(*grid, to_parent)});
    }
  }
  openvdb::GridPtrVec out;
  for (const std::string& name : names) {
    const auto& group = parts[name];
    double voxel = 0;
    for (const Part& p : group) voxel = std::max(voxel, p.grid->voxelSize()[0]);
    auto grid = group.front().grid->isType<openvdb::FloatGrid>()
                    ? merged<openvdb::FloatGrid>(group, 2 * voxel)
                    : merged<openvdb::DoubleGrid>(group, 2 * voxel);
    if (grid->activeVoxelCount() > 0) out.push_back(grid);
  }
  return out;
}

}  // namespace maquette
