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

// A cover lists every cell, so regions whose cells at the level would not fit in memory are
// refused first, with an estimate of the count from their lon/lat area.
inline constexpr double kMaxCoverCells = 2e7;

// Estimates of the cells at `level` in a box W S E N, and in the polygons' bounding box.
double cover_size_estimate(const std::vector<double>& bbox, int level);
double cover_size_estimate(const std::vector<PolygonRings>& polygons, int level);
// Throws maquette::Error naming `what`, the estimate `cells` and `advice` when it is over `limit`.
void check_cover_size(double cells, double limit, int level, const std::string& what,
                      const std::string& advice = "use a coarser level or a smaller region");
// Throws maquette::Error naming `what` with the estimate when the polygons' bounding box holds
// more than kMaxCoverCells cells at the level.
void check_cover_size(const std::vector<PolygonRings>& polygons, int level,
                      const std::string& what);
// Cells at `level` covering every polygon of the GeoJSON, sorted and unique.
std::vector<CellId> cover_geojson(const Grid& grid, const std::vector<PolygonRings>& polygons,
                                  int level, Containment mode);
// Cells at `level` covering a lon/lat box W S E N (checked by check_bbox, naming `option`),
// sorted; refused over kMaxCoverCells, with the estimate.
std::vector<CellId> cover_box(const Grid& grid, const std::vector<double>& bbox, int level,
                              Containment mode, const std::string& option);

// The cell's boundary as a GeoJSON Polygon geometry (counter-clockwise ring).
nlohmann::json cell_boundary_geojson(const Grid& grid, CellId cell, int points_per_edge);

// Throws maquette::Error naming `option` unless bbox is W S E N with latitudes in +-90, S < N and
// W != E (a box with area; W > E crosses the antimeridian).
void check_bbox(const std::vector<double>& bbox, const std::string& option);

}  // namespace maquette
