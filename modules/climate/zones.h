// Zones of a regression: the polygons of a features layer (WKB decoded by core/wkb_polygons.h:
// Polygon and MultiPolygon, 2D/Z/M/ZM), or one zone covering everything. A point belongs to the
// first zone (by fid) whose polygon holds it (even-odd rule, so holes are excluded); zones must not
// cross the antimeridian.
#pragma once

#include <array>
#include <cstddef>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/geojson.h"
#include "core/wkb_polygons.h"

namespace maquette::climate {

struct Zone {
  std::optional<int64_t> fid;          // none: the single zone covering everything
  std::string name;                    // from the zone_field attribute, else the fid
  std::vector<PolygonRings> polygons;  // empty for the single zone
  std::array<double, 4> bbox{};        // west, south, east, north
};

bool zone_contains(const Zone& zone, LonLat p);
// Index of the first zone holding p, or -1.
int zone_of(const std::vector<Zone>& zones, LonLat p);

nlohmann::json zone_to_json(const Zone& zone);
Zone zone_from_json(const nlohmann::json& j);

}  // namespace maquette::climate
