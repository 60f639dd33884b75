// Fog volumes given column by column (README.md, "Fog volumes of voxel columns"): how a module
// that must not link OpenVDB (deform.water's lakes, from their depth rasters) gets a volume,
// through the plug-in libmaquette_vdb.so. This header needs no OpenVDB.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "content/content.h"

namespace maquette {

// A body as a dense raster of voxel columns on an affine lattice: voxel (i, j, k) is centred at
// centre + i * axes[0] + j * axes[1] + k * axes[2] (metres in the frame), and column (i, j),
// 0 <= i < width, 0 <= j < height, held at [j * width + i], has its voxels low <= k < high
// (none when low >= high).
struct FogColumns {
  int32_t width = 0, height = 0;
  std::vector<int32_t> low, high;
  std::array<std::array<double, 3>, 3> axes{};
  std::array<double, 3> centre{};
  ObjectProvenance provenance;
  std::string name;
};

// One float grid of class fog volume per body, in the bodies' order, in their frame (`origin` is
// the content's), on the body's lattice (a linear transform; its index origin the voxel at
// `centre`): the columns' voxels active, of density 1, the rest inactive, 0; an 8^3 region of a
// leaf that all its 64 columns fill is an active tile (no leaf: less to build and write; its
// voxels count and mesh as the leaf's would). Built in parallel (TBB) by the 8 x 8 columns of a
// VDB leaf, each block's leaves' masks whole, into a FogTree (fog_tree.h: no OpenVDB tree, no
// leaf buffer) sorted in tree order and written from it: the same bytes as OpenVDB's writer of
// the tree of these voxels, whatever the thread count. Time linear in the columns and the leaves
// set (and n log n in the leaves, their sort); memory linear in the columns and the leaves. Each
// grid's metadata carries the provenance ("object_id", "feature_id", "tool"), as volume_to_mesh
// reads it back (a grid named "water" meshes as water). Throws maquette::Error naming `where` and
// the body for a negative size, low or high not of width * height columns, an axis or the centre
// not finite, axes that do not span space, or a column whose voxels reach beyond +-2^30 (the
// grid's 32-bit coordinates with room for a leaf).
VolumeContent columns_to_fog(const std::vector<FogColumns>& bodies, const EnuOrigin& origin,
                             const std::string& where);

}  // namespace maquette
