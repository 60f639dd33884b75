// A panorama and its guides from what each pixel sees (render/rasterizer.h) of a terrain scene
// (render/terrain_scene.h): the surface's colour (an imagery layer sampled bilinearly where the
// pixel sees it: at the point of the grid's plane interpolated in its triangle, or at its lon/lat
// where a corner is off its tile's face; stretched for display; where it has no texel, the nearest
// texel's within a reach (render/edge_texels.h), the stretch taken over the imagery's own texels
// only; beyond, the middle of the display range, grey 128; without imagery, an earth colour),
// shaded by the DEM's normals under a sun, faded into the haze with distance (aerial perspective: a
// fraction 1 - exp(-distance / haze_distance) of the haze colour), over a sky graded from the haze
// colour at the horizon to blue at 30 degrees up (render/sky.h). Guides per pixel: the DEM's
// altitude, the distance from the eye, lon/lat, the land-cover class when a categorical layer is
// given (nearest sample), the shading factor, and silhouettes: terrain pixels on the near side of
// a depth discontinuity (a 4-neighbour is sky or more than `silhouette_jump` times farther). Rows
// are shaded in parallel, each pixel from its own fragment: the same bits for any threads. A strip
// of rows of the picture (render/panorama_strips.h) is shaded as the same rows of the whole
// picture, given the whole picture's display stretch (its texels are those of the pixels on a grid
// of stretch_step, gathered strip by strip).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/grid.h"
#include "image/stretch.h"
#include "render/rasterizer.h"
#include "render/terrain_scene.h"
#include "store/store.h"

namespace maquette {

// Terrain the texture has no texel for takes its nearest texel's colour within this many texels
// of the texture's level (render/edge_texels.h: the imagery carried past its edge; Zion's DEM
// reaches up to 17 of its 35 m texels past the Landsat scene); farther, grey 128.
constexpr int kTextureReach = 32;

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

// Its arrays are FreshArrays (render/fresh_array.h): shade_panorama writes every pixel of each it
// sizes (NaN guides on the sky).
struct Panorama {
  int width = 0, height = 0;
  int first_row = 0;        // of the picture: the panorama may be a strip of it
  FreshArray<uint8_t> rgb;  // 3 per pixel, row-major
  // Per pixel, NaN on the sky: metres from the eye, degrees (float64: the haze and silhouettes
  // are computed from the distance, lon/lat to a millimetre); metres of the DEM's datum and
  // class (float32: a tenth of a millimetre at 2 km, the DEM's own float32; fewer fresh pages).
  FreshArray<double> distance, lon, lat;
  FreshArray<float> altitude, land_cover;
  FreshArray<float> cast_shadow;  // with PanoramaLook::shadow: 0 (sunlit) to 1 (in shadow)
  // The factor the surface's colour was shaded by: hillshade times sunlit share, 0.3 to 1 (the
  // transfer in the picture blends its colours with it).
  FreshArray<float> shading;
  FreshArray<uint8_t> silhouette;  // 255 on a silhouette, 0 elsewhere
};

using BandStretch = std::array<StretchRange, 3>;          // per band of the texture
using StretchTexels = std::array<std::vector<float>, 3>;  // texels per band

// The display stretch is taken over the texels of the pixels whose row and column are multiples
// of this step: 1 up to 4 MP, about 4 M pixels above.
int stretch_step(int width, int height);

// Appends to `texels` those of the terrain pixels of `f` on the grid of `step` (picture rows, so
// the strips of a picture gather the whole picture's); nothing without a texture to stretch.
// `scratch`: resized to 3 floats a pixel of `f`, written and read on those pixels only (its memory
// reused by the strips of a picture).
void gather_stretch_texels(const Store& store, const Grid& grid, const TerrainScene& scene,
                           const Fragments& f, const PanoramaLook& look, int step,
                           StretchTexels& texels, FreshArray<float>& scratch);

// The stretch of `texels` (which it reorders): the 2 and 98 % quantiles per band, or the values as
// stored without a texture or with look.stretch false.
BandStretch texel_stretch(StretchTexels& texels, const PanoramaLook& look);

// The rows of `f` shaded; `stretch`: the whole picture's (nullptr: `f` is the whole picture, its
// stretch taken from its own texels).
Panorama shade_panorama(const Store& store, const Grid& grid, const TerrainScene& scene,
                        const Fragments& fragments, const PinholeCamera& camera,
                        const PanoramaLook& look, const BandStretch* stretch = nullptr);
// The same into `out`, whose arrays are resized to the rows of `fragments` and every pixel of them
// written, and `texels` (scratch, 3 floats a pixel, written and read on terrain pixels only): the
// strips of a picture shaded one after the other into the same arrays reuse their memory.
void shade_panorama(const Store& store, const Grid& grid, const TerrainScene& scene,
                    const Fragments& fragments, const PinholeCamera& camera,
                    const PanoramaLook& look, const BandStretch* stretch, Panorama& out,
                    FreshArray<float>& texels);

}  // namespace maquette
