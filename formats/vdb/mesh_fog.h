// The insides of closed triangle meshes as fog volumes (README.md, "Fog volumes of closed
// meshes"): how a module that must not link OpenVDB (deform.water's lakes) gets the volume of a
// body it has meshed, through the plug-in libmaquette_vdb.so. This header needs no OpenVDB.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "content/content.h"

namespace maquette {

// A closed mesh to fill, with its voxel size (metres along the frame's x, y and z), a corner of
// its voxel lattice (voxel faces lie at corner + k * voxel, k integer: a flat face of the body
// on such a plane is cut by no voxel) and the name of its grid.
struct FogBody {
  MeshObject mesh;
  std::array<double, 3> voxel{};
  std::array<double, 3> corner{};
  std::string name;
};

// One float grid of class fog volume per body, in the bodies' order, in their frame (`origin` is
// the content's), voxel (i, j, k) centred at corner + (i + 1/2, j + 1/2, k + 1/2) * voxel: the
// voxels whose centres lie inside the mesh active, of density 1, the rest inactive, 0. Inside is
// found column by column (a scanline voxelization along z): each triangle's height where it
// covers a column's centre (a centre on an edge shared by two triangles counted in one of them
// only), the winding number up the column rising through faces seen from below and falling
// through faces seen from above; linear in the columns the triangles cover and the voxels set.
// In parallel (TBB) by blocks of triangles, then by the 8 x 8 columns of a VDB leaf, whose leaves
// are built whole (no per-voxel descent of the tree): the same bodies give the same bytes
// whatever the thread count. The active
// voxels' volume approximates the mesh's (exactly, for faces on the lattice's faces). Each grid's
// metadata carries its mesh's provenance ("object_id", "feature_id", "tool"), as volume_to_mesh
// reads it back (a grid named "water" meshes as water).
// Precondition: each mesh is closed and consistently oriented (counter-clockwise seen from
// outside), else the winding numbers are wrong. Throws maquette::Error naming `where` and the
// body for a voxel size that is not finite and positive, a corner not finite, a mesh without
// whole triangles or with an index out of range, a vertex not finite, or a mesh reaching beyond
// the grid's 32-bit voxel coordinates (+-2^31 voxels from the lattice's corner; naming the extent
// and the voxel size).
VolumeContent mesh_to_fog(const std::vector<FogBody>& bodies, const EnuOrigin& origin,
                          const std::string& where);

}  // namespace maquette
