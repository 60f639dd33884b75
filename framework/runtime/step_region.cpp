#include <cmath>
#include <map>

#include "core/error.h"
#include "runtime/step_exec.h"

namespace maquette {
namespace {

// Copies `src` (no halo) into `dst` with its top-left at (col, row), or the reverse.
void paste(const Tile<float>& src, Tile<float>& dst, int64_t col, int64_t row) {
  for (int r = 0; r < src.size(); ++r)
    for (int c = 0; c < src.size(); ++c)
      for (int k = 0; k < src.channels(); ++k)
        dst.at(int(col) + c, int(row) + r, k) = src.at(c, r, k);
}

void cut(const Tile<float>& src, Tile<float>& dst, int64_t col, int64_t row) {
  for (int r = 0; r < dst.size(); ++r)
    for (int c = 0; c < dst.size(); ++c)
      for (int k = 0; k < dst.channels(); ++k)
        dst.at(c, r, k) = src.at(int(col) + c, int(row) + r, k);
}

// The features of the port within its reach of any of `cells`, by id.
FeatureList near_any(const FeaturePort& port, const std::vector<CellId>& cells) {
  std::map<int64_t, const VectorFeature*> by_id;
  for (const CellId c : cells)
    for (const VectorFeature* f : port.index->within(CellOutline(default_grid(), c), port.reach_m))
      by_id.emplace(f->id, f);
  FeatureList out;
  for (const auto& [id, f] : by_id) out.push_back(f);
  return out;
}

// A refined step ("refine": k) writes output mosaics, and so tiles, 2^k times finer: the same
// place at pixel level + k.
void refine_mosaic(Mosaic& m, int refine) {
  m.level += refine;
  m.origin_col <<= refine;
  m.origin_row <<= refine;
}

}  // namespace

void run_region_step(const StepPlan& plan, StepIO& io, Progress& progress) {
  const auto& op = static_cast<const RegionOperator&>(*plan.step->op);
  const std::vector<CellId>& cells = plan.cells.cells();
  if (cells.empty()) return;
  const int n = plan.tile_size;
  const auto [col0, row0, extent] = plan.mosaic;
  const int side = int(extent * n);  // at most kMaxMosaicSide (checked by plan_run)
  auto offset = [&](CellId c) {
    return std::pair<int64_t, int64_t>(int64_t(c.col() - col0) * n, int64_t(c.row() - row0) * n);
  };

  Mosaic input;
  input.face = cells.front().face();
  input.level = plan.level + log2_tile_size(n);
  input.origin_col = int64_t(col0) * n;
  input.origin_row = int64_t(row0) * n;
  Mosaic output = input;
  for (const auto& [port, layer] : plan.inputs) {
    Tile<float> mosaic(side, layer.channels, 0, NAN);
    for (const CellId c : cells)
      if (const auto tile = io.read(layer, c))
        paste(*tile, mosaic, offset(c).first, offset(c).second);
    input.layers.emplace(port, std::move(mosaic));
  }
  for (const FeaturePort& f : plan.features) input.features[f.port] = near_any(f, cells);
  const int refine = plan.step->refine;
  refine_mosaic(output, refine);
  output.layers = io.blank_outputs(side << refine);
  for (const CellId c : cells) output.content.emplace(c, io.blank_content(c));
  try {
    op.run({&default_grid(), &plan.params, &io.store(), &plan.inputs}, input, output);
  } catch (const std::exception& e) {
    throw Error(plan.step->label() + " failed on the region's mosaic: " + e.what());
  } catch (...) {
    throw Error(plan.step->label() + " failed on the region's mosaic: unknown exception");
  }
  for (const auto& [port, layer] : plan.outputs) {
    if (layer.kind != LayerKind::Raster) continue;
    const Tile<float>& m = output.layers.at(port);
    if (m.size() != side << refine || m.channels() != layer.channels)
      throw Error(plan.step->label() + ": the operator changed the size of output mosaic '" + port +
                  "'");
  }

  if (output.content.size() != cells.size())  // the runner prepared one entry per cell
    throw Error(plan.step->label() + ": the operator added content for cells not of the step");

  std::vector<TileSet> tiles(cells.size(), io.blank_outputs(n << refine));
  std::vector<CellOutput> outputs;
  for (size_t i = 0; i < cells.size(); ++i) {
    for (auto& [port, tile] : tiles[i])
      cut(output.layers.at(port), tile, offset(cells[i]).first << refine,
          offset(cells[i]).second << refine);
    try {
      outputs.push_back(
          {cells[i], &tiles[i], io.encode_content(cells[i], output.content.at(cells[i]))});
    } catch (const std::exception& e) {
      throw Error(plan.step->label() + " failed on cell " + cells[i].ToText() + ": " + e.what());
    }
  }
  io.write(outputs);
  progress.advance(int64_t(cells.size()));
}

}  // namespace maquette
