// A panorama and its guides from what each pixel sees (render/rasterizer.h) of a terrain scene
// (render/terrain_scene.h): the surface's colour (an imagery layer sampled bilinearly where the
// pixel sees it: at the point of the grid's plane interpolated in its triangle, or at its lon/lat
// where a corner is off its tile's face; at the level the distance needs, trilinearly between the
// overviews whose texels are about the pixel's width on the ground where a pixel spans more than
// a texel; stretched for display; where it has no texel, the nearest
// texel's within a reach (render/edge_texels.h), the stretch taken over the imagery's own texels
// only; beyond, the middle of the display range, grey 128; without imagery, an earth colour),
// shaded by the DEM's normals under a sun, faded into the haze with distance (aerial perspective: a
// fraction 1 - exp(-distance / haze_distance) of the haze colour), over a sky graded from the haze
// colour at the horizon to blue at 30 degrees up (render/sky.h). Guides per pixel: the DEM's
// altitude, the distance from the eye, lon/lat, the land-cover class when a categorical layer is
// given (the nearest sample's, or with its boundaries smoothed), the shading factor, and
// silhouettes: terrain pixels on the near side of a depth discontinuity (a 4-neighbour is sky or
// more than `silhouette_jump` times farther). Rows are shaded in parallel, each pixel from its own
// fragment: the same bits for any threads. A strip of rows of the picture
// (render/panorama_strips.h) is shaded as the same rows of the whole picture, given the whole
// picture's display stretch (its texels are those of the pixels on a grid of stretch_step, gathered
// strip by strip).
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "core/grid.h"
#include "core/tile.h"
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
  // The land-cover guide read with its classes' boundaries smoothed (image/layer_sampler.h
  // Read::kSmoothLabels: curves through the cells' staircase, as a painter draws them), or as
  // the nearest cell's class.
  bool smooth_land_cover = false;
  // The texture with the quicklooks' display stretch (image/stretch.h: 2-98 % of each band over
  // the texels the picture shows), or as stored.
  bool stretch = true;
  double sun_azimuth = 315, sun_altitude = 45;  // degrees (clockwise from north, above horizon)
  double haze_distance = 60000;                 // metres
  double silhouette_jump = 1.05;
  // Per vertex of the scene, 1 in the terrain's cast shadow (render/terrain_shadow.h), or none:
  // a shadowed surface gets the hillshade's ambient share only, as a slope facing away does.
  const std::vector<uint8_t>* shadow = nullptr;
  // Samples per pixel side: above 1, each pixel's colour the mean of K x K samples over it
  // (render/panorama_supersample.h), its guides its centre's.
  int antialias = 1;
};

// Its arrays are FreshArrays (render/fresh_array.h): shade_panorama writes every pixel of each it
// sizes (NaN guides on the sky).
struct Panorama {
  int width = 0, height = 0;
  int first_row = 0;        // of the picture: the panorama may be a strip of it
  FreshArray<uint8_t> rgb;  // 3 per pixel, row-major
  // Per pixel, NaN on the sky, float32 (fewer fresh pages: a picture's guides are most of the
  // memory it first touches): metres from the eye; lon/lat as degrees from `origin` (the eye's;
  // the longitude's the short way round), lonlat() the pixel's own; both to about 1e-7 of the
  // distance from the eye, a centimetre at 100 km. Metres of the DEM's datum and class (a tenth
  // of a millimetre at 2 km, the DEM's own float32).
  LonLat origin{0, 0};
  FreshArray<float> distance, lon_offset, lat_offset;
  FreshArray<float> altitude, land_cover;
  FreshArray<float> cast_shadow;  // with PanoramaLook::shadow: 0 (sunlit) to 1 (in shadow)
  // The factor the surface's colour was shaded by: hillshade times sunlit share, 0.3 to 1 (the
  // transfer in the picture blends its colours with it).
  FreshArray<float> shading;
  FreshArray<uint8_t> silhouette;  // 255 on a silhouette, 0 elsewhere
  // With PanoramaLook::antialias K > 1 (render/panorama_supersample.h), the share of the pixel's
  // K x K samples that see terrain, 0 to 1 (not NaN on the sky: a sky pixel beside the skyline
  // has some); none otherwise.
  FreshArray<float> coverage;

  // Pixel i's lon/lat in degrees (lon in [-180, 180]; NaN on the sky).
  LonLat lonlat(size_t i) const {
    const double lon = origin.lon + double(lon_offset[i]);
    return {std::abs(lon) > 180 ? std::remainder(lon, 360.0) : lon,
            origin.lat + double(lat_offset[i])};
  }
};

using BandStretch = std::array<StretchRange, 3>;  // per band of the texture
// Texels, 3 floats each (NaN for none; each appended texel written once: the vector's growth does
// not fill it).
using StretchTexels = std::vector<float, DefaultInitAllocator<float>>;

// Per row of a picture, where shade_guides wrote its texels: the runs of terrain pixels [first,
// end), left to right, and among them the columns whose texel is the imagery's nearest past its
// edge (render/edge_texels.h), ascending. The display stretch reads the texels in place from them
// (the imagery's own only), not from a copy.
struct TexelRows {
  std::vector<std::vector<std::array<uint32_t, 2>>> terrain;
  std::vector<std::vector<uint32_t>> past_edge;
  explicit TexelRows(int rows) : terrain(size_t(rows)), past_edge(size_t(rows)) {}
};

// The display stretch is taken over the texels of the pixels whose row and column are multiples
// of this step: 1 up to 4 MP, about 4 M pixels above.
int stretch_step(int width, int height);

// The layers' samplers of each thread (image/layer_sampler.h, render/edge_texels.h), kept across
// the strips of a picture: each thread reads a tile and assembles its halo once a picture, not
// once a strip. The layers of `look` must outlive it.
class PanoramaSamplers {
 public:
  PanoramaSamplers(const Store& store, const Grid& grid, const PanoramaLook& look);
  ~PanoramaSamplers();

  // Every thread's samplers drop the tiles (and edge blocks) not used since the last call: called
  // between strips, outside parallel work, it keeps a picture's memory bounded by about two
  // strips' tiles. The samplers' values do not depend on what they keep.
  void forget_unused();

 private:
  struct Threads;
  std::unique_ptr<Threads> threads_;
  friend void gather_stretch_texels(const Grid&, const TerrainScene&, const Fragments&,
                                    const PinholeCamera&, const PanoramaLook&, PanoramaSamplers&,
                                    int, StretchTexels&, FreshArray<float>&);
  friend void shade_guides(const Grid&, const TerrainScene&, const Fragments&, const PinholeCamera&,
                           const PanoramaLook&, PanoramaSamplers&, Panorama&, FreshArray<float>&,
                           TexelRows*);
};

// Appends to `texels` those of the terrain pixels of `f` on the grid of `step` (picture rows, so
// the strips of a picture gather the whole picture's); nothing without a texture to stretch.
// `scratch`: resized to 3 floats a pixel of `f`, written and read on those pixels only (its memory
// reused by the strips of a picture).
void gather_stretch_texels(const Grid& grid, const TerrainScene& scene, const Fragments& f,
                           const PinholeCamera& camera, const PanoramaLook& look,
                           PanoramaSamplers& samplers, int step, StretchTexels& texels,
                           FreshArray<float>& scratch);

// The stretch of `texels`: the 2 and 98 % quantiles per band, or the values as stored without a
// texture or with look.stretch false.
BandStretch texel_stretch(const StretchTexels& texels, const PanoramaLook& look);

// Sizes `p`'s arrays for the rows [first_row, first_row + rows) of a picture `width` pixels wide
// (shade_guides and colour_panorama write every pixel of them).
void size_panorama(Panorama& p, int width, int first_row, int rows, const PanoramaLook& look);

// The guides of the rows of `fragments` (shading among them; NaN on the sky) written into the same
// rows of `p`, which holds them, and into `texels` (resized to 3 floats a pixel of `p`, written on
// terrain pixels only) the imagery's texel where each pixel sees the surface (NaN for none); then
// the pixels without a texel given the imagery's nearest within the reach (render/edge_texels.h:
// not stretched over). With `rows` (sized for the picture's rows), those rows' terrain runs and
// columns past the edge appended to it.
void shade_guides(const Grid& grid, const TerrainScene& scene, const Fragments& fragments,
                  const PinholeCamera& camera, const PanoramaLook& look, PanoramaSamplers& samplers,
                  Panorama& p, FreshArray<float>& texels, TexelRows* rows);

// The colour and silhouettes of every pixel of `p` from its guides (the sky: NaN distance) and
// `texels` (shade_guides'), the texels stretched by `stretch`. A pixel next to a row `p` does not
// hold is not on a silhouette for it (a strip has a row of margin each side).
void colour_panorama(const PinholeCamera& camera, const PanoramaLook& look,
                     const BandStretch& stretch, const FreshArray<float>& texels, Panorama& p);

// The fragments of the picture's rows [first, first + rows), the attributes of the vertices they
// show made (render/terrain_scene.h attribute_vertices); valid until the next call.
using DrawRows = std::function<const Fragments&(int first, int rows)>;

// The whole picture of `camera`, its fragments drawn by `draw` in strips of `strip_rows` rows (one
// strip's fragments at a time), its guides and texels written strip by strip into the whole
// picture's, then its display stretch taken over the whole picture's texels where they are
// (TexelRows) and its colour and silhouettes made: the same bits for any strips. That stretch
// into `stretch` when given. look.antialias is not applied here (render/panorama_strips.h).
Panorama shade_panorama(const Store& store, const Grid& grid, const TerrainScene& scene,
                        const PinholeCamera& camera, const PanoramaLook& look, int strip_rows,
                        const DrawRows& draw, BandStretch* stretch = nullptr);

}  // namespace maquette
