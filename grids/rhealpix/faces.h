// How the six rHEALPix faces meet: like the faces of a cube, with 0/90/180/270 degree turns.
#pragma once

#include <optional>

#include "core/grid.h"

namespace maquette {

// Maps a coordinate at `level` possibly outside its face onto the face holding it (see
// Grid::wrap for the corner rule); nullopt beyond one face width.
std::optional<FaceCoord> wrap_face_coord(FaceCoord c, int level);

}  // namespace maquette
