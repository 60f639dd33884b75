// The base footprint of a model layer's model, where structures.place's fit (place_stroke.h)
// takes it.
#pragma once

#include <string>

#include "content/content.h"
#include "place_stroke.h"

namespace maquette::structures {

// Vertices at most this far above a model's lowest vertex make its base: a model's floor is flat
// within the store's 1 mm quantization, and a plinth or steps within 5 cm still count as its foot.
inline constexpr double kModelBaseHeightM = 0.05;

// The base of `model` (a model layer's mesh, store/README.md "Model layers": metres, x east,
// y north, z up; the ingest turns glTF's y up to z up), in the model's x, y, counter-clockwise:
// the outline of its floor (its downward-facing triangles within kModelBaseHeightM of its
// lowest vertex; an L-shaped building's L, holes left out) when that floor is one polygon
// bounded by a simple cycle; otherwise (no floor faces, several pieces such as legs, a boundary
// touching itself) the convex hull of its vertices within kModelBaseHeightM of its lowest. The
// stroke drawn around the object is matched against it: a hull would make a concave model
// placed too small (by sqrt(area / hull area)). Throws maquette::Error prefixed with `where` when
// the model has no vertex or a non-finite one, or when its base has no area (fewer than 3 points
// not on a line: a model standing on a point or an edge).
Ring model_base(const MeshContent& model, const std::string& where);

}  // namespace maquette::structures
