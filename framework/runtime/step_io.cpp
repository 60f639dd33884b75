#include "runtime/step_io.h"

#include <cmath>

#include "core/error.h"
#include "core/halo.h"

namespace maquette {

namespace {
const double* nodata_ptr(const LayerInfo& layer) { return layer.nodata ? &*layer.nodata : nullptr; }
}  // namespace

StepIO::StepIO(Store& store, const StepPlan& plan, int64_t run_id)
    : store_(store), plan_(plan), run_id_(run_id) {}

std::optional<Tile<float>> StepIO::read(const LayerInfo& layer, CellId cell) const {
  const std::optional<RawTile> raw = store_.get_tile(layer.name, cell);
  if (!raw) return std::nullopt;
  return to_tile<float>(*raw, nodata_ptr(layer));
}

CellData StepIO::load(CellId cell, int halo) const {
  CellData data;
  for (const auto& [port, layer] : plan_.inputs) {
    data.inputs[port] = assemble_halo(default_grid(), cell, plan_.tile_size, halo,
                                      [&](CellId c) { return read(layer, c); });
  }
  data.outputs = blank_outputs(plan_.tile_size);
  return data;
}

TileSet StepIO::blank_outputs(int size) const {
  TileSet tiles;
  for (const auto& [port, layer] : plan_.outputs)
    tiles.emplace(port, Tile<float>(size, layer.channels, 0, NAN));
  return tiles;
}

void StepIO::write(std::span<const CellOutput> cells) {
  Store::Batch batch(store_);
  for (const auto& [cell, tiles] : cells) {
    for (const auto& [port, layer] : plan_.outputs) {
      const Tile<float>& tile = tiles->at(port);
      if (tile.size() != layer.tile_size || tile.channels() != layer.channels || tile.halo() != 0)
        throw Error("output '" + port + "' is not a " + std::to_string(layer.tile_size) +
                    "-pixel tile of " + std::to_string(layer.channels) + " channel(s)");
      batch.put_tile(layer.name, cell, from_tile(tile, layer.dtype, nodata_ptr(layer)));
    }
    batch.mark_done(run_id_, plan_.step->index, cell);
  }
  batch.commit();
}

void StepIO::write_artifact(const Artifact& artifact, std::span<const CellId> cells) {
  Store::Batch batch(store_);
  batch.put_artifact(artifact);
  for (const CellId cell : cells) batch.mark_done(run_id_, plan_.step->index, cell);
  batch.commit();
}

}  // namespace maquette
