#include "core/geojson.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/error.h"
#include "core/json_file.h"
#include "core/region.h"

namespace maquette {
namespace {

using json = nlohmann::json;

std::vector<LonLat> parse_ring(const json& ring, const std::string& where) {
  if (!ring.is_array() || ring.size() < 4)
    throw Error(where + ": a polygon ring needs at least 4 positions, got " + excerpt(ring));
  std::vector<LonLat> out;
  for (const json& pos : ring) {
    if (!pos.is_array() || pos.size() < 2 || !pos[0].is_number() || !pos[1].is_number())
      throw Error(where + ": bad position " + excerpt(pos) + " (expected [lon, lat])");
    const LonLat p{pos[0].get<double>(), pos[1].get<double>()};
    if (!(std::abs(p.lat) <= 90.0))
      throw Error(where + ": latitude " + excerpt(pos[1]) + " is outside -90..90");
    out.push_back(p);
  }
  return out;
}

PolygonRings parse_polygon(const json& coords, const std::string& where) {
  if (!coords.is_array() || coords.empty())
    throw Error(where + ": a Polygon needs an array of rings, got " + excerpt(coords));
  PolygonRings rings;
  for (const json& ring : coords) rings.push_back(parse_ring(ring, where));
  // An outer ring whose points lie on a line (or on one point) covers nothing.
  double twice_area = 0;
  const std::vector<LonLat>& outer = rings.front();
  for (size_t i = 0; i + 1 < outer.size(); ++i)
    twice_area += outer[i].lon * outer[i + 1].lat - outer[i + 1].lon * outer[i].lat;
  if (twice_area == 0)
    throw Error(where + ": a polygon has no area (its outer ring " + excerpt(coords.front()) +
                " is degenerate)");
  return rings;
}

// The member `key` of a GeoJSON object of type `type`; throws naming both when it is absent.
const json& member(const json& g, const char* key, const std::string& type,
                   const std::string& where) {
  const auto it = g.find(key);
  if (it == g.end()) throw Error(where + ": a " + type + " has no \"" + key + "\"");
  return *it;
}

void collect(const json& g, const std::string& where, std::vector<PolygonRings>& out) {
  if (!g.is_object() || !g.contains("type") || !g["type"].is_string())
    throw Error(where + ": not a GeoJSON object (no \"type\")");
  const std::string type = g["type"];
  if (type == "FeatureCollection") {
    for (const json& f : g.value("features", json::array())) collect(f, where, out);
  } else if (type == "Feature") {
    collect(member(g, "geometry", type, where), where, out);
  } else if (type == "GeometryCollection") {
    for (const json& geom : g.value("geometries", json::array())) collect(geom, where, out);
  } else if (type == "Polygon") {
    out.push_back(parse_polygon(member(g, "coordinates", type, where), where));
  } else if (type == "MultiPolygon") {
    for (const json& p : member(g, "coordinates", type, where))
      out.push_back(parse_polygon(p, where));
  } else {
    throw Error(where + ": geometry type '" + excerpt(type) + "' is not a Polygon or MultiPolygon");
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
  const json doc = read_json_file(path);
  try {
    return geojson_polygons(doc, path);
  } catch (const json::exception& e) {
    throw Error(path + ": invalid GeoJSON: " + e.what());
  }
}

namespace {

// Cells at `level` in a lon/lat box (W > E crosses the antimeridian), from its share of the
// sphere's area: an estimate, exact for the whole globe.
double cells_in_box(double west, double south, double east, double north, int level) {
  constexpr double kDeg = 3.14159265358979323846 / 180;
  const double width = std::min(360.0, east >= west ? east - west : east - west + 360);
  const double share = width / 360 * (std::sin(north * kDeg) - std::sin(south * kDeg)) / 2;
  return share * CellId::kNumFaces * std::ldexp(1.0, 2 * level);
}

}  // namespace

double cover_size_estimate(const std::vector<double>& bbox, int level) {
  return cells_in_box(bbox[0], bbox[1], bbox[2], bbox[3], level);
}

double cover_size_estimate(const std::vector<PolygonRings>& polygons, int level) {
  double west = 180, south = 90, east = -180, north = -90;
  for (const PolygonRings& p : polygons)
    for (const LonLat& q : p.front()) {
      west = std::min(west, q.lon);
      east = std::max(east, q.lon);
      south = std::min(south, q.lat);
      north = std::max(north, q.lat);
    }
  return polygons.empty() ? 0 : cells_in_box(west, south, std::min(east, west + 360), north, level);
}

void check_cover_size(double cells, double limit, int level, const std::string& what,
                      const std::string& advice) {
  if (cells <= limit) return;
  char text[64];
  std::snprintf(text, sizeof text, "%.3g", cells);
  throw Error(what + " holds about " + text + " cells at level " + std::to_string(level) +
              ", over the limit of " + std::to_string(int64_t(limit)) +
              " cells a cover lists: " + advice);
}

std::vector<CellId> cover_box(const Grid& grid, const std::vector<double>& bbox, int level,
                              Containment mode, const std::string& option) {
  check_bbox(bbox, option);
  CellId::CheckLevel(level);
  check_cover_size(cover_size_estimate(bbox, level), kMaxCoverCells, level, option);
  return grid.cover_bbox(bbox[0], bbox[1], bbox[2], bbox[3], level, mode);
}

void check_cover_size(const std::vector<PolygonRings>& polygons, int level,
                      const std::string& what) {
  CellId::CheckLevel(level);
  check_cover_size(cover_size_estimate(polygons, level), kMaxCoverCells, level, what);
}

std::vector<CellId> cover_geojson(const Grid& grid, const std::vector<PolygonRings>& polygons,
                                  int level, Containment mode) {
  std::vector<CellId> cells;
  grid.visit_cover_polygons(polygons, level, mode, [&cells, level](CellId cell) {
    for_each_at_level(cell, level, [&cells](CellId c) { cells.push_back(c); });
  });
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
  for (int k : {0, 2})
    if (!std::isfinite(b[size_t(k)]))
      throw Error(option + ": longitude " + fmt(b[size_t(k)]) + " is not a number");
  if (b[1] > b[3]) throw Error(option + ": south " + fmt(b[1]) + " is north of north " + fmt(b[3]));
  // W > E crosses the antimeridian, so only equality leaves nothing.
  if (b[1] == b[3])
    throw Error(option + ": south equals north (" + fmt(b[1]) + "): the box has no area");
  if (b[0] == b[2])
    throw Error(option + ": west equals east (" + fmt(b[0]) +
                "): the box has no area (the whole globe is -180 -90 180 90)");
}

}  // namespace maquette
