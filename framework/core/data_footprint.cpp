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

DataFootprint::DataFootprint(std::vector<PolygonRings> sources, std::vector<PolygonRings> region) {
  PolygonSet source_set(sources), region_set(region);
  parts_.push_back(
      {std::move(sources), std::move(region), std::move(source_set), std::move(region_set)});
}

DataFootprint::Part DataFootprint::part(const nlohmann::json& j, const std::string& where) {
  if (!j.is_object() || !j.contains("sources"))
    throw Error(where + ": expected {\"sources\": MultiPolygon}");
  std::vector<PolygonRings> region;
  if (j.contains("region")) region = geojson_polygons(j.at("region"), where + ".region");
  std::vector<PolygonRings> sources = geojson_polygons(j.at("sources"), where + ".sources");
  PolygonSet source_set(sources), region_set(region);
  return {std::move(sources), std::move(region), std::move(source_set), std::move(region_set)};
}

std::optional<DataFootprint> DataFootprint::from_provenance(const nlohmann::json& provenance,
                                                            const std::string& layer) {
  const auto it = provenance.find("footprint");
  if (it == provenance.end()) return std::nullopt;
  const std::string where = "layer '" + layer + "' provenance.footprint";
  DataFootprint f;
  if (it->is_array()) {
    for (size_t i = 0; i < it->size(); ++i)
      f.parts_.push_back(part((*it)[i], where + "[" + std::to_string(i) + "]"));
    if (f.parts_.empty()) throw Error(where + ": no parts");
  } else {
    f.parts_.push_back(part(*it, where));
  }
  return f;
}

nlohmann::json DataFootprint::Part::to_json() const {
  nlohmann::json j = {{"sources", multipolygon(sources)}};
  if (!region.empty()) j["region"] = multipolygon(region);
  return j;
}

nlohmann::json DataFootprint::to_json() const {
  if (parts_.size() == 1) return parts_.front().to_json();
  nlohmann::json parts = nlohmann::json::array();
  for (const Part& p : parts_) parts.push_back(p.to_json());
  return parts;
}

DataFootprint DataFootprint::united(const DataFootprint& other) const {
  DataFootprint out = *this;
  for (const Part& p : other.parts_) {
    const nlohmann::json j = p.to_json();
    if (std::none_of(out.parts_.begin(), out.parts_.end(),
                     [&](const Part& q) { return q.to_json() == j; }))
      out.parts_.push_back(p);
  }
  return out;
}

bool DataFootprint::contains(LonLat p) const {
  return std::any_of(parts_.begin(), parts_.end(), [&](const Part& part) {
    return contains_any_turn(part.source_set, p) &&
           (part.region_set.empty() || contains_any_turn(part.region_set, p));
  });
}

std::vector<CellId> DataFootprint::cover(const Grid& grid, int level) const {
  std::vector<CellId> cells;
  for (const Part& part : parts_) {
    std::vector<CellId> c = cover_geojson(grid, part.sources, level, Containment::Overlap);
    if (!part.region.empty()) {
      const std::vector<CellId> region =
          cover_geojson(grid, part.region, level, Containment::Overlap);
      std::vector<CellId> both;
      std::set_intersection(c.begin(), c.end(), region.begin(), region.end(),
                            std::back_inserter(both));
      c = std::move(both);
    }
    std::vector<CellId> merged;
    std::set_union(cells.begin(), cells.end(), c.begin(), c.end(), std::back_inserter(merged));
    cells = std::move(merged);
  }
  return cells;
}

}  // namespace maquette
