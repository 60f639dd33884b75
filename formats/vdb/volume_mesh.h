// Volumes as meshes, for exports (README.md, "Meshing"): each grid of a volume meshed with
// OpenVDB's volumeToMesh into one closed, outward-facing triangle mesh in the volume's frame.
// This header needs no OpenVDB: the plug-in libmaquette_vdb.so exposes it to the program.
#pragma once

#include <string>

#include "content/content.h"

namespace maquette {

struct VolumeMeshSettings {
  // The surface of a fog volume: where its density crosses this value (the inside holds more).
  // Level sets are meshed at 0 (their zero crossing), whatever this is.
  double fog_isovalue = 0.5;
  // volumeToMesh's adaptivity, 0..1: 0 keeps one polygon per voxel crossing (the finest mesh),
  // larger values merge polygons where the surface is flat.
  double adaptivity = 0;
};

// One MeshObject per grid, in the volume's order and frame (the grids' world space): triangles
// counter-clockwise seen from outside (volumeToMesh's quads split along their first diagonal),
// vertex normals along the grid's gradient (pointing outwards), no texture coordinates. The
// material is water (blue, semi-transparent) for grids whose metadata "material" is "water", or
// without that metadata whose name is "water"; grey otherwise. Provenance from the grid's
// metadata "object_id", "feature_id" (int64) and "tool" (string) when present.
// Throws maquette::Error naming `where` for a volume that does not decode (decode_volume) or a
// grid that is not a float or double scalar grid.
MeshContent volume_to_mesh(const VolumeContent& volume, const VolumeMeshSettings& settings,
                           const std::string& where);

}  // namespace maquette
