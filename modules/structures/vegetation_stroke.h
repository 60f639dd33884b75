// Vegetation strokes: the features of tool "vegetation" of a features port, closed strokes
// (Polygon or MultiPolygon, holes allowed) around the areas covered by plants, with the attribute
// `spacing_m` (the plants' average spacing: one plant per spacing_m x spacing_m), or without it
// for structures.vegetation_spacing to estimate it from the orthophoto.
//
// Each stroke is placed in its own plane: the tangent plane (core/enu_frame.h,
// x east, y north, metres) at the first vertex of its outer ring, a point of the stroke and of no
// cell, so that the plants it decides are the same whatever cell asks. A point (x, y) of the plane
// goes to the ground vertically (the geodetic position of (x, y, 0)); over a stroke of 10 km the
// plane's distances differ from the ground's by under 1e-6 relative.
#pragma once

#include <string>
#include <vector>

#include "core/enu_frame.h"
#include "core/polygon_set.h"
#include "footprint.h"
#include "runtime/operator.h"
#include "runtime/vector_feature.h"

namespace maquette::structures {

struct VegetationStroke {
  const VectorFeature* feature = nullptr;
  double spacing_m = 0;  // 0: none given
  EnuFrame plane;
  std::vector<std::vector<PlaneRing>> polygons;  // in the plane: outer ring, then holes (closed)
  PolygonSet region;                             // the same, for point tests (LonLat = x, y)

  PlanePoint to_plane(LonLat p) const;
  LonLat to_ground(PlanePoint p) const;
};

// The features port "strokes" of the operators reading vegetation strokes.
InputSpec strokes_input();

// The strokes of tool "vegetation" among `features`, in the order given. Throws maquette::Error
// naming `port`, the feature id and the field at fault: a geometry other than a (Multi)Polygon,
// spacing_m not a positive number, an empty polygon.
std::vector<VegetationStroke> vegetation_strokes(const FeatureList& features,
                                                 const std::string& port);

}  // namespace maquette::structures
