// Test helpers: the climate module's operators loaded from the built .so through the
// framework's loader, run on cells alone or as pipeline steps through the runner on a store, and
// tiles sampled from analytic fields at pixel centres.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/halo.h"
#include "runtime/operator_registry.h"
#include "runtime/params_schema.h"
#include "runtime/pipeline.h"
#include "runtime/runner.h"

namespace maquette::climate_test {

inline const OperatorRegistry& climate_registry() {
  static const OperatorRegistry registry = [] {
    OperatorRegistry r;
    r.add(load_module(MAQUETTE_MODULE_DIR "/libmaquette_climate.so"));
    return r;
  }();
  return registry;
}

inline const Operator& climate_operator(const std::string& name) {
  const Operator* op = climate_registry().find(name);
  if (!op) throw Error("no operator " + name);
  return *op;
}

// Runs a cell operator that reads no store on one cell with `params` (defaults filled in as the
// runner does), mapping the outputs named in `outputs` (empty: all).
inline CellData run(const std::string& name, CellId cell, int size, CellData data,
                    const json& params = json::object(),
                    const std::vector<std::string>& outputs = {}) {
  const auto& op = static_cast<const CellOperator&>(climate_operator(name));
  const json full = validate_params(op.spec().params_schema, params, name);
  for (const OutputSpec& out : op.spec().outputs)
    if (outputs.empty() || std::find(outputs.begin(), outputs.end(), out.name) != outputs.end())
      data.outputs.emplace(out.name, Tile<float>(size, out.channels));
  op.run({.cell = cell, .tile_size = size, .grid = &default_grid(), .params = &full}, data);
  return data;
}

// Runs the pipeline `steps` on `cells` (of one level) of the store at `path` through the runner,
// quietly on one thread.
inline void run_steps(const std::string& path, const std::vector<CellId>& cells, int tile_size,
                      const json& steps) {
  json region = json::array();
  for (const CellId c : cells) region.push_back(c.ToText());
  const json doc = {{"store", path},
                    {"region", {{"cells", region}}},
                    {"level", cells.front().level()},
                    {"tile_size", tile_size},
                    {"steps", steps}};
  RunOptions options;
  options.threads = 1;
  options.quiet = true;
  run_pipeline(parse_pipeline(doc.dump(), "test", ".", climate_registry()), options);
}

// A tile of `cell` holding field(pixel centre) (no halo).
inline Tile<float> sample(CellId cell, int size, const std::function<double(LonLat)>& field) {
  return sample_field(default_grid(), cell, size, field);
}

// The field on `cell` with a halo, assembled from its neighbours as the runner does.
inline Tile<float> with_halo(CellId cell, int size, int halo,
                             const std::function<double(LonLat)>& field) {
  return assemble_halo(default_grid(), cell, size, halo, [&](CellId c) {
    return std::optional<Tile<float>>(sample(c, size, field));
  });
}

inline LonLat centre_of(CellId cell, int size, int col, int row) {
  return pixel_centre(default_grid(),
                      {cell.face(), global_col(cell, size, col), global_row(cell, size, row)},
                      cell.level() + log2_tile_size(size));
}

// Metres east and north of `origin` (local equirectangular; tests only need a smooth field).
inline double east_m(LonLat p, LonLat origin) {
  return (p.lon - origin.lon) * std::cos(origin.lat * M_PI / 180) * 111320.0;
}
inline double north_m(LonLat p, LonLat origin) { return (p.lat - origin.lat) * 110574.0; }

// The text of the error `f` throws ("" when it does not).
inline std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

}  // namespace maquette::climate_test
