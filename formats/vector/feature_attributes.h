// An OGR feature's fields as typed JSON.
#pragma once

#include <ogr_feature.h>

#include <memory>
#include <nlohmann/json.hpp>

namespace maquette {

// Every field of `feature` by name: integers, reals (non-finite ones as null), booleans
// (OFSTBoolean), strings, JSON (OFSTJSON, parsed when valid), dates and times as ISO 8601 text,
// lists as arrays, binary as hex text; unset and null fields as null.
nlohmann::json feature_attributes(const OGRFeature& feature);

// The fields of a layer definition, in order: [{"name", "type": "Integer64", "subtype":
// "Boolean"}] (OGR's type names), kept at ingest so that an export restores them.
nlohmann::json field_definitions(const OGRFeatureDefn& defn);
// One of those back as an OGR field; throws maquette::Error for an unknown type name.
std::unique_ptr<OGRFieldDefn> field_definition(const nlohmann::json& definition);
// The field of a value without a recorded definition: its JSON type (numbers, booleans, text;
// arrays and objects as JSON text).
std::unique_ptr<OGRFieldDefn> inferred_field(const std::string& name, const nlohmann::json& value);

// Sets the fields of `feature` (from its definition) from `attributes`, the inverse of
// feature_attributes; absent and null values are left null.
void set_feature_attributes(OGRFeature& feature, const nlohmann::json& attributes);

}  // namespace maquette
