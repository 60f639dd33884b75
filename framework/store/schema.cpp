#include "store/schema.h"

#include <string>

#include "store/store_impl.h"

namespace maquette {
namespace {

// Cell ids are < 2^62, so they are plain SQLite INTEGERs that sort in id order. Layers are
// referenced by their integer id to keep the (layer, cell) keys short. Tiles and overviews
// are WITHOUT ROWID so that a (layer, cell) range is one range scan of the primary key.
constexpr const char* kSchema = R"sql(
CREATE TABLE layers(
  id INTEGER PRIMARY KEY,
  name TEXT NOT NULL UNIQUE,
  kind TEXT NOT NULL,
  dtype TEXT NOT NULL,
  channels INTEGER NOT NULL,
  tile_size INTEGER NOT NULL,
  level INTEGER NOT NULL,
  nodata REAL,
  semantics TEXT NOT NULL,
  units TEXT NOT NULL,
  codec TEXT NOT NULL,
  provenance TEXT NOT NULL,
  created TEXT NOT NULL,
  updated TEXT NOT NULL);
CREATE TABLE tiles(
  layer INTEGER NOT NULL,
  cell INTEGER NOT NULL,
  blob BLOB NOT NULL,
  PRIMARY KEY(layer, cell)) WITHOUT ROWID;
CREATE TABLE overviews(
  layer INTEGER NOT NULL,
  level INTEGER NOT NULL,
  cell INTEGER NOT NULL,
  blob BLOB NOT NULL,
  PRIMARY KEY(layer, level, cell)) WITHOUT ROWID;
CREATE TABLE stale_overviews(
  layer INTEGER NOT NULL,
  level INTEGER NOT NULL,
  cell INTEGER NOT NULL,
  PRIMARY KEY(layer, level, cell)) WITHOUT ROWID;
CREATE TABLE artifacts(
  name TEXT PRIMARY KEY,
  media_type TEXT NOT NULL,
  data BLOB NOT NULL,
  metadata TEXT NOT NULL,
  updated TEXT NOT NULL);
CREATE TABLE runs(
  id INTEGER PRIMARY KEY AUTOINCREMENT,
  pipeline TEXT NOT NULL,
  pipeline_hash TEXT NOT NULL,
  status TEXT NOT NULL,
  started TEXT NOT NULL,
  finished TEXT);
CREATE INDEX runs_by_pipeline ON runs(pipeline_hash, id);
CREATE TABLE run_cells(
  run INTEGER NOT NULL,
  step INTEGER NOT NULL,
  cell INTEGER NOT NULL,
  PRIMARY KEY(run, step, cell)) WITHOUT ROWID;
)sql";

// Version 2: features layers. A feature is stored once (geometry blobs can be large, so a rowid
// table) with the cells it is indexed in, which lets a rewrite drop its old index entries; the
// index (layer, cell, fid) makes a cell range one range scan.
constexpr const char* kFeaturesSchema = R"sql(
CREATE TABLE features(
  layer INTEGER NOT NULL,
  fid INTEGER NOT NULL,
  west REAL NOT NULL,
  south REAL NOT NULL,
  east REAL NOT NULL,
  north REAL NOT NULL,
  geometry BLOB NOT NULL,
  attributes TEXT NOT NULL,
  cells BLOB NOT NULL,
  PRIMARY KEY(layer, fid));
CREATE TABLE feature_cells(
  layer INTEGER NOT NULL,
  cell INTEGER NOT NULL,
  fid INTEGER NOT NULL,
  PRIMARY KEY(layer, cell, fid)) WITHOUT ROWID;
)sql";

// Version 3: the layers being written (marked before their first tile, cleared when done), so
// that readers refuse a layer that a failed or killed command left partial.
constexpr const char* kIncompleteSchema = R"sql(
CREATE TABLE IF NOT EXISTS incomplete_layers(
  layer INTEGER PRIMARY KEY,
  run INTEGER NOT NULL);
)sql";

// Version 4: the blobs of content layers (by level and cell) and model layers (level 0, cell 0),
// each split into parts (content_rows.cpp) so that blobs of a few kB fill whole pages; version 3
// kept them in tiles and overviews, where a WITHOUT ROWID row spills what exceeds ~4 kB into
// overflow pages of its own, partly empty (the file held 2-2.4x the blobs' bytes).
constexpr const char* kContentSchema = R"sql(
CREATE TABLE IF NOT EXISTS content(
  layer INTEGER NOT NULL,
  level INTEGER NOT NULL,
  cell INTEGER NOT NULL,
  part INTEGER NOT NULL,
  data BLOB NOT NULL,
  PRIMARY KEY(layer, level, cell, part)) WITHOUT ROWID;
)sql";

int32_t pragma_int(sqlite::Connection& conn, const char* sql) {
  auto q = conn.query(sql);
  return q.step() ? int32_t(q.int64(0)) : 0;
}

// Brings a version 1 store (no features tables), 2 (no incomplete marks) or 3 (content blobs in
// tiles and overviews) to the current version.
void migrate(sqlite::Connection& conn) {
  conn.transaction([&] {
    // Re-checked under the write lock: another process may have migrated it meanwhile.
    const int32_t version = pragma_int(conn, "PRAGMA user_version");
    if (version >= kStoreSchemaVersion) return;
    if (version < 2) conn.exec(kFeaturesSchema);
    conn.exec(kIncompleteSchema);
    conn.exec(kContentSchema);
    move_content_rows(conn);
    set_version(conn);
  });
}

[[noreturn]] void not_a_store(const sqlite::Connection& conn) {
  throw Error(conn.path() + " is not a Maquette store");
}

}  // namespace

void set_version(sqlite::Connection& conn) {
  conn.exec(("PRAGMA user_version = " + std::to_string(kStoreSchemaVersion)).c_str());
}

void configure_connection(sqlite::Connection& conn, bool writer) {
  conn.exec("PRAGMA mmap_size = 1073741824");
  // In WAL mode NORMAL loses no committed transaction when the process dies (only on power loss).
  if (writer) conn.exec("PRAGMA synchronous = NORMAL");
  const int32_t version = pragma_int(conn, "PRAGMA user_version");
  if (!writer && version >= 1 && version < 4 &&
      pragma_int(conn, "PRAGMA application_id") == kStoreApplicationId)
    view_content_rows(conn);
}

void create_schema(sqlite::Connection& conn) {
  if (pragma_int(conn, "PRAGMA application_id") == 0) {
    // Only effective on an empty file.
    conn.exec(("PRAGMA page_size = " + std::to_string(kStorePageSize)).c_str());
    conn.transaction([&] {
      // Re-checked under the write lock: another process may have created it meanwhile.
      if (pragma_int(conn, "PRAGMA application_id") != 0) return;
      if (pragma_int(conn, "SELECT count(*) FROM sqlite_schema") != 0) not_a_store(conn);
      conn.exec(kSchema);
      conn.exec(kFeaturesSchema);
      conn.exec(kIncompleteSchema);
      conn.exec(kContentSchema);
      conn.exec(("PRAGMA application_id = " + std::to_string(kStoreApplicationId)).c_str());
      set_version(conn);
    });
  }
  check_schema(conn);
  if (pragma_int(conn, "PRAGMA user_version") < kStoreSchemaVersion) migrate(conn);
}

void check_schema(sqlite::Connection& conn) {
  if (pragma_int(conn, "PRAGMA application_id") == 0 &&
      pragma_int(conn, "SELECT count(*) FROM sqlite_schema") == 0)
    throw Error(conn.path() + " is an empty database, not a Maquette store");
  if (pragma_int(conn, "PRAGMA application_id") != kStoreApplicationId) not_a_store(conn);
  const int32_t version = pragma_int(conn, "PRAGMA user_version");
  if (version > kStoreSchemaVersion)
    throw Error(conn.path() + " is a newer store (schema version " + std::to_string(version) +
                "): this Maquette reads up to version " + std::to_string(kStoreSchemaVersion) +
                "; use a newer Maquette");
}

}  // namespace maquette
