// The transfer in the picture (issue 19; paper 000's own pipeline, its Fig. 5): a rendered
// panorama's guides (panorama_guides.h) as the synthesis's target, the painting as its
// exemplar, the painted colours blended with the render's shading.
//
// The picture is one window of global pixels (its own columns and rows), synthesized in tiles
// of params.tile pixels a side, each from its guides within synthesis_halo() (beyond the
// picture's edge, the nearest edge pixel's): by synthesis.h's contract the same bits for any
// tile size and thread count. Guides per pixel: the land-cover class through the class table
// (terrain without a class matches any; the sky: sky_class, or not painted), the altitude and
// the distance guides (the sky is far: 1), the light guide (panorama_light; none on the sky),
// and the depth for coherence breaks (the sky: infinitely far), so that no coherent patch
// crosses a silhouette.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "paint_params.h"
#include "panorama_guides.h"
#include "synthesis.h"
#include "transfer_exemplar.h"

namespace maquette::synthesis {

struct PaintedPanorama {
  int width = 0, height = 0;
  std::vector<uint8_t> rgb;   // 3 per pixel: painted, or the render's sky
  std::vector<float> source;  // 2 per pixel: the painting pixel (column, row) copied, or NaN
};

// The files a maquette-paint run reads, named for messages (core/output_clash.h): the panorama
// `picture` and its guides (read_panorama's STEM-guides.tif), the params' file `params_path`, and
// the exemplar's files (exemplar_inputs: the painting, its class image, exclusion mask, altitude,
// distance and light images, guides; the further paintings' too). No output may be one of them.
std::vector<InputFile> paint_inputs(const std::string& picture, const std::string& params_path,
                                    const PaintParams& params);

// The picture's light guide: each terrain pixel's shading factor as its quantile
// (class_quantiles, light_guide.h) among the terrain pixels of its painting class (its land
// cover through the class table; those without a class one more class), NaN on the sky (and
// where the shading is NaN). A function of the whole picture: computed once, then windowed.
// Precondition: the picture has its shading band.
std::vector<float> panorama_light(const PanoramaPicture& picture, const PaintParams& params);

// The synthesis's guides of the picture over `window` grown by synthesis_halo(); `light` the
// picture's (panorama_light), or empty: no light guide.
TargetGuides panorama_target(const PanoramaPicture& picture, const PaintParams& params,
                             const std::vector<float>& light, const PixelRect& window);

// The picture painted. Each painted pixel is the painting's colour at its source times
// (1 - shading) + shading * s / s_median, s the render's shading factor and s_median its median
// over the terrain: ground lit as the picture's typical ground keeps the painting's colour,
// slopes turned from the sun darken, those facing it brighten (paper 000's blend with a terrain
// shading). With w_light > 0 the light guide is the target's too (panorama_light); with
// haze_distance, aerial perspective (painted_haze.h), after the shading blend. A picture
// rendered with --antialias (its coverage guide) gets its skyline anti-aliased in turn
// (skyline_blend.h).
// Precondition: the picture has a shading band when params.shading > 0 or w_light > 0
// (read_panorama with_shading); throws maquette::Error otherwise, and when sky_class has no pixel
// to copy in the exemplar (check_class_has_pixels, naming params.source's sky_class).
PaintedPanorama paint_panorama(const PanoramaPicture& picture, const TransferExemplar& exemplar,
                               const PaintParams& params);

}  // namespace maquette::synthesis
