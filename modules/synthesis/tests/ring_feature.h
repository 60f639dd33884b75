// A GeoJSON FeatureCollection of one feature: a closed ring as a Polygon, or (to be refused) as a
// LineString, for the region operators' tests.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace maquette::test {

inline std::string ring_feature(const nlohmann::json& ring, const std::string& type) {
  using nlohmann::json;
  const json geometry = type == "Polygon" ? json{{"type", "Polygon"}, {"coordinates", {ring}}}
                                          : json{{"type", "LineString"}, {"coordinates", ring}};
  return json{
      {"type", "FeatureCollection"},
      {"features", {{{"type", "Feature"}, {"properties", json::object()}, {"geometry", geometry}}}}}
      .dump();
}

}  // namespace maquette::test
