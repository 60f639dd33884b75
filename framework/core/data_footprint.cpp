#include "core/data_footprint.h"

#include <algorithm>
#include <iterator>

#include "core/error.h"

namespace maquette {
namespace {

nlohmann::json multipolygon(const std::vector<PolygonRings>& polygons) {
  nlohmann::json coords = nlohmann::json::array();
  for (const PolygonRings& polygon : polygons) {
    nlohmann::json rings = nlohmann::json::array();
    for (const auto& ring : polygon) {
      nlohmann::json points = nlohmann::json::array();
      for (const LonLat& p : ring) points.push_back({p.lon, p.lat});
      rings.push_back(std::move(points));
    }
    coords.push_back(std::move(rings));
  }
  return {{"type", "MultiPolygon"}, {"coordinates", std::move(coords)}};
}

// Outlines may run beyond +-180 (a source across the antimeridian keeps its longitudes
// continuous): the point is tried at its three longitudes.
bool contains_any_turn(const PolygonSet& set, LonLat p) {
  return set.contains(p) || set.contains({p.lon + 360, p.lat}) ||
         set.contains({p.lon - 360, p.lat});
}

}  // namespace

DataFootprint::DataFootprint(std::vector<PolygonRings> sources, std::vector<PolygonRings> region)
    : sources_(std::move(sources)),
      region_(std::move(region)),
      source_set_(sources_),
      region_set_(region_) {}

std::optional<DataFootprint> DataFootprint::from_provenance(const nlohmann::json& provenance,
                                                            const std::string& layer) {
  const auto it = provenance.find("footprint");
  if (it == provenance.end()) return std::nullopt;
  const std::string where = "layer '" + layer + "' provenance.footprint";
  if (!it->is_object() || !it->contains("sources"))
    throw Error(where + ": expected {\"sources\": MultiPolygon}");
  std::vector<PolygonRings> region;
  if (it->contains("region")) region = geojson_polygons(it->at("region"), where + ".region");
  return DataFootprint(geojson_polygons(it->at("sources"), where + ".sources"), std::move(region));
}

nlohmann::json DataFootprint::to_json() const {
  nlohmann::json j = {{"sources", multipolygon(sources_)}};
  if (!region_.empty()) j["region"] = multipolygon(region_);
  return j;
}

bool DataFootprint::contains(LonLat p) const {
  return contains_any_turn(source_set_, p) &&
         (region_set_.empty() || contains_any_turn(region_set_, p));
}

std::vector<CellId> DataFootprint::cover(const Grid& grid, int level) const {
  std::vector<CellId> cells = cover_geojson(grid, sources_, level, Containment::Overlap);
  if (region_.empty()) return cells;
  const std::vector<CellId> region = cover_geojson(grid, region_, level, Containment::Overlap);
  std::vector<CellId> both;
  std::set_intersection(cells.begin(), cells.end(), region.begin(), region.end(),
                        std::back_inserter(both));
  return both;
}

}  // namespace maquette
