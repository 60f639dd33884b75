// A feature of a features layer as operators see it: its id, its geometry parsed once per step
// (core/geometry.h: typed, Z kept) and its attributes.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <vector>

#include "core/geometry.h"

namespace maquette {

struct VectorFeature {
  int64_t id = 0;  // the feature's fid, unique within its layer
  Geometry geometry;
  nlohmann::json attributes = nlohmann::json::object();  // typed values by field name
};

using FeatureList = std::vector<const VectorFeature*>;  // sorted by id

}  // namespace maquette
