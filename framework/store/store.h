// Store: one SQLite file per dataset. Layers, tiles keyed by (layer, cell id) in a WITHOUT ROWID
// table (so a range of cell ids is one index range scan), overview tiles, artifacts and run
// records. Tile blobs are compressed by the layer's codec (core: "zstd" with byte shuffling).
// Every write is one transaction; a process killed at any moment leaves a store that opens
// and passes PRAGMA integrity_check. A Store may be used from many threads at once: reads use
// a pool of read-only connections and run in parallel; commits are serialised. Layers of kind
// mesh, instances and volume hold 3D content, one blob per cell (content/content_blob.h); a layer
// of kind model holds one model (a mesh content blob in the model's own frame). See
// framework/store/README.md for the schema and blob encoding.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "content/content.h"
#include "core/cell_id.h"
#include "core/tile.h"

namespace maquette {

enum class LayerKind { Raster, Mesh, Volume, Features, Artifact, Instances, Model };
enum class Semantics { Continuous, Categorical };

std::string_view layer_kind_name(LayerKind k);
LayerKind parse_layer_kind(std::string_view name);  // throws maquette::Error
std::string_view semantics_name(Semantics s);
Semantics parse_semantics(std::string_view name);  // throws maquette::Error
// The content a layer of this kind holds in its cells (mesh, instances, volume), or nothing
// (raster, features, artifact, and model: one blob that is in no cell).
std::optional<ContentKind> layer_content_kind(LayerKind k);

// A layer's definition. Content layers (kinds mesh, instances, volume) are defined by name, kind
// and level only: the store keeps dtype uint8, 1 channel, tile size 1, no nodata, continuous,
// no units and codec "mqct" for them, whatever is asked (so a definition asked again with other
// raster fields is the same layer).
// Model layers (kind model) are defined by their name alone, like content layers (level 0).
struct LayerInfo {
  std::string name;
  LayerKind kind = LayerKind::Raster;
  DType dtype = DType::F32;
  int channels = 1;
  int tile_size = 256;
  int level = 0;  // level of the cells holding full-resolution tiles
  std::optional<double> nodata;
  Semantics semantics = Semantics::Continuous;
  std::string units;
  std::string codec = "zstd";  // "zstd" (byte-shuffled), "zstd:LEVEL", "raw", "normal_oct[:LEVEL]"
  nlohmann::json provenance = nlohmann::json::object();  // free-form: source, operator, params
};

struct LayerStats {
  int64_t tile_count = 0;             // full-resolution tiles; features layers: cells indexed
  int64_t feature_count = 0;          // features layers: features stored
  int64_t bytes = 0;                  // compressed blob bytes, overview tiles included
  std::vector<int> levels;            // levels holding tiles (overviews, then base), ascending
  std::optional<CellId> first, last;  // first and last full-resolution tile (or indexed cell)
};

// Store::model_stats: from the blob's envelope header and its GLB's JSON chunk (no Draco).
struct ModelStats {
  ContentStats content;   // objects and triangles
  int64_t materials = 0;  // the GLB's materials
  int64_t bytes = 0;      // of the blob
};

// Store::content_stats: read from the blobs' headers, without decoding a payload.
struct ContentLayerStats {
  // Summed over the cells at the layer's level (coarser levels hold simplified copies of the
  // same objects).
  ContentStats content;
  int64_t cells = 0;  // cells holding content at the layer's level
  int64_t bytes = 0;  // blob bytes, coarser levels included
};

// A vector feature of a `features` layer: stored once, indexed in every cell it touches.
struct Feature {
  int64_t fid = 0;                                       // unique within the layer
  std::vector<std::byte> wkb;                            // geometry, WKB in WGS84 lon/lat
  nlohmann::json attributes = nlohmann::json::object();  // typed values by field name
  std::array<double, 4> bbox{};                          // west, south, east, north (degrees)
};

struct Artifact {
  std::string name;
  std::string media_type = "application/json";
  std::vector<std::byte> data;
  nlohmann::json metadata = nlohmann::json::object();

  // An artifact whose data is `text` (e.g. a JSON document's dump), and the text of one.
  static Artifact FromText(std::string name, std::string_view text,
                           nlohmann::json metadata = nlohmann::json::object());
  std::string_view text() const {
    return {reinterpret_cast<const char*>(data.data()), data.size()};
  }
};

class Store {
 public:
  // ReadOnly, ReadWrite: an existing store. Create: creates the file if absent.
  // CreateBulk: like Create, and a store this open creates is filled in bulk until it is
  // closed: commits go through a rollback journal without syncs instead of the WAL, so each
  // new page is written once rather than twice (WAL, then checkpoint), ~12 % of a first ingest.
  // The close syncs the file and switches it to WAL like every store. Until then a killed
  // process still leaves a valid store (its journal rolls the open transaction back when the
  // store is next read), but a power cut may leave it damaged; a commit waits for the reads
  // of every connection, so a thread must not commit while it holds a read open (a scan's
  // visitor must not write); and another process opening the store for writing switches it to
  // WAL, after which it is written as usual. Meant for one writer filling a new store (ingest).
  enum class Mode { ReadOnly, ReadWrite, Create, CreateBulk };

  // Throws maquette::Error naming the path: missing file, not a Maquette store (or a newer
  // schema), read-only file opened for writing. A store on a read-only file system is read as
  // immutable (SQLite cannot make its -shm file there).
  static std::unique_ptr<Store> open(const std::string& path, Mode mode);
  // Throws maquette::Error saying why a store cannot be written (or created) at `path`: a
  // read-only file system, a file without write permission, a directory that is not writable.
  // Store::open checks it for every mode but ReadOnly; a command checks it before its work.
  static void check_writable(const std::string& path);
  ~Store();
  Store(const Store&) = delete;
  Store& operator=(const Store&) = delete;

  const std::string& path() const;
  bool read_only() const;
  // True when this open made the file (Mode::Create or CreateBulk on a path where no store was,
  // and no other process linked one there first): only then may a caller that gives up remove
  // it.
  bool created() const;

  // Layers. create_layer fails if the name exists with a different definition, and is a no-op
  // when it exists with the same one (so re-running a step is idempotent) but for its
  // provenance, which `info`'s replaces; an existing layer keeps its codec, whatever `info` asks
  // (older stores resume).
  void create_layer(const LayerInfo& info);
  // Throws what create_layer would when `info` is no valid definition or names a stored layer of
  // another definition; writes nothing: a run checks every output against its store before it
  // writes any (plan_run).
  void check_layer(const LayerInfo& info) const;
  std::optional<LayerInfo> layer(const std::string& name) const;
  // For readers: throws "unknown layer 'x' in STORE", and for a layer marked incomplete (below)
  // "layer 'x' in STORE is incomplete: ...", naming the run and how to finish it.
  LayerInfo require_layer(const std::string& name) const;
  std::vector<LayerInfo> layers() const;
  LayerStats stats(const std::string& layer) const;

  // Tiles (full-resolution tiles at the layer's level) of raster layers.
  std::optional<RawTile> get_tile(const std::string& layer, CellId cell) const;
  bool has_tile(const std::string& layer, CellId cell) const;
  // Cells holding tiles with ids in [first, last], ascending (pass a cell's range_min/max).
  std::vector<CellId> tile_cells(const std::string& layer, CellId first, CellId last) const;
  std::vector<CellId> tile_cells(const std::string& layer) const;
  void scan(const std::string& layer, CellId first, CellId last,
            const std::function<void(CellId, const RawTile&)>& visit) const;

  // A batch of writes committed atomically (one SQLite transaction). Use one per cell or per
  // group of cells; nothing is visible to readers or survives a crash until commit().
  // Writes are checked and encoded when made (in the calling thread, so batches of several
  // threads compress in parallel) and applied by commit() in one BEGIN IMMEDIATE transaction.
  // A batch that writes all four children of a parent also writes the parent's overview (built
  // from them in memory) rather than marking it stale; it keeps a copy of each tile whose
  // siblings it has not all seen, so memory grows with the tiles a batch holds.
  class Batch {
   public:
    explicit Batch(Store& store);  // throws if the store is read-only
    ~Batch();                      // rolls back (discards the writes) if not committed
    Batch(const Batch&) = delete;
    Batch& operator=(const Batch&) = delete;
    void put_tile(const std::string& layer, CellId cell, const RawTile& tile);
    // For a writer that puts every tile it writes under `parent` in this batch: builds the
    // parent's overview from them now (in this thread), and commit() writes it if the store then
    // holds no other child of `parent` (the same bytes update_overviews would build; otherwise
    // the parent stays stale for it). A batch holding all four children does this by itself.
    void put_parent_overview(const std::string& layer, CellId parent);
    void put_artifact(const Artifact& artifact);
    // Writes (or replaces) a feature of a features layer and indexes it in `cells`, which must
    // be at the layer's level; a replaced feature loses its old index entries.
    void put_feature(const std::string& layer, const Feature& feature,
                     std::span<const CellId> cells);
    // Writes (or replaces) the content of `cell` in a layer of kind mesh, instances or volume:
    // its objects at the layer's level, or their simplified copy at a coarser level. `blob` is
    // an envelope (content/content_blob.h) of the layer's content kind; throws maquette::Error
    // naming the layer and cell for another kind, a corrupt envelope, a cell finer than the
    // layer's level, or a layer that is not a content layer. The payload is not decoded.
    void put_content(const std::string& layer, CellId cell, std::string_view blob);
    // Removes the content of `cell` (at the layer's level or coarser) if it has any, marking its
    // parent stale as put_content does (a writer whose cell came out empty on a re-run). Throws
    // as put_content for a layer that is not a content layer or a cell finer than its level.
    void remove_content(const std::string& layer, CellId cell);
    // Writes (or replaces) the model `name`: creates the model layer if absent (with
    // `provenance`; a replaced model's layer takes the new one), all in commit()'s transaction.
    // `blob` is a mesh content envelope (content/content_blob.h) whose payload is a mesh GLB in
    // the model's frame (metres, x east, y north, z up, base at z = 0) and whose origin is zero.
    // Throws maquette::Error naming the model for a layer of that name of another kind, a
    // corrupt envelope, another content kind or a non-zero origin. The payload is not decoded.
    void put_model(const std::string& name, std::string_view blob,
                   const nlohmann::json& provenance = nlohmann::json::object());
    void mark_done(int64_t run_id, int step, CellId cell);  // run record progress
    // Progress of work not keyed by cells (e.g. a batch of features), in the same records.
    void mark_done(int64_t run_id, int step, int64_t key);
    void commit();

    // The batch's writes as bytes, for another process to add to a batch on its own copy of
    // the store (add_serialized; `maquette run --store-copies`): tiles and overviews as encoded
    // (not compressed again), content, artifacts and run records, layers by name rather than by
    // their row ids in this file. Tiles kept only to build a parent's overview with siblings
    // still to come are not passed on: the parent stays stale there, as here after commit().
    // Throws maquette::Error for a batch holding features or models, which it does not carry.
    std::string serialize() const;
    // Adds the writes of a batch's serialize() to this one, each layer looked up by name in this
    // store; throws maquette::Error naming the layer (and cell) for a layer this store lacks or
    // holds of another kind or level, and for bytes that are no serialized batch.
    void add_serialized(std::string_view bytes);

   private:
    struct Pending;
    Store& store_;
    bool open_ = true;
    std::unique_ptr<Pending> pending_;
  };
  void put_tile(const std::string& layer, CellId cell, const RawTile& tile);  // own transaction

  // Features layers. features_in: the features indexed in cells with ids in [first, last]
  // (pass a cell's range_min/max), each once, ordered by fid.
  std::vector<Feature> features_in(const std::string& layer, CellId first, CellId last) const;
  std::vector<CellId> feature_cells(const std::string& layer, int64_t fid) const;  // ascending
  int64_t feature_count(const std::string& layer) const;

  // Content layers (kinds mesh, instances, volume; Batch::put_content). get_content gives the
  // blob of `cell`, at the layer's level or a coarser one, its envelope checked (throws naming
  // layer and cell when corrupt); content_cells the cells holding content at `level` (default:
  // the layer's) with ids in [first, last], ascending. Throws for a layer of another kind.
  std::optional<std::string> get_content(const std::string& layer, CellId cell) const;
  std::vector<CellId> content_cells(const std::string& layer, int level, CellId first,
                                    CellId last) const;
  std::vector<CellId> content_cells(const std::string& layer, int level) const;
  std::vector<CellId> content_cells(const std::string& layer) const;
  ContentLayerStats content_stats(const std::string& layer) const;

  // Content overviews (built by content/content_overviews.h): writing a content layer's cell at
  // its level marks the parent stale, as tiles do. rebuild_stale_content takes up to `limit`
  // stale cells at `level` (ascending ids) and, in one write transaction, gives `build` each
  // cell with the stored blobs of its four children (by child digit, one level finer); `build`
  // fills `overviews` (one per cell, in parallel if it likes, without touching the store), and each
  // cell's overview is written (or removed, when nullopt: its children hold nothing), its mark
  // cleared and its parent marked stale. Returns the number of cells taken: fewer than `limit` when
  // the level has no marks left. Throws naming the layer for a layer that is not a content layer, a
  // level not below the layer's, or a blob of another kind than the layer's.
  using ContentChildren = std::array<std::optional<std::string>, 4>;
  using BuildContentOverviews =
      std::function<void(std::span<const CellId> cells, std::span<const ContentChildren> children,
                         std::span<std::optional<std::string>> overviews)>;
  size_t rebuild_stale_content(const std::string& layer, int level, size_t limit,
                               const BuildContentOverviews& build);

  // Model layers (Batch::put_model). get_model: the model's blob, its envelope checked; nothing
  // when the store has no layer of that name. Throws naming the model for a layer of another
  // kind or a corrupt blob.
  std::optional<std::string> get_model(const std::string& name) const;
  ModelStats model_stats(const std::string& name) const;  // throws as get_model, and if absent

  // Overviews: coarser levels down to `min_level`, mean (continuous) or mode (categorical),
  // nodata-aware. Built on demand; tiles written since mark their ancestors stale, and
  // update_overviews rebuilds only those.
  void update_overviews(const std::string& layer, int min_level = 0);
  std::optional<RawTile> get_overview(const std::string& layer, CellId cell) const;

  // Artifacts: fitted models, statistics, run reports.
  void put_artifact(const Artifact& artifact);
  std::optional<Artifact> get_artifact(const std::string& name) const;
  std::vector<std::string> artifact_names() const;

  // Run records: a run is a pipeline (JSON) being executed; steps record per-cell progress
  // so that --resume skips what is done.
  int64_t begin_run(const nlohmann::json& pipeline);
  std::optional<int64_t> latest_unfinished_run(const nlohmann::json& pipeline) const;
  std::vector<CellId> done_cells(int64_t run_id, int step) const;
  std::vector<int64_t> done_keys(int64_t run_id, int step) const;  // ascending
  void finish_run(int64_t run_id, const std::string& status);      // "ok" | "failed: ..."

  // Incomplete layers: a writer marks a layer before it writes its first tile and clears the
  // mark when the layer is whole, so that a command that fails or is killed midway leaves the
  // layer marked until a later run (`--resume`) finishes it; require_layer refuses it meanwhile.
  // finish_run(id, "ok") clears the marks of that run.
  void mark_incomplete(const std::string& layer, int64_t run_id);
  void mark_complete(const std::string& layer);
  // Why the layer is incomplete ("run 3 failed: ...", "run 3 is running or was interrupted"),
  // or nothing when it is complete (or unknown).
  std::optional<std::string> incomplete(const std::string& layer) const;
  // The run whose mark the layer holds, or nothing when it is complete (or unknown).
  std::optional<int64_t> incomplete_run(const std::string& layer) const;
  // Undoes a failed write: removes the layer with its tiles, overviews and features, and the run
  // with its records, in one transaction (for a command that created the layer it failed to fill).
  void drop_layer(const std::string& layer, int64_t run_id);

  int64_t file_size() const;
  bool integrity_ok() const;  // PRAGMA integrity_check == "ok"

 private:
  struct Impl;
  explicit Store(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace maquette
