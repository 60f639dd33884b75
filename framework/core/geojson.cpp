#include "core/geojson.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "core/error.h"

namespace maquette {
namespace {

using json = nlohmann::json;

std::vector<LonLat> parse_ring(const json& ring, const std::string& where) {
  if (!ring.is_array() || ring.size() < 4)
    throw Error(where + ": a polygon ring needs at least 4 positions, got " + ring.dump());
  std::vector<LonLat> out;
  for (const json& pos : ring) {
    if (!pos.is_array() || pos.size() < 2 || !pos[0].is_number() || !pos[1].is_number())
      throw Error(where + ": bad position " + pos.dump() + " (expected [lon, lat])");
    const LonLat p{pos[0].get<double>(), pos[1].get<double>()};
    if (!(std::abs(p.lat) <= 90.0))
      throw Error(where + ": latitude " + pos[1].dump() + " is outside -90..90");
    out.push_back(p);
  }
  return out;
}

PolygonRings parse_polygon(const json& coords, const std::string& where) {
  if (!coords.is_array() || coords.empty())
    throw Error(where + ": a Polygon needs an array of rings, got " + coords.dump());
  PolygonRings rings;
  for (const json& ring : coords) rings.push_back(parse_ring(ring, where));
  return rings;
}

void collect(const json& g, const std::string& where, std::vector<PolygonRings>& out) {
  if (!g.is_object() || !g.contains("type") || !g["type"].is_string())
    throw Error(where + ": not a GeoJSON object (no \"type\")");
  const std::string type = g["type"];
  if (type == "FeatureCollection") {
    for (const json& f : g.value("features", json::array())) collect(f, where, out);
  } else if (type == "Feature") {
    collect(g.at("geometry"), where, out);
  } else if (type == "GeometryCollection") {
    for (const json& geom : g.value("geometries", json::array())) collect(geom, where, out);
  } else if (type == "Polygon") {
    out.push_back(parse_polygon(g.at("coordinates"), where));
  } else if (type == "MultiPolygon") {
    for (const json& p : g.at("coordinates")) out.push_back(parse_polygon(p, where));
  } else {
    throw Error(where + ": geometry type '" + type + "' is not a Polygon or MultiPolygon");
  }
}

}  // namespace

std::vector<PolygonRings> geojson_polygons(const json& geojson, const std::string& where) {
  std::vector<PolygonRings> out;
  collect(geojson, where, out);
  if (out.empty()) throw Error(where + ": no polygons");
  return out;
}

std::vector<PolygonRings> read_geojson_polygons(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Error("cannot read GeoJSON file " + path);
  try {
    return geojson_polygons(json::parse(in), path);
  } catch (const json::exception& e) {
    throw Error(path + ": invalid GeoJSON: " + e.what());
  }
}

std::vector<CellId> cover_geojson(const Grid& grid, const std::vector<PolygonRings>& polygons,
                                  int level, Containment mode) {
  std::vector<CellId> cells;
  for (const PolygonRings& p : polygons) {
    const auto c = grid.cover_polygon(p, level, mode);
    cells.insert(cells.end(), c.begin(), c.end());
  }
  std::sort(cells.begin(), cells.end());
  cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  return cells;
}

json cell_boundary_geojson(const Grid& grid, CellId cell, int points_per_edge) {
  json ring = json::array();
  for (const LonLat& p : grid.boundary(cell, points_per_edge)) ring.push_back({p.lon, p.lat});
  return {{"type", "Polygon"}, {"coordinates", json::array({ring})}};
}

void check_bbox(const std::vector<double>& b, const std::string& option) {
  auto fmt = [](double v) {
    std::ostringstream s;
    s << v;
    return s.str();
  };
  if (b.size() != 4) throw Error(option + " needs 4 numbers: W S E N");
  for (int k : {1, 3})
    if (!(std::abs(b[size_t(k)]) <= 90.0))
      throw Error(option + ": latitude " + fmt(b[size_t(k)]) + " is outside -90..90");
  if (b[1] > b[3]) throw Error(option + ": south " + fmt(b[1]) + " is north of north " + fmt(b[3]));
}

}  // namespace maquette
