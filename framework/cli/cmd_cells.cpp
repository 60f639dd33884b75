// maquette cells: the grid from the command line (point to cell, cell info, cover, levels).
#include <spdlog/spdlog.h>

#include <cstdio>
#include <functional>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "core/error.h"
#include "core/geojson.h"
#include "core/grid.h"
#include "core/region.h"
#include "core/tile.h"

namespace maquette::cli {
namespace {

using json = nlohmann::json;

struct CellsOptions {
  double lon = 0, lat = 0;
  int level = 0;
  bool json_out = false;
  std::string id;
  std::vector<double> bbox;
  std::string geojson;
  std::string mode = "overlap";
  bool compact = false;
  int tile_size = 256;
  int edge_points = 16;
  double max_cells = 1e9;
};

Containment parse_mode(const std::string& mode) {
  if (mode == "centre" || mode == "center") return Containment::Centre;
  if (mode == "overlap") return Containment::Overlap;
  if (mode == "full") return Containment::Full;
  throw Error("--mode '" + mode + "' is not one of centre, overlap, full");
}

void print_cell_info(const CellsOptions& o) {
  const Grid& grid = default_grid();
  const CellId cell = CellId::Parse(o.id);
  const LonLat c = grid.centre(cell);
  const PlaneSquare sq = grid.plane_square(cell);
  const json boundary = cell_boundary_geojson(grid, cell, o.edge_points);
  if (o.json_out) {
    json j = {{"id", cell.ToText()},
              {"int_id", cell.id()},
              {"level", cell.level()},
              {"face", std::string(1, CellId::kFaceLetters[size_t(cell.face())])},
              {"centre", {c.lon, c.lat}},
              {"area_m2", grid.area(cell.level())},
              {"plane_square", {{"x_min", sq.x_min}, {"y_max", sq.y_max}, {"side", sq.side}}},
              {"boundary", boundary}};
    std::cout << j.dump(2) << "\n";
    return;
  }
  std::printf("cell      %s (integer id %llu)\n", cell.ToText().c_str(),
              static_cast<unsigned long long>(cell.id()));
  std::printf("level     %d\n", cell.level());
  std::printf("centre    %.9f %.9f (lon lat, degrees)\n", c.lon, c.lat);
  std::printf("area      %.6f m2 (exact, every cell of level %d)\n", grid.area(cell.level()),
              cell.level());
  std::printf("plane     x %.6f .. %.6f, y %.6f .. %.6f (m), side %.6f m\n", sq.x_min,
              sq.x_min + sq.side, sq.y_max - sq.side, sq.y_max, sq.side);
  std::printf("boundary  %s\n", boundary.dump().c_str());
}

// Prints cells as they come: one id a line, or the items of one JSON array.
class CellPrinter {
 public:
  explicit CellPrinter(bool json) : json_(json) {}
  void operator()(CellId cell) {
    const std::string id = cell.ToText();
    if (json_)
      std::printf(count_ == 0 ? "[\"%s\"" : ",\"%s\"", id.c_str());
    else
      std::printf("%s\n", id.c_str());
    ++count_;
  }
  void finish() const {
    if (json_) std::printf(count_ == 0 ? "[]\n" : "]\n");
  }
  int64_t count() const { return count_; }

 private:
  bool json_;
  int64_t count_ = 0;
};

// Streams the cover: cells are printed as the grid finds them, so that any cover within
// --max-cells is listed in bounded memory.
void print_cover(const CellsOptions& o) {
  CellId::CheckLevel(o.level);
  const Grid& grid = default_grid();
  const Containment mode = parse_mode(o.mode);
  std::vector<PolygonRings> polygons;
  if (!o.geojson.empty()) {
    polygons = read_geojson_polygons(o.geojson);
  } else if (o.bbox.size() == 4) {
    check_bbox(o.bbox, "--bbox");
  } else {
    throw Error("cells cover needs --bbox W S E N or --geojson FILE");
  }
  check_cover_size(polygons.empty() ? cover_size_estimate(o.bbox, o.level)
                                    : cover_size_estimate(polygons, o.level),
                   o.max_cells, o.level, polygons.empty() ? "--bbox" : o.geojson,
                   "use a coarser level or a smaller region, or raise --max-cells");

  CellPrinter print(o.json_out);
  StreamCompactor compactor(std::ref(print));
  const std::function<void(CellId)> visit = [&](CellId cell) {
    if (o.compact)
      compactor.add(cell);
    else
      for_each_at_level(cell, o.level, std::ref(print));
  };
  if (polygons.empty())
    grid.visit_cover_bbox(o.bbox[0], o.bbox[1], o.bbox[2], o.bbox[3], o.level, mode, visit);
  else
    grid.visit_cover_polygons(polygons, o.level, mode, visit);
  compactor.finish();
  print.finish();
  if (print.count() == 0)
    spdlog::warn("no cell at level {} {} the region", o.level,
                 mode == Containment::Full      ? "lies wholly inside"
                 : mode == Containment::Overlap ? "overlaps"
                                                : "has its centre in");
}

void print_levels(const CellsOptions& o) {
  const Grid& grid = default_grid();
  log2_tile_size(o.tile_size);
  if (o.json_out) {
    json rows = json::array();
    for (int l = 0; l <= CellId::kMaxLevel; ++l) {
      const LevelInfo i = grid.level_info(l, o.tile_size);
      rows.push_back({{"level", l},
                      {"cell_side_m", i.cell_side_m},
                      {"plane_side_m", i.plane_side_m},
                      {"area_m2", i.area_m2},
                      {"pixel_m", i.pixel_m},
                      {"tile_size", o.tile_size}});
    }
    std::cout << rows.dump(2) << "\n";
    return;
  }
  std::printf("%5s %16s %16s %22s %14s\n", "level", "cell side (m)", "plane side (m)", "area (m2)",
              ("pixel@" + std::to_string(o.tile_size) + " (m)").c_str());
  for (int l = 0; l <= CellId::kMaxLevel; ++l) {
    const LevelInfo i = grid.level_info(l, o.tile_size);
    std::printf("%5d %16.4f %16.4f %22.6f %14.6f\n", l, i.cell_side_m, i.plane_side_m, i.area_m2,
                i.pixel_m);
  }
}

}  // namespace

void add_cells_command(CLI::App& app) {
  auto opts = std::make_shared<CellsOptions>();
  CLI::App* cells = app.add_subcommand(
      "cells", "The grid: point to cell, cell info, cover a region, levels table");
  cells->require_subcommand(1);

  CLI::App* from_point =
      cells->add_subcommand("from-point", "Print the id of the cell holding a point");
  from_point->add_option("LON", opts->lon, "Longitude, degrees")
      ->required()
      ->check(CLI::Range(-360.0, 360.0));
  from_point->add_option("LAT", opts->lat, "Latitude, degrees (-90..90)")->required();
  from_point->add_option("--level,-l", opts->level, "Cell level (0..29)")->required();
  from_point->add_flag("--json", opts->json_out, "Print JSON");
  from_point->callback([opts] {
    CellId::CheckLevel(opts->level);
    const CellId cell = default_grid().cell_from_point({opts->lon, opts->lat}, opts->level);
    if (opts->json_out)
      std::cout << json{{"id", cell.ToText()}, {"int_id", cell.id()}}.dump() << "\n";
    else
      std::printf("%s\n", cell.ToText().c_str());
  });

  CLI::App* info =
      cells->add_subcommand("info", "Centre, area, level, plane square and boundary of a cell");
  info->add_option("ID", opts->id, "Cell id: text (e.g. N11011323) or integer")->required();
  info->add_option("--edge-points", opts->edge_points, "Boundary points per edge")
      ->check(CLI::Range(1, 100000));
  info->add_flag("--json", opts->json_out, "Print JSON");
  info->callback([opts] { print_cell_info(*opts); });

  CLI::App* cover = cells->add_subcommand("cover", "Print the cells at a level covering a region");
  auto* bbox =
      cover->add_option("--bbox", opts->bbox, "W S E N in degrees (W > E crosses the antimeridian)")
          ->expected(4);
  cover->add_option("--geojson", opts->geojson, "GeoJSON file with a Polygon or MultiPolygon")
      ->excludes(bbox);
  cover->add_option("--level,-l", opts->level, "Cell level (0..29)")->required();
  cover
      ->add_option("--mode", opts->mode,
                   "centre: cell centre inside; overlap: cell touches; full: cell inside")
      ->capture_default_str();
  cover->add_flag("--compact", opts->compact,
                  "Replace complete sets of 4 siblings by their parent");
  cover->add_flag("--json", opts->json_out, "Print a JSON array");
  cover
      ->add_option("--max-cells", opts->max_cells,
                   "Refuse regions holding more cells at the level than this (estimated from "
                   "their lon/lat area; cells are streamed, so only the output's size bounds it)")
      ->capture_default_str();
  cover->callback([opts] { print_cover(*opts); });

  CLI::App* levels =
      cells->add_subcommand("levels", "Print the levels table: cell side, area, pixel size");
  levels->add_option("--tile-size", opts->tile_size, "Tile size in pixels (a power of two)")
      ->capture_default_str();
  levels->add_flag("--json", opts->json_out, "Print JSON");
  levels->callback([opts] { print_levels(*opts); });
}

}  // namespace maquette::cli
