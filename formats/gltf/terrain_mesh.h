// The terrain mesh of one cell: a regular grid of vertices at the corners of every K-th pixel of
// the DEM tile (K: decimation), so a cell's edge vertices are corners its neighbours have too.
// A corner's height is the mean of the (up to 4) pixels around it, read through the tile's halo,
// and its position is computed from its global corner coordinates on the face: both cells of an
// edge compute the same values. Normals are central differences of the neighbouring corners,
// across face seams too (the corners beyond the face are placed on the next face), and the
// ellipsoid's normal at face corners, where three faces meet: a vertex shared by two cells gets
// the same normal in both. Skirts hang from the four edges, `skirt_depth` metres down, so
// that neighbours of different levels never show cracks. Corners without any valid pixel
// (nodata) are left out with their triangles. Heights are converted to the ellipsoid (`heights`)
// at the corners.
#pragma once

#include <cstdint>
#include <vector>

#include "core/grid.h"
#include "core/lonlat_bounds.h"
#include "core/tile.h"
#include "gdal/vertical_datum.h"
#include "gltf/local_frame.h"

namespace maquette {

// Also the geometry of content meshes, which may leave normals and texcoords empty.
struct TerrainMesh {
  // glTF axes (x east, y up, z south), metres from `offset`, 3 per vertex. Far from the export
  // frame's origin floats keep only ~1 m (at 10^7 m), so each mesh is written relative to an
  // offset at the mesh, its glTF node's translation (a double in the JSON); until quantized
  // (Lattice::rebase) the offset is 0 and positions are in the export's frame.
  std::vector<double> positions;
  Vec3 offset{};               // in the export's frame
  std::vector<float> normals;  // unit, 3 per vertex
  std::vector<float>
      texcoords;  // into the cell's imagery tile (0, 0 at its top-left), 2 per vertex
  std::vector<uint32_t> indices;          // triangles, counter-clockwise seen from above
  double min_height = 0, max_height = 0;  // above the ellipsoid, skirts included
  // Where a terrain mesh's vertices lie (degrees), longitudes unwrapped around the cell's centre
  // (west < -180 or east > 180 across the antimeridian); at_pole when one is at a pole.
  LonLatBounds lonlat{1e9, 90, -1e9, -90};
  bool at_pole = false;

  size_t vertex_count() const { return positions.size() / 3; }
};

// `dem` has a halo of at least 2 pixels; `decimation` divides its size; `heights` takes the DEM's
// heights to heights above the ellipsoid.
TerrainMesh build_terrain_mesh(const Grid& grid, CellId cell, const Tile<float>& dem,
                               int decimation, const LocalFrame& frame, double skirt_depth,
                               const EllipsoidalHeights& heights);

}  // namespace maquette
