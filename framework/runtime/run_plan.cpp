#include "runtime/run_plan.h"

#include <algorithm>
#include <optional>

#include "core/error.h"
#include "core/region.h"

namespace maquette {
namespace {

class Planner {
 public:
  Planner(const Pipeline& pipeline, const Store* store, int threads)
      : pipeline_(pipeline), store_(store), threads_(threads) {}

  StepPlan plan(const PipelineStep& step) {
    StepPlan sp;
    sp.step = &step;
    sp.level = pipeline_.level;
    sp.tile_size = pipeline_.tile_size;
    const OperatorSpec& spec = step.op->spec();
    for (const auto& in : spec.inputs) {
      const auto it = step.inputs.find(in.name);
      if (it == step.inputs.end()) continue;
      const LayerInfo info = input_layer(step, in.name, it->second, sp);
      if (sp.inputs.empty()) {
        sp.level = info.level;
        sp.tile_size = info.tile_size;
      }
      sp.inputs.emplace_back(in.name, info);
    }
    std::vector<CellId> cells =
        sp.inputs.empty() ? pipeline_.region : tiles_in_region(sp.inputs.front().second);
    if (spec.kind == OperatorKind::Region) {
      check_one_face(step, cells);
      sp.mosaic = mosaic_box(step, cells, sp.tile_size);
    }
    for (const auto& out : spec.outputs) {
      const auto it = step.outputs.find(out.name);
      if (it == step.outputs.end()) continue;
      if (spec.kind == OperatorKind::Reduce) {
        sp.artifact = it->second;
        continue;
      }
      LayerInfo info;
      info.name = it->second;
      info.dtype = out.dtype;
      info.channels = out.channels;
      info.tile_size = sp.tile_size;
      info.level = sp.level;
      info.nodata = out.nodata;
      info.semantics = out.semantics;
      info.units = out.units;
      info.provenance = {{"operator", step.op_name}, {"params", step.params}};
      sp.outputs.emplace(out.name, info);
      produced_[info.name] = {info, cells};
    }
    const size_t chunk = default_chunk_size(cells.size(), threads_);
    sp.cells = CellPlan(std::move(cells), chunk);
    return sp;
  }

 private:
  struct Produced {
    LayerInfo info;
    std::vector<CellId> cells;  // the cells an earlier step writes, sorted
  };

  LayerInfo input_layer(const PipelineStep& step, const std::string& port, const std::string& name,
                        const StepPlan& sp) const {
    const std::string where = step.label() + ": inputs." + port + ": ";
    std::optional<LayerInfo> info;
    if (const auto it = produced_.find(name); it != produced_.end())
      info = it->second.info;
    else if (store_ != nullptr)
      info = store_->layer(name);
    if (!info) throw Error(where + "unknown layer '" + name + "' in " + pipeline_.store_path);
    if (info->kind != LayerKind::Raster)
      throw Error(where + "layer '" + name + "' is a " + std::string(layer_kind_name(info->kind)) +
                  " layer, not a raster");
    if (!sp.inputs.empty() && (info->level != sp.level || info->tile_size != sp.tile_size))
      throw Error(where + "layer '" + name + "' has level " + std::to_string(info->level) +
                  " and tile size " + std::to_string(info->tile_size) +
                  ", unlike the first input '" + sp.inputs.front().second.name + "' (level " +
                  std::to_string(sp.level) + ", tile size " + std::to_string(sp.tile_size) + ")");
    return *info;
  }

  // The layer's tiles (stored, or written by an earlier step) intersecting the region.
  std::vector<CellId> tiles_in_region(const LayerInfo& layer) const {
    std::vector<CellId> cells;
    if (store_ != nullptr && store_->layer(layer.name)) cells = stored_tiles(layer);
    if (const auto it = produced_.find(layer.name); it != produced_.end()) {
      std::vector<CellId> merged;
      std::set_union(cells.begin(), cells.end(), it->second.cells.begin(), it->second.cells.end(),
                     std::back_inserter(merged));
      cells = std::move(merged);
    }
    return cells;
  }

  std::vector<CellId> stored_tiles(const LayerInfo& layer) const {
    const std::vector<CellId>& region = pipeline_.region;
    std::vector<CellId> cells;
    if (layer.level < pipeline_.level) {
      // Coarser tiles: the ancestors of the region's cells (sorted region, so sorted ancestors).
      for (const CellId r : region) {
        const CellId a = r.parent(layer.level);
        if ((cells.empty() || cells.back() != a) && store_->has_tile(layer.name, a))
          cells.push_back(a);
      }
      return cells;
    }
    // Finer or equal tiles: one range scan per run of adjacent region cells.
    for (const IdRange& range : to_ranges(region)) {
      const auto part = store_->tile_cells(layer.name, range.min, range.max);
      cells.insert(cells.end(), part.begin(), part.end());
    }
    return cells;
  }

  static void check_one_face(const PipelineStep& step, const std::vector<CellId>& cells) {
    if (!cells.empty() && cells.front().face() != cells.back().face())
      throw Error(step.label() +
                  ": a region operator needs all cells on one face, but they span faces " +
                  CellId::FromFace(cells.front().face()).ToText() + " to " +
                  CellId::FromFace(cells.back().face()).ToText());
  }

  // Checked before anything runs, so that a huge mosaic is refused before it is allocated.
  static MosaicBox mosaic_box(const PipelineStep& step, const std::vector<CellId>& cells,
                              int tile_size) {
    if (cells.empty()) return {};
    uint32_t col0 = UINT32_MAX, row0 = UINT32_MAX, col1 = 0, row1 = 0;
    for (const CellId c : cells) {
      col0 = std::min(col0, c.col());
      row0 = std::min(row0, c.row());
      col1 = std::max(col1, c.col());
      row1 = std::max(row1, c.row());
    }
    const MosaicBox box{col0, row0, int64_t(std::max(col1 - col0, row1 - row0)) + 1};
    if (const int64_t side = box.cells * tile_size; side > kMaxMosaicSide)
      throw Error(step.label() + ": the region's mosaic would be " + std::to_string(side) + " x " +
                  std::to_string(side) + " samples, above the limit of " +
                  std::to_string(kMaxMosaicSide) + " x " + std::to_string(kMaxMosaicSide));
    return box;
  }

  const Pipeline& pipeline_;
  const Store* store_;
  int threads_;
  std::map<std::string, Produced> produced_;
};

}  // namespace

RunPlan plan_run(const Pipeline& pipeline, const Store* store, int threads) {
  Planner planner(pipeline, store, threads);
  RunPlan plan;
  for (const auto& step : pipeline.steps) plan.steps.push_back(planner.plan(step));
  return plan;
}

void print_plan(const Pipeline& pipeline, const RunPlan& plan, std::ostream& out) {
  out << "pipeline " << pipeline.source << ": store " << pipeline.store_path << ", level "
      << pipeline.level << ", tile size " << pipeline.tile_size << ", region of "
      << pipeline.region.size() << " cells\n";
  for (const auto& sp : plan.steps) {
    const OperatorSpec& spec = sp.step->op->spec();
    out << sp.step->label() << ": " << operator_kind_name(spec.kind) << " operator, "
        << sp.cells.size() << " cells at level " << sp.level << "\n";
    for (const auto& [port, layer] : sp.inputs)
      out << "  reads  " << layer.name << " (" << port << ")\n";
    for (const auto& [port, layer] : sp.outputs)
      out << "  writes " << layer.name << " (" << port << ": " << dtype_name(layer.dtype) << " x"
          << layer.channels << ", " << sp.cells.size() << " tiles of " << layer.tile_size
          << "px)\n";
    if (!sp.artifact.empty()) out << "  writes artifact " << sp.artifact << "\n";
  }
}

}  // namespace maquette
