#include "zones.h"

#include <algorithm>

#include "core/polygon_set.h"

namespace maquette::climate {

bool zone_contains(const Zone& zone, LonLat p) {
  if (!zone.fid) return true;
  if (p.lon < zone.bbox[0] || p.lat < zone.bbox[1] || p.lon > zone.bbox[2] || p.lat > zone.bbox[3])
    return false;
  return std::any_of(zone.polygons.begin(), zone.polygons.end(),
                     [&](const PolygonRings& polygon) { return polygon_contains(polygon, p); });
}

int zone_of(const std::vector<Zone>& zones, LonLat p) {
  for (size_t i = 0; i < zones.size(); ++i)
    if (zone_contains(zones[i], p)) return int(i);
  return -1;
}

nlohmann::json zone_to_json(const Zone& zone) {
  nlohmann::json polygons = nlohmann::json::array();
  for (const PolygonRings& poly : zone.polygons) {
    nlohmann::json rings = nlohmann::json::array();
    for (const auto& ring : poly) {
      nlohmann::json points = nlohmann::json::array();
      for (const LonLat& p : ring) points.push_back({p.lon, p.lat});
      rings.push_back(std::move(points));
    }
    polygons.push_back(std::move(rings));
  }
  return {{"fid", zone.fid ? nlohmann::json(*zone.fid) : nlohmann::json(nullptr)},
          {"name", zone.name},
          {"bbox", zone.bbox},
          {"polygons", std::move(polygons)}};
}

Zone zone_from_json(const nlohmann::json& j) {
  Zone z;
  if (!j.at("fid").is_null()) z.fid = j.at("fid").get<int64_t>();
  z.name = j.at("name").get<std::string>();
  z.bbox = j.at("bbox").get<std::array<double, 4>>();
  for (const auto& rings : j.at("polygons")) {
    PolygonRings poly;
    for (const auto& ring : rings) {
      std::vector<LonLat> points;
      for (const auto& p : ring) points.push_back({p[0].get<double>(), p[1].get<double>()});
      poly.push_back(std::move(points));
    }
    z.polygons.push_back(std::move(poly));
  }
  return z;
}

}  // namespace maquette::climate
