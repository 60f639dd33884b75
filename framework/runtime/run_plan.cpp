#include "runtime/run_plan.h"

#include <algorithm>
#include <optional>
#include <set>

#include "core/data_footprint.h"
#include "core/error.h"
#include "core/output_clash.h"
#include "core/region.h"
#include "core/tile.h"
#include "core/unfolded_faces.h"
#include "runtime/artifact_refs.h"
#include "runtime/params_schema.h"

namespace maquette {
namespace {

// Heights made from heights keep their vertical datum (formats/gdal/vertical_datum.h) and the
// footprint of their sources (core/data_footprint.h): an output takes those of the input of the
// same port name and units (terrain.fill_voids' "dem").
void inherit_source_description(const std::vector<std::pair<std::string, LayerInfo>>& inputs,
                                const std::string& port, LayerInfo& output) {
  for (const auto& [name, in] : inputs)
    if (name == port && in.units == output.units)
      for (const char* key : {"vertical_datum", "footprint"})
        if (in.provenance.contains(key)) output.provenance[key] = in.provenance[key];
}

class Planner {
 public:
  Planner(const Pipeline& pipeline, const Store* store, int threads)
      : pipeline_(pipeline), store_(store), threads_(threads) {}

  StepPlan plan(const PipelineStep& step) {
    StepPlan sp;
    sp.step = &step;
    sp.params = step.params;
    sp.level = pipeline_.level;
    sp.tile_size = pipeline_.tile_size;
    const OperatorSpec& spec = step.op->spec();
    check_artifact_refs(step);
    check_named_params(step);
    if (spec.kind == OperatorKind::Task) return plan_task(step, std::move(sp));
    for (const auto& in : spec.inputs) {
      const auto it = step.inputs.find(in.name);
      if (it == step.inputs.end()) continue;
      if (in.kind == LayerKind::Features) {
        sp.features.push_back(features_port(step, in, it->second));
        continue;
      }
      const LayerInfo info = input_layer(step, in, it->second, sp);
      if (sp.inputs.empty()) {
        sp.level = info.level;
        sp.tile_size = info.tile_size;
      }
      sp.inputs.emplace_back(in.name, info);
    }
    std::vector<CellId> cells =
        sp.inputs.empty() ? cells_near(sp.features) : tiles_in_region(sp.inputs.front().second);
    if (spec.fills_footprint && !sp.inputs.empty())
      cells = with_footprint_cells(std::move(cells), sp.inputs.front().second);
    if (spec.kind == OperatorKind::Region)
      sp.mosaic = mosaic_box(step, cells,
                             spec.spans_faces ? anchor_face(step, cells) : one_face(step, cells),
                             sp.tile_size);
    const int out_tile_size = output_tile_size(step, sp.tile_size);
    for (const auto& out : spec.outputs) {
      const auto it = step.outputs.find(out.name);
      if (it == step.outputs.end()) continue;
      if (spec.kind == OperatorKind::Reduce) {
        sp.artifact = it->second;
        artifacts_.insert(sp.artifact);
        continue;
      }
      LayerInfo info;
      info.name = it->second;
      info.dtype = out.dtype;
      info.channels = out.channels;
      info.tile_size = out_tile_size;
      info.level = sp.level;
      info.nodata = out.nodata;
      info.semantics = out.semantics;
      info.units = out.units;
      info.codec = out.codec;
      info.kind = out.kind;
      info.provenance = {{"operator", step.op_name}, {"params", step.params}};
      inherit_source_description(sp.inputs, out.name, info);
      check_stored(step, out.name, info);
      sp.outputs.emplace(out.name, info);
      produced_[info.name] = {info, cells};
    }
    const size_t chunk = default_chunk_size(cells.size(), threads_);
    sp.cells = CellPlan(std::move(cells), chunk);
    return sp;
  }

 private:
  // An output layer the store holds must keep its definition (Store::check_layer): refused here,
  // naming the step, before a run writes anything, and by a dry run.
  void check_stored(const PipelineStep& step, const std::string& port,
                    const LayerInfo& info) const {
    if (store_ == nullptr) return;
    try {
      store_->check_layer(info);
    } catch (const Error& e) {
      throw Error(step.label() + ": outputs." + port + ": " + e.what());
    }
  }

  struct Produced {
    LayerInfo info;
    std::vector<CellId> cells;  // the cells an earlier step writes, sorted
  };

  // A task's layers read must exist; the raster layer it writes is an output like a cell step's
  // (its tiles within the region are the cells of the steps reading it).
  StepPlan plan_task(const PipelineStep& step, StepPlan sp) {
    TaskPlan task;
    try {
      task = static_cast<const TaskOperator&>(*step.op).plan(task_context(pipeline_, step));
    } catch (const std::exception& e) {
      throw Error(step.label() + ": " + e.what());
    }
    for (const auto& [field, name] : task.reads)
      if (!produced_.count(name) && !written_.count(name) &&
          !(store_ != nullptr && store_->layer(name)))
        throw Error(step.label() + ": " + field + ": unknown layer '" + name + "' in " +
                    pipeline_.store_path);
    if (!task.written.empty()) written_.insert(task.written);
    std::vector<CellId> cells = pipeline_.region;  // a task without a raster layer records these
    if (task.layer) {
      sp.level = task.layer->level;
      sp.tile_size = task.layer->tile_size;
      check_stored(step, step.outputs.begin()->first, *task.layer);
      sp.outputs.emplace(step.outputs.begin()->first, *task.layer);
      produced_[task.layer->name] = {*task.layer, within_region(task.cells, task.layer->level)};
      cells = task.cells;
    }
    sp.cells = CellPlan(std::move(cells), 1);
    return sp;
  }

  // `cells` (sorted, at the layer's level) and the region's cells overlapping the layer's
  // footprint (OperatorSpec::fills_footprint).
  std::vector<CellId> with_footprint_cells(std::vector<CellId> cells,
                                           const LayerInfo& layer) const {
    const std::optional<DataFootprint> footprint =
        DataFootprint::from_provenance(layer.provenance, layer.name);
    if (!footprint) return cells;
    const std::vector<CellId> inside =
        within_region(footprint->cover(default_grid(), layer.level), layer.level);
    std::vector<CellId> merged;
    std::set_union(cells.begin(), cells.end(), inside.begin(), inside.end(),
                   std::back_inserter(merged));
    return merged;
  }

  // The cells of `cells` (sorted, at `level`) overlapping the region.
  std::vector<CellId> within_region(const std::vector<CellId>& cells, int level) const {
    const std::vector<CellId>& region = pipeline_.region;
    std::vector<CellId> out;
    if (level >= pipeline_.level) {
      for (const CellId c : cells)
        if (std::binary_search(region.begin(), region.end(), c.parent(pipeline_.level)))
          out.push_back(c);
      return out;
    }
    std::vector<CellId> ancestors;  // sorted, since the region is
    for (const CellId r : region)
      if (ancestors.empty() || ancestors.back() != r.parent(level))
        ancestors.push_back(r.parent(level));
    std::set_intersection(cells.begin(), cells.end(), ancestors.begin(), ancestors.end(),
                          std::back_inserter(out));
    return out;
  }

  // Artifacts in params ({"$artifact": NAME}) must be in the store or written by an earlier step.
  void check_artifact_refs(const PipelineStep& step) const {
    for (const auto& [path, name] : artifact_refs(step.params))
      require_artifact(step.label() + ": " + path, name);
  }

  // `where`: "step 2 (op): params.fit".
  void require_artifact(const std::string& where, const std::string& name) const {
    if (!artifacts_.count(name) && !written_.count(name) &&
        !(store_ != nullptr && store_->get_artifact(name)))
      throw Error(where + ": unknown artifact '" + name + "' (not in " + pipeline_.store_path +
                  " nor written by an earlier step)");
  }

  // The params naming what the step reads or writes (params_schema.h, named_param).
  void check_named_params(const PipelineStep& step) const {
    const json& schema = step.op->spec().params_schema;
    if (!schema.contains("properties")) return;
    for (const auto& [key, param] : schema.at("properties").items()) {
      const std::optional<NamedKind> kind = named_kind(param);
      const auto value = step.params.find(key);  // a string, once validated
      if (!kind || value == step.params.end() || !value->is_string() ||
          value->get_ref<const std::string&>().empty())
        continue;
      const std::string& name = value->get_ref<const std::string&>();
      const std::string where = step.label() + ": params." + key;
      if (*kind == NamedKind::OutputFile) {
        try {
          check_outputs_spare_inputs(
              {name}, {{"the store", pipeline_.store_path}, {"the pipeline", pipeline_.source}});
        } catch (const Error& e) {
          throw Error(where + ": " + e.what());
        }
        continue;
      }
      for (const auto& [port, output] : step.outputs)
        if (output == name)
          throw Error(step.label() + ": outputs." + port + ": '" + name +
                      "' is also what the step reads (params." + key + ")");
      if (*kind == NamedKind::Artifact) {
        require_artifact(where, name);
      } else if (!produced_.count(name) && !written_.count(name) &&
                 !(store_ != nullptr && store_->layer(name))) {
        throw Error(where + ": unknown layer '" + name + "' (not in " + pipeline_.store_path +
                    " nor written by an earlier step)");
      }
    }
  }

  // The layer `name` given to a port taking `kind` layers, written by an earlier step or in the
  // store; `where` is "step 2 (op): inputs.PORT: ".
  LayerInfo port_layer(const std::string& where, const std::string& name, LayerKind kind) const {
    std::optional<LayerInfo> info;
    if (const auto it = produced_.find(name); it != produced_.end())
      info = it->second.info;
    else if (store_ != nullptr)
      info = store_->layer(name);
    if (!info) throw Error(where + "unknown layer '" + name + "' in " + pipeline_.store_path);
    if (info->kind != kind)
      throw Error(where + "layer '" + name + "' is a " + std::string(layer_kind_name(info->kind)) +
                  " layer, but the port takes a " + std::string(layer_kind_name(kind)) + " layer");
    return *info;
  }

  // A features port: its features are read now, unless an earlier step (a task) writes the
  // layer, whose features are then read when the step starts.
  FeaturePort features_port(const PipelineStep& step, const InputSpec& in,
                            const std::string& name) const {
    FeaturePort fp{in.name, name, in.reach_m, nullptr};
    if (written_.count(name)) return fp;
    const std::string where = step.label() + ": inputs." + in.name;
    port_layer(where + ": ", name, LayerKind::Features);
    fp.index = std::make_shared<const FeatureIndex>(*store_, name, where);
    return fp;
  }

  // The region's cells within reach of a feature of any port: all of them when the features of
  // a port are not known yet (written by an earlier step), or when there is no port.
  std::vector<CellId> cells_near(const std::vector<FeaturePort>& ports) const {
    if (ports.empty() ||
        std::any_of(ports.begin(), ports.end(), [](const FeaturePort& p) { return !p.index; }))
      return pipeline_.region;
    std::vector<CellId> cells;
    for (const CellId c : pipeline_.region) {
      const CellOutline outline(default_grid(), c);
      if (std::any_of(ports.begin(), ports.end(), [&](const FeaturePort& p) {
            return !p.index->within(outline, p.reach_m).empty();
          }))
        cells.push_back(c);
    }
    return cells;
  }

  LayerInfo input_layer(const PipelineStep& step, const InputSpec& port, const std::string& name,
                        const StepPlan& sp) const {
    const std::string where = step.label() + ": inputs." + port.name + ": ";
    const LayerInfo info = port_layer(where, name, LayerKind::Raster);
    const std::string takes = " (" + port.description + ")";
    if (port.semantics && info.semantics != *port.semantics)
      throw Error(where + "layer '" + name + "' is " + std::string(semantics_name(info.semantics)) +
                  ", but the port takes a " + std::string(semantics_name(*port.semantics)) +
                  " layer" + takes);
    if (!port.channels.empty() && std::find(port.channels.begin(), port.channels.end(),
                                            info.channels) == port.channels.end()) {
      std::string counts;
      for (const int c : port.channels)
        counts += (counts.empty() ? "" : " or ") + std::to_string(c);
      throw Error(where + "layer '" + name + "' has " + std::to_string(info.channels) +
                  (info.channels == 1 ? " channel" : " channels") + ", but the port takes " +
                  counts + takes);
    }
    if (!sp.inputs.empty() && (info.level != sp.level || info.tile_size != sp.tile_size))
      throw Error(where + "layer '" + name + "' has level " + std::to_string(info.level) +
                  " and tile size " + std::to_string(info.tile_size) +
                  ", unlike the first input '" + sp.inputs.front().second.name + "' (level " +
                  std::to_string(sp.level) + ", tile size " + std::to_string(sp.tile_size) + ")");
    return info;
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

  // The step's input tile size times 2^refine, a valid tile size (log2_tile_size).
  static int output_tile_size(const PipelineStep& step, int tile_size) {
    const int size = tile_size << step.refine;  // refine <= 12, tile_size <= 4096: no overflow
    try {
      log2_tile_size(size);
    } catch (const Error& e) {
      throw Error(step.label() + ": refine: " + std::to_string(step.refine) +
                  " levels finer than " + std::to_string(tile_size) + "-sample tiles: " + e.what());
    }
    return size;
  }

  static int one_face(const PipelineStep& step, const std::vector<CellId>& cells) {
    if (!cells.empty() && cells.front().face() != cells.back().face())
      throw Error(step.label() +
                  ": a region operator needs all cells on one face, but they span faces " +
                  CellId::FromFace(cells.front().face()).ToText() + " to " +
                  CellId::FromFace(cells.back().face()).ToText());
    return cells.empty() ? 0 : cells.front().face();
  }

  // The face a mosaic over several faces is unfolded around: the first (by id) that shares an
  // edge with each of the others, which share none among themselves (two that did would meet
  // the anchor at a corner, with a gap between them in the plane). The same for any tiling of
  // the same ground.
  static int anchor_face(const PipelineStep& step, const std::vector<CellId>& cells) {
    std::vector<CellId> first_of_face;  // cells sorted by id, so by face
    for (const CellId c : cells)
      if (first_of_face.empty() || first_of_face.back().face() != c.face())
        first_of_face.push_back(c);
    const Grid& grid = default_grid();
    const auto adjacent = [&](size_t i, size_t j) {
      return UnfoldedFaces::adjacent(grid, first_of_face[i].face(), first_of_face[j].face());
    };
    const size_t n = first_of_face.size();
    if (n <= 1) return n == 0 ? 0 : first_of_face.front().face();
    for (size_t a = 0; a < n; ++a) {
      bool fits = true;
      for (size_t i = 0; i < n; ++i)
        for (size_t j = i + 1; j < n; ++j)
          fits = fits && (i == a || j == a ? adjacent(i, j) : !adjacent(i, j));
      if (fits) return first_of_face[a].face();
    }
    const auto named = [&](size_t i) {
      const CellId c = first_of_face[i];
      return c.ToText() + " (face " + CellId::FromFace(c.face()).ToText() + ")";
    };
    for (size_t i = 0; i < n; ++i)
      for (size_t j = i + 1; j < n; ++j)
        for (size_t k = j + 1; k < n; ++k)
          if (adjacent(i, j) && adjacent(j, k) && adjacent(i, k))
            throw Error(step.label() + ": the region's cells " + named(i) + ", " + named(j) +
                        " and " + named(k) +
                        " lie on three faces meeting at a corner, which leave a gap when unfolded "
                        "into one plane: split the region there");
    std::string faces;
    for (size_t i = 0; i < n; ++i) faces += (i == 0 ? "" : ", ") + named(i);
    throw Error(step.label() + ": the region's cells " + faces +
                " lie on faces that no one face and the neighbours across its edges hold: split "
                "the region");
  }

  // Checked before anything runs, so that a huge mosaic is refused before it is allocated. The
  // box of the cells' tiles in the plane unfolded around `face` (just `face` when they lie on it).
  static MosaicBox mosaic_box(const PipelineStep& step, const std::vector<CellId>& cells, int face,
                              int tile_size) {
    if (cells.empty()) return {};
    const UnfoldedFaces plane(default_grid(), face,
                              cells.front().level() + log2_tile_size(tile_size));
    int64_t col0 = INT64_MAX, row0 = INT64_MAX, col1 = INT64_MIN, row1 = INT64_MIN;
    for (const CellId c : cells) {
      const auto place = plane.place_tile(c, tile_size);  // the anchor's faces have a place
      for (const int64_t i : {int64_t(0), int64_t(tile_size - 1)}) {
        const auto [col, row] = place->at(i, i);
        col0 = std::min(col0, col), row0 = std::min(row0, row);
        col1 = std::max(col1, col), row1 = std::max(row1, row);
      }
    }
    // Tiles lie on whole cells of the unfolded plane: their corners divide by the tile size.
    const auto cell_of = [&](int64_t pixel) {
      return pixel >= 0 ? pixel / tile_size : -((-pixel - 1) / tile_size) - 1;
    };
    const MosaicBox box{face, cell_of(col0), cell_of(row0),
                        std::max(col1 - col0, row1 - row0) / tile_size + 1};
    // A refined step's output mosaic is the largest (with the operator's halo).
    if (const int64_t side = (box.cells * tile_size + 2 * step.op->spec().halo) << step.refine;
        side > kMaxMosaicSide)
      throw Error(step.label() + ": the region's mosaic would be " + std::to_string(side) + " x " +
                  std::to_string(side) + " samples, above the limit of " +
                  std::to_string(kMaxMosaicSide) + " x " + std::to_string(kMaxMosaicSide));
    return box;
  }

  const Pipeline& pipeline_;
  const Store* store_;
  int threads_;
  std::map<std::string, Produced> produced_;
  std::set<std::string> artifacts_;  // written by the steps planned so far
  std::set<std::string> written_;    // features layers and artifacts written by tasks
};

}  // namespace

TaskContext task_context(const Pipeline& pipeline, const PipelineStep& step) {
  TaskContext ctx;
  ctx.store_path = pipeline.store_path;
  ctx.base_dir = pipeline.base_dir;
  ctx.params = &step.params;
  ctx.outputs = &step.outputs;
  return ctx;
}

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
    if (spec.kind == OperatorKind::Task && sp.outputs.empty()) {  // export: writes files only
      out << sp.step->label() << ": task, writes no layer\n";
      continue;
    }
    out << sp.step->label() << ": " << operator_kind_name(spec.kind) << " operator, "
        << sp.cells.size() << " cells at level " << sp.level
        << (sp.step->refine > 0 ? ", outputs refined " + std::to_string(sp.step->refine) +
                                      (sp.step->refine == 1 ? " level" : " levels")
                                : std::string())
        << "\n";
    for (const auto& [port, layer] : sp.inputs)
      out << "  reads  " << layer.name << " (" << port << ")\n";
    for (const FeaturePort& f : sp.features)
      out << "  reads  " << f.layer << " (" << f.port << ": features within " << f.reach_m
          << " m)\n";
    for (const auto& [port, layer] : sp.outputs)
      if (layer.kind == LayerKind::Raster)
        out << "  writes " << layer.name << " (" << port << ": " << dtype_name(layer.dtype) << " x"
            << layer.channels << ", " << sp.cells.size() << " tiles of " << layer.tile_size
            << "px)\n";
      else
        out << "  writes " << layer.name << " (" << port << ": " << layer_kind_name(layer.kind)
            << " content of up to " << sp.cells.size() << " cells)\n";
    if (!sp.artifact.empty()) out << "  writes artifact " << sp.artifact << "\n";
  }
}

}  // namespace maquette
