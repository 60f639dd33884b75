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
// the content's): OpenVDB's meshToLevelSet of the mesh, voxel (i, j, k) centred at corner +
// (i + 1/2, j + 1/2, k + 1/2) * voxel, then sdfToFogVolume: the voxels whose centres lie inside the
// mesh active, 1 at least a voxel deep, ramping to 0 towards the surface; outside inactive, 0.
// The active voxels' volume approximates the mesh's (the error is of the order of a voxel layer
// over the surface). Each grid's metadata carries its mesh's provenance ("object_id",
// "feature_id", "tool"), as volume_to_mesh reads it back (a grid named "water" meshes as water).
// The same bodies give the same bytes whatever the thread count.
// Precondition: each mesh is closed (each edge in two triangles), as meshToLevelSet's inside and
// outside need (its sign comes from a flood fill of the outside, not from the winding). Throws
// maquette::Error naming `where` and the body for a voxel size that is not finite and positive, a
// corner not finite, a mesh without whole triangles or with an index out of range.
VolumeContent mesh_to_fog(const std::vector<FogBody>& bodies, const EnuOrigin& origin,
                          const std::string& where);

}  // namespace maquette
