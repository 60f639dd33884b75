// What deform.water's operators share about a stroke: whether it is a water stroke, its name in
// messages, and its polygon for point-in-polygon tests.
#pragma once

#include <string>

#include "core/polygon_set.h"
#include "runtime/vector_feature.h"

namespace maquette::deform {

bool is_water_stroke(const VectorFeature& f);  // its attribute tool is "water"

std::string describe(const VectorFeature& f);  // "feature 7 (tool water)"

// The stroke's polygon (holes included); throws naming the feature when it is not a Polygon.
PolygonSet stroke_polygon(const VectorFeature& f);

}  // namespace maquette::deform
