#include "runtime/step_io.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/halo.h"

namespace maquette {

namespace {
const double* nodata_ptr(const LayerInfo& layer) { return layer.nodata ? &*layer.nodata : nullptr; }

// The cache's capacity in tiles: kTileCacheBytes of the step's largest decoded input tiles.
size_t cache_capacity(const StepPlan& plan) {
  size_t tile_bytes = 1;
  for (const auto& [port, layer] : plan.inputs)
    tile_bytes = std::max(tile_bytes, size_t(layer.tile_size) * size_t(layer.tile_size) *
                                          size_t(layer.channels) * sizeof(float));
  return std::max<size_t>(4, kTileCacheBytes / tile_bytes);
}

}  // namespace

StepIO::StepIO(Store& store, const StepPlan& plan, int64_t run_id, WriteRelay* relay)
    : store_(store), plan_(plan), run_id_(run_id), relay_(relay), cache_(cache_capacity(plan)) {
  for (const LayerInfo& layer : store.layers())
    if (layer.kind == LayerKind::Model) models_.insert(layer.name);
}

std::optional<Tile<float>> StepIO::read(const LayerInfo& layer, CellId cell) const {
  const std::optional<RawTile> raw = store_.get_tile(layer.name, cell);
  if (!raw) return std::nullopt;
  ++decoded_;
  return to_tile<float>(*raw, nodata_ptr(layer));
}

CellData StepIO::load(CellId cell, int halo) {
  CellData data;
  for (const auto& [port, layer] : plan_.inputs) {
    // Without a halo each tile is read once: caching it would only evict useful tiles.
    // (&layer = layer: clang 14, the fuzz build's compiler, cannot capture a structured binding)
    auto fetch = [&, &layer = layer](CellId c) -> std::optional<Tile<float>> {
      if (halo == 0) return read(layer, c);
      return *cache_.get(layer.name, c, [&] { return read(layer, c); });
    };
    data.inputs[port] = assemble_halo(default_grid(), cell, plan_.tile_size, halo, fetch);
  }
  if (!plan_.features.empty()) {
    const CellOutline outline(default_grid(), cell);
    for (const FeaturePort& f : plan_.features)
      data.features[f.port] = f.index->within(outline, f.reach_m);
  }
  data.outputs =
      plan_.step->op->spec().writes_all_samples ? uninitialized_outputs() : blank_outputs();
  data.content = blank_content(cell);
  return data;
}

TileSet StepIO::blank_outputs(int size) const {
  TileSet tiles;
  for (const auto& [port, layer] : plan_.outputs)
    if (layer.kind == LayerKind::Raster)
      tiles.emplace(port, Tile<float>(size > 0 ? size : layer.tile_size, layer.channels, 0, NAN));
  return tiles;
}

TileSet StepIO::uninitialized_outputs() const {
  TileSet tiles;
  for (const auto& [port, layer] : plan_.outputs)
    if (layer.kind == LayerKind::Raster)
      tiles.emplace(port, Tile<float>::uninitialized(layer.tile_size, layer.channels));
  return tiles;
}

CellContent StepIO::blank_content(CellId cell) const {
  CellContent content;
  const LonLat centre = default_grid().centre(cell);
  const EnuOrigin origin{centre.lon, centre.lat, 0};
  for (const auto& [port, layer] : plan_.outputs) {
    if (layer.kind == LayerKind::Mesh) content.meshes[port].origin = origin;
    if (layer.kind == LayerKind::Instances) content.instances[port].origin = origin;
    if (layer.kind == LayerKind::Volume) content.volumes[port].origin = origin;
  }
  return content;
}

std::vector<ContentBlob> StepIO::encode_content(CellId cell, const CellContent& content) const {
  // The operator may have added ports to the maps: each must be a mapped output of that kind.
  const auto check = [&](const auto& by_port, LayerKind kind) {
    for (const auto& entry : by_port) {
      const auto it = plan_.outputs.find(entry.first);
      if (it == plan_.outputs.end() || it->second.kind != kind)
        throw Error("outputs." + entry.first + ": not a mapped " +
                    std::string(layer_kind_name(kind)) + " output of the step");
    }
  };
  check(content.meshes, LayerKind::Mesh);
  check(content.instances, LayerKind::Instances);
  check(content.volumes, LayerKind::Volume);
  return encode_cell_content(content, cell, default_grid(), models_);
}

void StepIO::group_siblings(std::span<const CellId> cells) {
  for (const CellId cell : cells)
    if (cell.level() > 0) ++groups_[cell.parent()].expected;
}

void StepIO::write(std::span<const CellOutput> cells) {
  const auto group = cells.size() == 1 && cells.front().cell.level() > 0
                         ? groups_.find(cells.front().cell.parent())
                         : groups_.end();
  if (group == groups_.end()) {
    Store::Batch batch(store_);
    add(batch, cells);
    return commit(batch);
  }
  Group& g = group->second;
  std::unique_ptr<Store::Batch> full;
  {
    std::lock_guard lock(g.mutex);
    if (!g.batch) g.batch = std::make_unique<Store::Batch>(store_);
    try {
      add(*g.batch, cells);
    } catch (...) {
      g.batch.reset();  // no cell half-written: the group's others are computed again on resume
      throw;
    }
    if (++g.written == g.expected) full = std::move(g.batch);
  }
  if (full) commit(*full);
}

void StepIO::flush() {
  for (auto& [parent, g] : groups_) {
    std::lock_guard lock(g.mutex);
    if (const std::unique_ptr<Store::Batch> held = std::move(g.batch)) commit(*held);
  }
}

void StepIO::add(Store::Batch& batch, std::span<const CellOutput> cells) const {
  for (const auto& [cell, tiles, content] : cells) {
    for (const auto& [port, layer] : plan_.outputs) {
      if (layer.kind != LayerKind::Raster) continue;
      const Tile<float>& tile = tiles->at(port);
      if (tile.size() != layer.tile_size || tile.channels() != layer.channels || tile.halo() != 0)
        throw Error("output '" + port + "' is not a " + std::to_string(layer.tile_size) +
                    "-pixel tile of " + std::to_string(layer.channels) + " channel(s)");
      batch.put_tile(layer.name, cell, from_tile(tile, layer.dtype, nodata_ptr(layer)));
    }
    for (const auto& [port, layer] : plan_.outputs) {
      if (!layer_content_kind(layer.kind)) continue;
      // A port the operator left empty removes what an earlier run wrote there.
      const auto blob = std::ranges::find(content, port, &ContentBlob::port);
      if (blob == content.end())
        batch.remove_content(layer.name, cell);
      else
        batch.put_content(layer.name, cell, blob->blob);
    }
    batch.mark_done(run_id_, plan_.step->index, cell);
  }
}

void StepIO::write_done(std::span<const CellId> cells, const Artifact* artifact) {
  Store::Batch batch(store_);
  if (artifact != nullptr) batch.put_artifact(*artifact);
  for (const CellId cell : cells) batch.mark_done(run_id_, plan_.step->index, cell);
  commit(batch);
}

void StepIO::commit(Store::Batch& batch) {
  if (!relay_ || !relay_->relays()) return batch.commit();
  std::string bytes = batch.serialize();
  if (relay_->commits_here()) batch.commit();
  relay_->relay(std::move(bytes));
}

}  // namespace maquette
