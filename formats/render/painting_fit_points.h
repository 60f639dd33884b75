// The control points of a painting (issue 19, "Fitting a DEM to a painting"): pairs of a point
// clicked in the painting and the ground point it shows. The JSON file:
//   {"width": 4000, "height": 2500,
//    "points": [{"name": "Lady Mountain", "x": 1203.5, "y": 880, "lon": -112.97, "lat": 37.26,
//                "height": 2100}, ...]}
// width and height: the painting's size in pixels (integers in [1, 65536]); x, y: pixels from its
// top-left corner, rows down, the centre of pixel (i, j) at (i + 0.5, j + 0.5) as in
// render/camera.h, inside the painting; lon, lat: degrees; height (optional): metres above the
// ellipsoid, else the DEM's height there (the caller fills it in); name (optional): for messages.
// Any other field is refused (a misspelt "heigth" would take the DEM's height silently).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/enu_frame.h"

namespace maquette {

struct ControlPoint {
  std::string name;  // "points[i]" when the file gives none
  double x = 0, y = 0;
  double lon = 0, lat = 0;
  std::optional<double> height;  // above the ellipsoid
};

struct PaintingPoints {
  int width = 0, height = 0;
  std::vector<ControlPoint> points;
};

// Throws maquette::Error naming the file, the field (e.g. "points[3].lat") and its value: the file
// unreadable or not JSON, a field missing or not a number, a size out of [1, 65536], a point
// outside the painting, a longitude outside [-180, 180] or latitude outside [-90, 90], a height
// that is not finite, fewer than 4 points.
PaintingPoints read_painting_points(const std::string& path);

// The same checks on text already read; `source` names it in the messages.
PaintingPoints parse_painting_points(const std::string& text, const std::string& source);

}  // namespace maquette
