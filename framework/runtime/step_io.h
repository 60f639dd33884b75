// The store access of one running step, from any thread: reading input tiles as float with the
// operator's halo, and writing each cell's output tiles and content together with its run record
// in one batch, so a killed run leaves no cell half-written (and relayed to the other ranks'
// copies of the store under --store-copies, write_relay.h). The store is the single writer:
// batches are encoded in the calling thread and committed one at a time under its write mutex.
// Input tiles read for a halo go through a TileCache of at most kTileCacheBytes of decoded tiles
// (and at least 4 tiles), so each is decoded about once per step.
//
// A cell step's cells that share a parent are written in one batch (group_siblings), which
// builds the parent's overview from their tiles in memory (Store::Batch): the threads and ranks
// computing the cells build the finest overview level, and update_overviews only the coarser
// ones, from the stored overviews rather than from every tile decoded again. A group's tiles are
// encoded under the group's lock (rarely contended: siblings are computed by one thread unless a
// chunk boundary or a steal splits them).
#pragma once

#include <atomic>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <span>
#include <string>

#include "runtime/content_output.h"
#include "runtime/operator.h"
#include "runtime/run_plan.h"
#include "runtime/tile_cache.h"
#include "runtime/write_relay.h"
#include "store/store.h"

namespace maquette {

using TileSet = std::map<std::string, Tile<float>>;  // by port name

struct CellOutput {
  CellId cell;
  const TileSet* tiles;                   // the raster outputs
  std::vector<ContentBlob> content = {};  // encode_content's blobs
};

inline constexpr size_t kTileCacheBytes = size_t(256) << 20;

class StepIO {
 public:
  // `relay` (--store-copies): every batch is also passed to it, for the other ranks.
  StepIO(Store& store, const StepPlan& plan, int64_t run_id, WriteRelay* relay = nullptr);

  // The tile of `layer` at `cell` as float (nodata -> NaN), or nullopt.
  std::optional<Tile<float>> read(const LayerInfo& layer, CellId cell) const;
  // The step's input tiles at `cell` with `halo` pixels, the features of its features ports
  // within their reach of the cell (their indexes read: StepPlan::features), and output tiles for
  // mapped outputs: NaN, or uninitialized for an operator that writes every sample
  // (OperatorSpec::writes_all_samples).
  CellData load(CellId cell, int halo);
  // The run's store, for operators to read (CellContext::store, StepContext::store).
  const Store& store() const { return store_; }
  // Tiles read and decoded so far (for tests of the cache).
  int64_t decoded() const { return decoded_; }
  // NaN tiles for the step's mapped outputs, of `size` pixels (0: of their layers' tile size).
  TileSet blank_outputs(int size = 0) const;
  // Uninitialized tiles for the step's mapped outputs, of their layers' tile size.
  TileSet uninitialized_outputs() const;
  // Empty content for the step's mapped content outputs, the origin at the cell's centre.
  CellContent blank_content(CellId cell) const;
  // The cell's content checked and encoded (content_output.h), for write().
  std::vector<ContentBlob> encode_content(CellId cell, const CellContent& content) const;

  // One batch: the output tiles and content of all `cells` and their run records. A mapped
  // content output without a blob (the operator left it empty) removes the cell's content there.
  // A single cell of a group (group_siblings) waits in its group's batch until the group's other
  // cells are written; the last one commits the batch.
  void write(std::span<const CellOutput> cells);
  // `cells` (sorted, distinct) are the cells this process writes one at a time in the step: those
  // sharing a parent form a group, written in one batch. Call before any write.
  void group_siblings(std::span<const CellId> cells);
  // Commits the groups some of whose cells were not written (one failed): the cells that were.
  void flush();
  // One batch: the run records of all `cells` (a task's, a reduce's with its artifact).
  void write_done(std::span<const CellId> cells, const Artifact* artifact = nullptr);

 private:
  // The batch of the cells sharing a parent, once all `expected` of them are written.
  struct Group {
    std::mutex mutex;
    int expected = 0, written = 0;
    std::unique_ptr<Store::Batch> batch;
  };

  void add(Store::Batch& batch, std::span<const CellOutput> cells) const;
  void commit(Store::Batch& batch);

  Store& store_;
  const StepPlan& plan_;
  int64_t run_id_;
  WriteRelay* relay_;
  std::set<std::string> models_;    // the store's model layers: instances' prototypes
  std::map<CellId, Group> groups_;  // by parent; fixed by group_siblings
  TileCache cache_;
  mutable std::atomic<int64_t> decoded_{0};
};

}  // namespace maquette
