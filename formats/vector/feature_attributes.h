// An OGR feature's fields as typed JSON.
#pragma once

#include <ogr_feature.h>

#include <nlohmann/json.hpp>

namespace maquette {

// Every field of `feature` by name: integers, reals (non-finite ones as null), booleans
// (OFSTBoolean), strings, JSON (OFSTJSON, parsed when valid), dates and times as ISO 8601 text,
// lists as arrays, binary as hex text; unset and null fields as null.
nlohmann::json feature_attributes(const OGRFeature& feature);

}  // namespace maquette
