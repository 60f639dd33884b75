// Test helpers: the texture module's operators loaded from the built .so through the framework's
// loader, run on cells (reduce operators merged in cell-id order as the runner does), and DEM
// tiles sampled from analytic fields with halos.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <set>
#include <string>
#include <vector>

#include "../model.h"
#include "core/error.h"
#include "core/halo.h"
#include "runtime/operator_registry.h"
#include "runtime/params_schema.h"

namespace maquette::texture_test {

using texture::json;

inline const Operator& texture_operator(const std::string& name) {
  static const OperatorRegistry registry = [] {
    OperatorRegistry r;
    r.add(load_module(MAQUETTE_MODULE_DIR "/libmaquette_texture.so"));
    return r;
  }();
  const Operator* op = registry.find(name);
  if (!op) throw Error("no operator " + name);
  return *op;
}

inline json full_params(const std::string& name, const json& params) {
  return validate_params(texture_operator(name).spec().params_schema, params, name);
}

// Runs a cell operator on one cell, its params validated and checked as a pipeline's are
// (OperatorSpec::check_params, the input ports `data` holds taken as mapped).
inline CellData run_cell(const std::string& name, CellId cell, int size, CellData data,
                         const json& params) {
  const auto& op = static_cast<const CellOperator&>(texture_operator(name));
  const json full = full_params(name, params);
  if (op.spec().check_params) {
    std::set<std::string> mapped;
    for (const auto& [port, tile] : data.inputs) mapped.insert(port);
    op.spec().check_params(full, mapped);
  }
  for (const OutputSpec& out : op.spec().outputs)
    data.outputs.emplace(out.name, Tile<float>(size, out.channels));
  op.run({.cell = cell, .tile_size = size, .grid = &default_grid(), .params = &full}, data);
  return data;
}

// Runs a reduce operator over cells (sorted), the inputs of each from `inputs(cell)`; returns
// the artifact's JSON.
inline json run_reduce(const std::string& name, std::vector<CellId> cells, int size,
                       const std::function<CellData(CellId)>& inputs, const json& params) {
  const auto& op = static_cast<const ReduceOperator&>(texture_operator(name));
  const json full = full_params(name, params);
  std::sort(cells.begin(), cells.end());
  json merged;
  for (const CellId c : cells)
    merged = op.merge(
        merged, op.map({.cell = c, .tile_size = size, .grid = &default_grid(), .params = &full},
                       inputs(c)));
  const Artifact a = op.finish(merged, {&default_grid(), &full, nullptr});
  return json::parse(a.text());
}

using Field = std::function<double(LonLat)>;

// A tile of `cell` holding field(pixel centre) (no halo).
inline Tile<float> sample(CellId cell, int size, const Field& field, int channels = 1) {
  const Grid& grid = default_grid();
  const int level = cell.level() + log2_tile_size(size);
  Tile<float> tile(size, channels);
  for (int row = 0; row < size; ++row)
    for (int col = 0; col < size; ++col) {
      const double v = field(pixel_centre(
          grid, {cell.face(), global_col(cell, size, col), global_row(cell, size, row)}, level));
      for (int k = 0; k < channels; ++k) tile.at(col, row, k) = float(v);
    }
  return tile;
}

// The tile of `cell` with a halo, its neighbours sampled from the same field.
inline Tile<float> with_halo(CellId cell, int size, int halo,
                             const std::function<Tile<float>(CellId)>& tile_of) {
  return assemble_halo(default_grid(), cell, size, halo,
                       [&](CellId c) { return std::optional<Tile<float>>(tile_of(c)); });
}

// A smooth synthetic relief of 0..3000 m with slopes up to ~40 degrees at ~100 m pixels.
inline double relief(LonLat p) {
  return 1500 + 1450 * std::sin(2 * M_PI * p.lon / 0.11) * std::cos(2 * M_PI * p.lat / 0.13);
}

}  // namespace maquette::texture_test
