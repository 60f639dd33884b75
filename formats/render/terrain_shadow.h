// Cast shadows on a panorama's terrain (render/cast_shadow.h): the DEM resampled on a square grid
// of the camera's east-north-up plane (heights along its up axis, so the earth's curvature is in
// them and the sun's parallel rays are straight lines), a node every DEM sample (coarser when the
// terrain's extent would need more than kMaxNodes), the sun's azimuth and altitude those of the
// eye's frame (as the hillshade's). Each vertex of the scene is then tested against that grid.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "core/grid.h"
#include "image/layer_sampler.h"
#include "render/camera.h"
#include "render/terrain_scene.h"
#include "store/store.h"

namespace maquette {

constexpr size_t kMaxShadowNodes = size_t(1) << 24;

// 1 for each vertex of `scene` (unbent: before render/progressive_bend.h) in the shadow of the
// terrain, 0 elsewhere. `dem` and `exaggeration` are those `scene` was built from; the sun's
// altitude in (0, 90) degrees. Nodes are sampled in parallel, each on its own, and the march
// gives the same bits for any threads. `tiles`: the DEM's LayerSampler::shared_tiles at its level
// (those `scene` was built from).
std::vector<uint8_t> shadow_vertices(std::shared_ptr<LayerSampler::Tiles> tiles, const Grid& grid,
                                     const LayerInfo& dem, const TerrainScene& scene,
                                     const PinholeCamera& camera, double exaggeration,
                                     double sun_azimuth, double sun_altitude);

}  // namespace maquette
