// Vector geometries as features layers store them (store/store.h Feature::wkb: WKB in WGS84
// lon/lat), typed: Point, LineString, Polygon (with holes) and their Multi* forms, Z kept.
#pragma once

#include <cmath>
#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace maquette {

struct GeoPoint {
  double lon = 0;  // degrees
  double lat = 0;  // degrees
  double z = NAN;  // the geometry's Z (metres in GeoJSON), NaN for a 2D geometry
};

using GeoPath = std::vector<GeoPoint>;  // a LineString, or a ring (closed: last point == first)

struct GeoPolygon {
  std::vector<GeoPath> rings;  // outer ring first, then holes
};

enum class GeometryType { Point, LineString, Polygon, MultiPoint, MultiLineString, MultiPolygon };
std::string_view geometry_type_name(GeometryType type);  // "MultiPolygon"

// One geometry: a single Point, LineString or Polygon is the one element of its vector.
struct Geometry {
  GeometryType type = GeometryType::Point;
  bool has_z = false;
  std::vector<GeoPoint> points;      // Point, MultiPoint
  std::vector<GeoPath> lines;        // LineString, MultiLineString
  std::vector<GeoPolygon> polygons;  // Polygon, MultiPolygon
};

// Parses ISO or EWKB (2D, Z, M or ZM: M is dropped), either byte order. Throws maquette::Error
// prefixed with `where` (e.g. "feature 3 of 'roads'"): "... has truncated WKB", "... is a
// GeometryCollection, not a Point, LineString, Polygon or one of their Multi* forms", a Multi*
// part of another type, "... has a coordinate that is not finite" (lon, lat, or Z when it has
// Z), or "... has a latitude of 7782.348801 degrees" (outside [-90, 90]).
Geometry parse_wkb(std::span<const std::byte> wkb, const std::string& where);

}  // namespace maquette
