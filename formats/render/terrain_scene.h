// The terrain a panorama draws: a DEM layer's full-resolution tiles as one triangle mesh in a
// camera's ENU frame. Each tile, padded with a one-pixel halo from its neighbours (core/halo.h,
// across face seams too), gives a vertex at every sample centre (core/tile_frame.h: where the
// sample really lies) and two triangles per square of four samples, always split along the same
// diagonal; the halo's squares close the gaps between tiles, so neighbouring tiles share edges
// and no square is drawn twice. Squares with a missing sample (nodata, no neighbour tile) are left
// out. Heights go to the ellipsoid through the layer's vertical datum, exaggerated by a factor
// above that datum. Tiles are built in parallel and joined in their cell order: the mesh is the
// same whatever the threads.
#pragma once

#include <optional>
#include <vector>

#include "core/grid.h"
#include "render/camera.h"
#include "render/rasterizer.h"
#include "store/store.h"

namespace maquette {

struct TerrainScene {
  RenderMesh mesh;
  std::vector<double> lonlat;   // degrees, 2 per vertex
  std::vector<float> altitude;  // the DEM's height (its own datum, not exaggerated), per vertex
  // Unit normals in the camera's ENU frame (central differences of the exaggerated surface,
  // one-sided at a tile's border), 3 per vertex.
  std::vector<float> normals;
};

// `dem`: a one-channel raster layer of heights in metres; `exaggeration` > 0.
TerrainScene build_terrain_scene(const Store& store, const Grid& grid, const LayerInfo& dem,
                                 const PinholeCamera& camera, double exaggeration);

// The DEM's height at `p` converted to the ellipsoid (bilinear between samples); nullopt where
// the layer has no data.
std::optional<double> terrain_ellipsoidal_height(const Store& store, const Grid& grid,
                                                 const LayerInfo& dem, LonLat p);

}  // namespace maquette
