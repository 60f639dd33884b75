// The store access of one running step, from any thread: reading input tiles as float with the
// operator's halo, and writing each cell's output tiles together with its run record in one
// batch, so a killed run leaves no cell half-written. The store is the single writer: batches are
// encoded in the calling thread and committed one at a time under its write mutex.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <string>

#include "runtime/operator.h"
#include "runtime/run_plan.h"
#include "store/store.h"

namespace maquette {

using TileSet = std::map<std::string, Tile<float>>;  // by port name

struct CellOutput {
  CellId cell;
  const TileSet* tiles;
};

class StepIO {
 public:
  StepIO(Store& store, const StepPlan& plan, int64_t run_id);

  // The tile of `layer` at `cell` as float (nodata -> NaN), or nullopt.
  std::optional<Tile<float>> read(const LayerInfo& layer, CellId cell) const;
  // The step's input tiles at `cell` with `halo` pixels, and NaN output tiles for mapped outputs.
  CellData load(CellId cell, int halo) const;
  // NaN tiles of `size` pixels for the step's mapped outputs.
  TileSet blank_outputs(int size) const;

  // One batch: the output tiles of all `cells` and their run records.
  void write(std::span<const CellOutput> cells);
  // One batch: the artifact and the run records of all `cells`.
  void write_artifact(const Artifact& artifact, std::span<const CellId> cells);

 private:
  Store& store_;
  const StepPlan& plan_;
  int64_t run_id_;
};

}  // namespace maquette
