// The panorama's sky: graded from the haze colour at the horizon to blue 30 degrees up, by the
// elevation of each pixel's ray (render/panorama.h).
#pragma once

#include <array>
#include <cstdint>

#include "render/camera.h"

namespace maquette {

// The haze at the horizon (also the colour the terrain fades into with distance) and the sky 30
// degrees up and above.
inline constexpr std::array<double, 3> kHazeColour{205, 216, 228}, kZenithColour{92, 140, 200};

// The sky's colour at picture coordinates (x, y) (a pixel's centre at col + 0.5, row + 0.5).
std::array<uint8_t, 3> sky_colour(const PinholeCamera& camera, double x, double y);

// Row `row` of the picture's sky into rgb[0 .. 3 width): sky_colour at each pixel's centre, but
// computed at the ends of runs. The colour is a function of the ray's elevation, which along a row
// (the camera has no roll) falls or rises monotonically on each side of the picture's centre
// column, so two columns of one side with the same colour have it everywhere between them: runs
// are halved until their ends agree (a few dozen colours a row instead of one a pixel).
void sky_row(const PinholeCamera& camera, int row, uint8_t* rgb);

}  // namespace maquette
