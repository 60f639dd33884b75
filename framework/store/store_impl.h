// Store internals shared by store.cpp, batch.cpp, overviews.cpp and runs.cpp.
//
// Concurrency: one writer connection, used under `write_mutex` for the few statements of a
// transaction, and a pool of read-only connections, each borrowed by one thread at a time.
// In WAL mode readers see the last committed state and never wait for the writer, so reads
// run in parallel (and decode outside any lock) while another thread commits.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "store/checkpointer.h"
#include "store/sqlite.h"
#include "store/store.h"

namespace maquette {

// A layer as the store resolves it: the row id used in tile keys, and its definition.
struct LayerEntry {
  int64_t id = 0;
  LayerInfo info;
};

class ReadPool {
 public:
  // A borrowed connection, returned to the pool when the lease ends.
  class Lease {
   public:
    Lease(ReadPool& pool, std::unique_ptr<sqlite::Connection> conn)
        : pool_(pool), conn_(std::move(conn)) {}
    ~Lease() { pool_.give_back(std::move(conn_)); }
    Lease(const Lease&) = delete;
    Lease& operator=(const Lease&) = delete;
    sqlite::Connection* operator->() { return conn_.get(); }
    sqlite::Connection& operator*() { return *conn_; }

   private:
    ReadPool& pool_;
    std::unique_ptr<sqlite::Connection> conn_;
  };

  explicit ReadPool(std::string path) : path_(std::move(path)) {}
  Lease borrow();
  // From now on, connections read the file as immutable (a store on a read-only file system,
  // whose -shm file SQLite cannot create); idle connections are closed.
  void read_immutable();

 private:
  void give_back(std::unique_ptr<sqlite::Connection> conn);

  std::string path_;
  bool immutable_ = false;
  std::mutex mutex_;
  std::vector<std::unique_ptr<sqlite::Connection>> idle_;
};

struct Store::Impl {
  Impl(std::string path, bool read_only) : path(path), read_only(read_only), readers(path) {}

  // Layer lookup (cached: layers are never dropped or redefined). Throws for unknown names.
  LayerEntry require(const std::string& name) const;
  std::optional<LayerEntry> find(const std::string& name) const;
  // require(), for readers of raster tiles: throws for a content layer, whose blobs are no tiles.
  LayerEntry require_tiles(const std::string& name) const;

  // Throws unless the store was opened for writing.
  void require_writable() const;
  // Runs f(writer) in one BEGIN IMMEDIATE transaction under the write mutex.
  template <typename F>
  void write(F&& f) {
    require_writable();
    {
      std::lock_guard lock(write_mutex);
      writer->transaction([&] { f(*writer); });
    }
    if (bulk) checkpointer->committed();  // outside the lock: it may stat the file
  }

  // Overview tiles built by update_overviews at one level, with their blobs, by cell id: the
  // next level up takes a child from here instead of decoding it when the stored blob is this
  // one (overviews.cpp).
  using BuiltOverviews = std::map<uint64_t, std::pair<std::vector<std::byte>, RawTile>>;
  // Rebuilds up to `limit` stale overview tiles at `level` in the writer's transaction, their
  // children taken from `below` where it holds them; adds what it built to `built` (up to 64
  // tiles); returns how many it rebuilt: fewer than `limit` when the level is done
  // (overviews.cpp).
  size_t rebuild_stale(sqlite::Connection& writer, const LayerEntry& layer, int level, size_t limit,
                       const BuiltOverviews& below, BuiltOverviews& built);

  // Decodes a stored blob and checks it against the layer; throws naming layer and cell.
  RawTile decode(std::span<const std::byte> blob, const LayerEntry& layer, CellId cell) const;

  const std::string path;
  const bool read_only;
  bool created = false;  // this open made the file (Store::created)
  bool bulk = false;     // filled in bulk until closed (Mode::CreateBulk on a new file)
  std::unique_ptr<sqlite::Connection> writer;  // null when read-only
  // Declared after `writer`, so destroyed before it: the writer's close checkpoints what is left.
  std::unique_ptr<Checkpointer> checkpointer;  // with the writer (Rollback when `bulk`)
  std::mutex write_mutex;
  mutable ReadPool readers;
  mutable std::mutex layers_mutex;
  mutable std::map<std::string, LayerEntry, std::less<>> layers;
};

// Layer definitions (layer_info.cpp).
// The codec recorded for content layers: their blobs are content envelopes (content_blob.h).
inline constexpr const char* kContentCodec = "mqct";
// Checks a definition (throws maquette::Error naming the field) and drops a NaN nodata of a
// float layer (NaN is always missing there).
LayerInfo normalized_layer(const LayerInfo& info);
// The first field where two definitions differ, as "dtype float32 vs uint16"; empty if none.
// Provenance and codec are not part of the definition (an existing layer keeps its codec).
std::string layer_difference(const LayerInfo& a, const LayerInfo& b);
// Layers whose blobs are content envelopes rather than raster tiles: content layers (by cell)
// and model layers (one blob).
inline bool holds_content(LayerKind k) { return layer_content_kind(k) || k == LayerKind::Model; }

// Layer rows (layers.cpp), inside the caller's transaction: the layer named `name` if any; a new
// layer of a normalized definition (returns its id); a layer's provenance replaced.
std::optional<LayerEntry> load_layer(sqlite::Connection& conn, const std::string& name);
int64_t insert_layer(sqlite::Connection& conn, const LayerInfo& definition);
void update_provenance(sqlite::Connection& conn, const LayerEntry& layer,
                       const nlohmann::json& provenance);

// A feature checked against its layer and ready to write (features.cpp).
struct FeatureWrite {
  int64_t layer = 0;
  Feature feature;
  std::vector<CellId> cells;  // sorted, unique
};
// Throws maquette::Error naming the layer and fid unless the layer holds features and the cells
// are valid cells at its level.
FeatureWrite feature_write(const LayerEntry& layer, const std::string& store_path,
                           const Feature& feature, std::span<const CellId> cells);
// Writes (or replaces) the feature and its index entries, inside the caller's transaction.
void write_feature(sqlite::Connection& conn, const FeatureWrite& write);
// Store::stats of a features layer: indexed cells as tiles, bytes of features and cell lists.
LayerStats feature_stats(sqlite::Connection& conn, const LayerEntry& layer);

// The blobs of content layers (by level and cell) and model layers (level 0, cell 0) in the
// `content` table, each split into parts (content_rows.cpp), inside the caller's transaction.
// write_content_blob writes (or replaces) one; delete_content_blob removes one (true if it was
// there); read_content_blob gives one; read_content_blobs visits those of the cells with ids in
// [first, last] at `level`, in ascending id order.
void write_content_blob(sqlite::Connection& conn, int64_t layer, int level, int64_t cell,
                        std::string_view blob);
bool delete_content_blob(sqlite::Connection& conn, int64_t layer, int level, int64_t cell);
std::optional<std::string> read_content_blob(sqlite::Connection& conn, int64_t layer, int level,
                                             int64_t cell);
void read_content_blobs(sqlite::Connection& conn, int64_t layer, int level, int64_t first,
                        int64_t last,
                        const std::function<void(int64_t cell, std::string&& blob)>& visit);
// Schema version 4 (schema.cpp): moves the blobs of content and model layers from tiles and
// overviews into `content`; view_content_rows gives a reader of an older store a temporary view
// `content` of them where they are.
void move_content_rows(sqlite::Connection& conn);
void view_content_rows(sqlite::Connection& conn);

// A content blob checked against its layer and ready to write, or a cell's content to remove
// (content.cpp).
struct ContentWrite {
  int64_t layer = 0;
  CellId cell;
  bool coarser = false;             // above the layer's level: simplified content
  std::optional<std::string> blob;  // nothing: remove the cell's content
};
// Throws maquette::Error naming the layer and cell unless the layer holds content of the blob's
// kind, the envelope is sound and the cell is at the layer's level or coarser (for a removal,
// `blob` nothing: a content layer and such a cell).
ContentWrite content_write(const LayerEntry& layer, const std::string& store_path, CellId cell,
                           std::optional<std::string_view> blob);
// Store::stats of a content or model layer: cells at the layer's level as tiles, every level's
// bytes.
LayerStats content_layer_stats(sqlite::Connection& conn, const LayerEntry& layer);
// Writes (or replaces, or removes) the cell's content; a change at the layer's level marks the
// parent stale.
void write_content(sqlite::Connection& conn, const ContentWrite& write);

// A model checked and ready to write (model.cpp).
struct ModelWrite {
  std::string name;
  std::string blob;
  nlohmann::json provenance;
};
// Throws maquette::Error naming the model unless `blob` is a sound mesh envelope with a zero
// origin and `existing` (the layer of that name, if any) is a model layer.
ModelWrite model_write(const std::optional<LayerEntry>& existing, const std::string& store_path,
                       const std::string& name, std::string_view blob,
                       const nlohmann::json& provenance);
// Writes (or replaces) the model, creating its layer if absent, inside the caller's transaction;
// throws as model_write if a layer of another kind took the name meanwhile.
void write_model(sqlite::Connection& conn, const std::string& store_path, const ModelWrite& write);
// The stored blobs of `cell`'s children by child digit, for raster and content overviews
// (overviews.cpp): one level below `cell`, in tiles (at the layer's level) or overviews for a
// raster layer, in the content table for a content layer.
using ChildBlobs = Store::ContentChildren;
ChildBlobs read_children(sqlite::Connection& conn, const LayerEntry& layer, CellId cell);
// Up to `limit` cells of `level` whose overviews are stale, in cell order, and their children's
// blobs (read_children): what raster and content overviews rebuild next (overviews.cpp).
struct StaleCells {
  std::vector<CellId> cells;
  std::vector<ChildBlobs> children;
};
StaleCells read_stale_cells(sqlite::Connection& conn, const LayerEntry& layer, int level,
                            size_t limit);
// Marks cell's parent overview stale, so that update_overviews rebuilds it (overviews.cpp).
void mark_parent_stale(sqlite::Connection& conn, int64_t layer_id, CellId cell);
// Writes (or replaces) the overview tile of `cell`, which is then no longer stale, and marks its
// parent stale (overviews.cpp).
void write_overview(sqlite::Connection& conn, int64_t layer_id, CellId cell,
                    std::span<const std::byte> blob);

// "cell Q2013" for error messages.
std::string cell_text(CellId cell);

}  // namespace maquette
