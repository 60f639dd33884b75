// Volumes for the coarser levels of a volume layer (content/content_overviews.h): a parent
// cell's grids from its children's, with OpenVDB's tools.
#pragma once

#include <openvdb/openvdb.h>

#include <span>
#include <string>

#include "content/content.h"
#include "content/content_overviews.h"

namespace maquette {

// The children's grids (each a float or double scalar grid of uniform voxels), those of the same
// name merged into one, in order of first appearance (child order, then the grids' order):
// - each grid is moved into the parent's frame (its transform followed by the rigid map from its
//   child's ENU frame to level.origin's, content/enu_transform.h) and resampled
//   (tools::resampleToMatch, box sampler; a level set is rebuilt at its zero crossing with a
//   band of the same width in voxels) into a grid of twice the largest voxel size of its name,
//   with a linear transform whose index origin is level.origin;
// - level sets are merged by CSG union, fog volumes by the maximum density;
// - the merged grid keeps the name, class and metadata of the first grid of its name; a grid
//   left without active voxels is dropped.
// Throws maquette::Error naming `where` for a grid of another type, or grids of one name
// differing in type or class.
openvdb::GridPtrVec coarsen_volumes(std::span<const VolumeContent> children,
                                    const ContentLevel& level, const std::string& where);

}  // namespace maquette
