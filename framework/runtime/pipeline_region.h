// The "region" of a pipeline: a bbox, a GeoJSON polygon or a list of cells, as cells at a level.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/cell_id.h"

namespace maquette {

// The region's cells at `level`, sorted by id: the cells overlapping a bbox [W, S, E, N] or a
// GeoJSON Polygon/MultiPolygon/Feature/FeatureCollection (inline, or a file path relative to
// `base_dir`), or the listed cells at `level` (see uncompact in core/region.h). Errors are
// prefixed with `context` (the pipeline file).
std::vector<CellId> region_cells(const nlohmann::json& region, int level,
                                 const std::string& base_dir, const std::string& context);

}  // namespace maquette
