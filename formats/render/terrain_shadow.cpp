#include "render/terrain_shadow.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "gdal/vertical_datum.h"
#include "image/layer_sampler.h"
#include "render/cast_shadow.h"

namespace maquette {
namespace {

// The DEM under the ENU plane's point (e, n), as the up coordinate of the terrain there: the
// geodetic point under (e, n) at the up found so far, twice (the second look corrects the
// first's lean of the local vertical, 1 m per 6.4 km of distance and metre of height).
std::optional<double> terrain_up(LayerSampler& sampler, const Grid& grid, const LayerInfo& dem,
                                 const EllipsoidalHeights& heights, const EnuFrame& frame,
                                 double exaggeration, double e, double n) {
  double up = 0;
  for (int look = 0; look < 2; ++look) {
    const GeodeticPoint g = frame.to_geodetic(e, n, up);
    const LonLat p{g.lon, g.lat};
    float z = NAN;
    if (!sampler.sample(p, grid.cell_from_point(p, dem.level), &z) || std::isnan(z))
      return std::nullopt;
    up = frame.to_enu(p.lon, p.lat, heights(p, z) + (exaggeration - 1) * z)[2];
  }
  return up;
}

}  // namespace

std::vector<uint8_t> shadow_vertices(std::shared_ptr<LayerSampler::Tiles> tiles, const Grid& grid,
                                     const LayerInfo& dem, const TerrainScene& scene,
                                     const PinholeCamera& camera, double exaggeration,
                                     double sun_azimuth, double sun_altitude) {
  const auto& pos = scene.mesh.positions;
  const size_t vertices = pos.size() / 3;
  if (vertices == 0) return {};
  double west = pos[0], east = pos[0], south = pos[1], north = pos[1];
  for (size_t v = 0; v < vertices; ++v) {
    west = std::min(west, pos[3 * v]);
    east = std::max(east, pos[3 * v]);
    south = std::min(south, pos[3 * v + 1]);
    north = std::max(north, pos[3 * v + 1]);
  }
  HeightGrid heights_grid;
  double spacing = grid.level_info(dem.level, dem.tile_size).pixel_m;
  const double area = (east - west + spacing) * (north - south + spacing);
  spacing = std::max(spacing, std::sqrt(area / double(kMaxShadowNodes)));
  heights_grid.spacing = spacing;
  heights_grid.x0 = west;
  heights_grid.y0 = north;
  heights_grid.width = int(std::ceil((east - west) / spacing)) + 1;
  heights_grid.height = int(std::ceil((north - south) / spacing)) + 1;
  heights_grid.z.assign(size_t(heights_grid.width) * size_t(heights_grid.height), NAN);

  const EllipsoidalHeights& heights = *scene.heights;  // the scene's datum, read once
  // The DEM's tiles (the scene's) and their halos assembled once for all threads.
  tbb::enumerable_thread_specific<std::optional<LayerSampler>> samplers;
  tbb::parallel_for(0, heights_grid.height, [&](int row) {
    auto& sampler = samplers.local();
    if (!sampler) sampler.emplace(tiles, LayerSampler::Read::kBilinear);
    for (int col = 0; col < heights_grid.width; ++col) {
      const auto up = terrain_up(*sampler, grid, dem, heights, camera.frame(), exaggeration,
                                 west + col * spacing, north - row * spacing);
      if (up) heights_grid.z[size_t(row) * size_t(heights_grid.width) + size_t(col)] = float(*up);
    }
  });

  const CastShadow shadow(heights_grid, sun_azimuth, sun_altitude);
  std::vector<uint8_t> flags(vertices, 0);
  tbb::parallel_for(size_t(0), vertices, [&](size_t v) {
    flags[v] = shadow.shadowed(pos[3 * v], pos[3 * v + 1], pos[3 * v + 2]);
  });
  return flags;
}

}  // namespace maquette
