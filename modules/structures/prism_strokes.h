// structures.prism's input: the clicks in a photo, as a JSON file (README.md "structures.prism"):
//   {"photo": "building.jpg",             path, relative to the JSON file's folder
//    "focal_px": 1000,                    optional: else EXIF, else estimated (prism_focal.h)
//    "profile": [[x, y], ...],            pixels, x right, y down from the top-left corner
//    "corner": 0,                         the profile's right-angled vertex
//    "extrusion": [x, y],                 the end of the corner's edge orthogonal to the profile
//    "more_extrusions": [{"vertex": 2, "end": [x, y]}],   optional
//    "height_m": 25}                      optional: the model's height (default 10)
#pragma once

#include <optional>
#include <string>

#include "prism_solver.h"

namespace maquette::structures {

struct PrismStrokes {
  std::string photo;  // resolved against the JSON file's folder
  std::optional<double> focal_px;
  PrismClicks clicks;
  double height_m = 10;
};

// Throws maquette::Error naming the file, the field and the value at fault (not JSON, a missing
// or mistyped field, a non-finite or non-positive number, an unknown field).
PrismStrokes read_prism_strokes(const std::string& path);

}  // namespace maquette::structures
