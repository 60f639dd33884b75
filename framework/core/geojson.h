// GeoJSON in and out: polygons of a region (Polygon, MultiPolygon, Feature, FeatureCollection)
// and cell boundaries.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/grid.h"

namespace maquette {

// A polygon: outer ring first, then holes; each ring a list of lon/lat.
using PolygonRings = std::vector<std::vector<LonLat>>;

// Every polygon of a GeoJSON object; throws maquette::Error naming `where` (e.g. the file) and
// the bad member for anything that is not a (Multi)Polygon or has latitudes outside +-90.
std::vector<PolygonRings> geojson_polygons(const nlohmann::json& geojson, const std::string& where);
// Reads a GeoJSON file and returns its polygons.
std::vector<PolygonRings> read_geojson_polygons(const std::string& path);

// Cells at `level` covering every polygon of the GeoJSON, sorted and unique.
std::vector<CellId> cover_geojson(const Grid& grid, const std::vector<PolygonRings>& polygons,
                                  int level, Containment mode);

// The cell's boundary as a GeoJSON Polygon geometry (counter-clockwise ring).
nlohmann::json cell_boundary_geojson(const Grid& grid, CellId cell, int points_per_edge);

// Throws maquette::Error naming `option` unless bbox is W S E N with latitudes in +-90 and S <= N.
void check_bbox(const std::vector<double>& bbox, const std::string& option);

}  // namespace maquette
