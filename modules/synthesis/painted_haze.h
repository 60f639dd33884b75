// Aerial perspective on the painted panorama (maquette-paint's `haze_distance`): the far terrain
// fades into a haze colour as the render's own picture does (render/panorama.h), so the painted
// distance reads as distance. Painted pictures lack it otherwise: the painting's far strokes come
// only where a class allows (the distance guide), and a dark forest on the skyline stays as dark
// as one in front.
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "paint_panorama.h"
#include "panorama_guides.h"

namespace maquette::synthesis {

// Each terrain pixel of `painted` (the picture's distance d finite) becomes (1 - f) C + f H in
// linear light (sRGB's transfer function), f = 1 - exp(-d / haze_distance), C its colour and H
// `colour`, or without it the mean, in linear light, of the painted picture's sky pixels; the sky
// and the sources unchanged. Preconditions: haze_distance > 0; `colour` given or the picture
// shows sky (check_haze_colour, before the painting's work).
void add_haze(const PanoramaPicture& picture, double haze_distance,
              const std::optional<std::array<uint8_t, 3>>& colour, PaintedPanorama& painted);

// Throws maquette::Error naming `params`' file and haze_distance when a haze is asked for without
// a haze_color and the picture shows no sky to take its colour from.
void check_haze_colour(const PanoramaPicture& picture, const PaintParams& params);

}  // namespace maquette::synthesis
