// Test helpers: the terrain module's operators loaded from the built .so through the framework's
// loader, run on one cell, and tiles sampled from analytic fields at pixel centres.
#pragma once

#include <cmath>
#include <functional>
#include <string>

#include "core/error.h"
#include "core/halo.h"
#include "runtime/operator_registry.h"
#include "runtime/params_schema.h"

namespace maquette::terrain_test {

inline const CellOperator& terrain_operator(const std::string& name) {
  static const OperatorRegistry registry = [] {
    OperatorRegistry r;
    r.add(load_module(MAQUETTE_MODULE_DIR "/libmaquette_terrain.so"));
    return r;
  }();
  const Operator* op = registry.find(name);
  if (!op || op->spec().kind != OperatorKind::Cell) throw Error("no cell operator " + name);
  return static_cast<const CellOperator&>(*op);
}

// Runs a cell operator on one cell with `params` (defaults filled in as the runner does).
inline CellData run(const std::string& name, CellId cell, int size, CellData data,
                    const json& params = json::object()) {
  const CellOperator& op = terrain_operator(name);
  const json full = validate_params(op.spec().params_schema, params, name);
  for (const OutputSpec& out : op.spec().outputs)
    data.outputs.emplace(out.name, Tile<float>(size, out.channels));
  op.run({.cell = cell, .tile_size = size, .grid = &default_grid(), .params = &full}, data);
  return data;
}

// A tile of `cell` holding field(pixel centre) (no halo).
inline Tile<float> sample(CellId cell, int size, const std::function<double(LonLat)>& field) {
  return sample_field(default_grid(), cell, size, field);
}

// True centre of pixel (col, row) of `cell`'s tile, halo pixels included.
inline LonLat true_centre(CellId cell, int size, int col, int row) {
  const int level = cell.level() + log2_tile_size(size);
  return pixel_centre(default_grid(), *pixel_source(default_grid(), cell, size, col, row), level);
}

}  // namespace maquette::terrain_test
