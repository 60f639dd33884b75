// The painted panorama's skyline anti-aliased from the render's coverage guide (`render panorama
// --antialias K`: the share of each pixel's K x K samples that see terrain), as the render's own
// colours are: maquette-paint paints each pixel from its centre's guides, so without it the
// painted terrain meets the painted sky in a staircase.
#pragma once

#include "paint_panorama.h"
#include "panorama_guides.h"

namespace maquette::synthesis {

// The painted skyline anti-aliased: each pixel whose coverage c (PanoramaPicture::coverage) lies
// strictly between 0 and 1 takes c T + (1 - c) S in linear light (sRGB's transfer function), T
// its terrain's colour (its own when its centre sees terrain, else the first neighbour's whose
// centre does) and S its sky's (its own when its centre sees the sky and `sky_painted`, else the
// first neighbour's whose centre sees the sky and whose coverage is 0: the sky's pure colour, not
// a render's mix; with an even K a pixel's centre is no sample), neighbours taken
// in the order above, left, right, below, then the diagonals, from the colours before any
// blending; a pixel without such neighbours keeps its colour. Nothing without coverage. The
// sources (`painted.source`) are unchanged.
void blend_skyline(const PanoramaPicture& picture, bool sky_painted, PaintedPanorama& painted);

}  // namespace maquette::synthesis
