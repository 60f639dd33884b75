// A panorama and its guides from what each pixel sees (render/rasterizer.h) of a terrain scene
// (render/terrain_scene.h): the surface's colour (an imagery layer sampled bilinearly at the
// pixel's lon/lat, stretched for display, or a plain earth colour), shaded by the DEM's normals
// under a sun, faded into the haze with distance (aerial perspective: a fraction 1 - exp(-distance
// / haze_distance) of the haze colour), over a sky graded from the haze colour at the horizon to
// blue at 30 degrees up. Guides per pixel: the DEM's altitude, the distance from the eye, lon/lat,
// the land-cover class when a categorical layer is given (nearest sample), and silhouettes: terrain
// pixels on the near side of a depth discontinuity (a 4-neighbour is sky or more than
// `silhouette_jump` times farther). Rows are shaded in parallel, each pixel from its own fragment:
// the same bits for any threads.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/grid.h"
#include "render/rasterizer.h"
#include "render/terrain_scene.h"
#include "store/store.h"

namespace maquette {

struct PanoramaLook {
  const LayerInfo* texture = nullptr;     // uint8 imagery of 1, 3 or 4 channels, or none
  const LayerInfo* land_cover = nullptr;  // a categorical layer, or none
  // The texture with the quicklooks' display stretch (image/stretch.h: 2-98 % of each band over
  // the texels the picture shows), or as stored.
  bool stretch = true;
  double sun_azimuth = 315, sun_altitude = 45;  // degrees (clockwise from north, above horizon)
  double haze_distance = 60000;                 // metres
  double silhouette_jump = 1.05;
  // Per vertex of the scene, 1 in the terrain's cast shadow (render/terrain_shadow.h), or none:
  // a shadowed surface gets the hillshade's ambient share only, as a slope facing away does.
  const std::vector<uint8_t>* shadow = nullptr;
};

struct Panorama {
  int width = 0, height = 0;
  std::vector<uint8_t> rgb;  // 3 per pixel, row-major
  // Per pixel, NaN on the sky: metres of the DEM's datum, metres from the eye, degrees, class.
  std::vector<double> altitude, distance, lon, lat, land_cover;
  std::vector<double> cast_shadow;  // with PanoramaLook::shadow: 0 (sunlit) to 1 (in shadow)
  std::vector<uint8_t> silhouette;  // 255 on a silhouette, 0 elsewhere
};

Panorama shade_panorama(const Store& store, const Grid& grid, const TerrainScene& scene,
                        const Fragments& fragments, const PinholeCamera& camera,
                        const PanoramaLook& look);

// Writes OUT (PNG, the picture), OUT's stem + "-guides.tif" (a float64 GeoTIFF, no
// georeferencing, one band each: altitude, distance, lon, lat, and land_cover and cast_shadow
// when computed; NaN on the sky) and stem + "-silhouettes.png" (8-bit). Each file whole or not at
// all.
void write_panorama(const Panorama& panorama, const std::string& out);

}  // namespace maquette
