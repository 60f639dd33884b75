#include "runtime/pipeline_region.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "core/error.h"
#include "core/geojson.h"
#include "core/grid.h"
#include "core/json_file.h"
#include "core/region.h"

namespace maquette {
namespace {

using json = nlohmann::json;

std::vector<CellId> bbox_cells(const json& v, int level, const std::string& where) {
  std::vector<double> bbox;
  if (v.is_array())
    for (const auto& x : v) {
      if (!x.is_number()) throw Error(where + ": expected a number, got " + excerpt(x));
      bbox.push_back(x.get<double>());
    }
  return cover_box(default_grid(), bbox, level, Containment::Overlap, where);
}

std::vector<CellId> geojson_cells(const json& v, int level, const std::string& base_dir,
                                  const std::string& where) {
  const auto polygons =
      v.is_string()
          ? read_geojson_polygons((std::filesystem::path(base_dir) / v.get<std::string>()).string())
          : geojson_polygons(v, where);
  check_cover_size(polygons, level, where);
  return cover_geojson(default_grid(), polygons, level, Containment::Overlap);
}

std::vector<CellId> listed_cells(const json& v, int level, const std::string& where) {
  if (!v.is_array()) throw Error(where + ": expected an array of cell ids, got " + excerpt(v));
  std::vector<CellId> cells;
  for (size_t i = 0; i < v.size(); ++i) {
    std::optional<CellId> cell;
    if (v[i].is_string()) cell = CellId::FromText(v[i].get<std::string>());
    if (v[i].is_number_unsigned() && CellId(v[i].get<uint64_t>()).is_valid())
      cell = CellId(v[i].get<uint64_t>());
    if (!cell)
      throw Error(where + "[" + std::to_string(i) + "]: " + excerpt(v[i]) +
                  " is not a valid cell id");
    cells.push_back(*cell);
  }
  // Listed at `level`, a coarse cell is 4^(level - its level) cells: refused as a cover would be.
  double count = 0;
  for (const CellId c : cells) count += std::ldexp(1.0, 2 * std::max(0, level - c.level()));
  if (count > kMaxCoverCells)
    throw Error(where + ": the cells hold " + std::to_string(int64_t(std::min(count, 9e18))) +
                " cells at level " + std::to_string(level) + ", over the limit of " +
                std::to_string(int64_t(kMaxCoverCells)) +
                " cells a region lists: use a coarser level or finer cells");
  return uncompact(cells, level);
}

}  // namespace

std::vector<CellId> region_cells(const json& region, int level, const std::string& base_dir,
                                 const std::string& context) {
  if (!region.is_object() || region.size() != 1)
    throw Error(context +
                ": region: expected {\"bbox\": ...}, {\"geojson\": ...} or {\"cells\": ...}, got " +
                excerpt(region));
  const std::string key = region.begin().key();
  const json& value = region.begin().value();
  const std::string where = context + ": region." + key;
  std::vector<CellId> cells;
  if (key == "bbox")
    cells = bbox_cells(value, level, where);
  else if (key == "geojson")
    cells = geojson_cells(value, level, base_dir, where);
  else if (key == "cells")
    cells = listed_cells(value, level, where);
  else
    throw Error(context + ": region: unknown field '" + excerpt(key) +
                "' (expected bbox, geojson or cells)");
  if (cells.empty()) throw Error(where + ": the region covers no cells");
  return cells;
}

}  // namespace maquette
