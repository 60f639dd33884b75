// The built-in prototypes of instances layers (content.h: InstancesContent::prototypes), made
// procedurally: "builtin:conifer" (a fir: a brown trunk under stacked tiers of dark green cones
// with jagged, drooping rims), "builtin:broadleaf" (a deciduous tree: a trunk under a lumpy crown
// of overlapping perturbed icospheres) and "builtin:shrub" (a bush: a low, wide lumpy dome over a
// stub of a trunk).
//
// Contract of each: 1 m tall, its base at the origin (z from 0 to exactly 1), centred on the z
// axis, x east, y north, z up, so an instance's scale is its height in metres; two materials
// (0: bark, 1: foliage, PBR colours in linear RGB) and two objects (trunk, crown) using them in
// that order; per-vertex unit normals; each object closed once vertices at the same position are
// merged (normals split at creases), triangles counter-clockwise seen from outside; fewer than
// 2,000 vertices in all. Crown diameters: conifer about 0.5 m, broadleaf about 0.7 m, shrub about
// 1.9 m. Made once, the same bytes on every call and every run (fixed seeds, no state).
#pragma once

#include <string_view>
#include <vector>

#include "content/content.h"

namespace maquette {

// The prototype named `name`; throws maquette::Error naming it and listing the known names.
// The origin of the returned content is meaningless: prototypes are in their own model frame.
const MeshContent& builtin_prototype(std::string_view name);

// The same, made anew on each call (builtin_prototype makes each once and keeps it).
MeshContent make_builtin_prototype(std::string_view name);

// "builtin:conifer", "builtin:broadleaf", "builtin:shrub".
const std::vector<std::string>& builtin_prototype_names();

// The names of built-in prototypes begin so; no model layer may (maquette ingest --as model).
inline constexpr std::string_view kBuiltinPrototypePrefix = "builtin:";

}  // namespace maquette
