// What deform.water's operators share about a stroke: whether it is a water stroke, its name in
// messages, its polygon for point-in-polygon tests, and the rule that water strokes do not
// overlap.
#pragma once

#include <string>
#include <vector>

#include "core/grid.h"
#include "core/polygon_set.h"
#include "runtime/vector_feature.h"

namespace maquette::deform {

bool is_water_stroke(const VectorFeature& f);  // its attribute tool is "water"

std::string describe(const VectorFeature& f);  // "feature 7 (tool water)"

// The stroke's polygon (holes included); throws naming the feature when it is not a Polygon.
PolygonSet stroke_polygon(const VectorFeature& f);

// Gives pixel `i` (its centre at `centre`) to stroke `f` in `owner` (a stroke per pixel, null:
// none yet). Water strokes must not overlap: a pixel in two of them would have two levels and its
// water would count in both bodies. Throws maquette::Error naming both features and the place
// when the pixel is already another stroke's.
void claim_pixel(std::vector<const VectorFeature*>& owner, size_t i, const VectorFeature& f,
                 LonLat centre);

}  // namespace maquette::deform
