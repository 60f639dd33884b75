// The SQLite store: opening, layers, tiles, artifacts, runs and batches, on real files.
#include "store/store.h"

#include <sqlite3.h>
#include <sys/stat.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <random>
#include <thread>

#include "core/error.h"
#include "store/codec.h"
#include "store_test_util.h"

namespace maquette {
namespace {

using test::expect_error;
using test::raw_sql;
using test::raw_tile;
using test::smooth_tile;
using test::TempDir;

// Flips bytes in the middle of every tile blob of a store file.
void corrupt_tiles(const std::string& path) {
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
  sqlite3_stmt* read = nullptr;
  sqlite3_prepare_v2(db, "SELECT layer, cell, blob FROM tiles", -1, &read, nullptr);
  std::vector<std::tuple<int64_t, int64_t, std::vector<unsigned char>>> rows;
  while (sqlite3_step(read) == SQLITE_ROW) {
    const auto* p = static_cast<const unsigned char*>(sqlite3_column_blob(read, 2));
    std::vector<unsigned char> blob(p, p + sqlite3_column_bytes(read, 2));
    for (size_t i = blob.size() / 2; i < blob.size() / 2 + 8; ++i) blob[i] ^= 0x5a;
    rows.emplace_back(sqlite3_column_int64(read, 0), sqlite3_column_int64(read, 1), blob);
  }
  sqlite3_finalize(read);
  sqlite3_stmt* write = nullptr;
  sqlite3_prepare_v2(db, "UPDATE tiles SET blob = ? WHERE layer = ? AND cell = ?", -1, &write,
                     nullptr);
  for (const auto& [layer, cell, blob] : rows) {
    sqlite3_bind_blob(write, 1, blob.data(), int(blob.size()), SQLITE_TRANSIENT);
    sqlite3_bind_int64(write, 2, layer);
    sqlite3_bind_int64(write, 3, cell);
    EXPECT_EQ(sqlite3_step(write), SQLITE_DONE);
    sqlite3_reset(write);
  }
  sqlite3_finalize(write);
  sqlite3_close(db);
}

LayerInfo dem_layer(int level = 3, int tile_size = 16) {
  LayerInfo l;
  l.name = "dem";
  l.dtype = DType::F32;
  l.tile_size = tile_size;
  l.level = level;
  l.nodata = -9999;
  l.units = "m";
  l.provenance = {{"source", "test"}, {"params", {{"a", 1}}}};
  return l;
}

CellId cell(std::string_view text) { return *CellId::FromText(text); }

TEST(StoreOpen, MissingFile) {
  TempDir dir;
  for (auto mode : {Store::Mode::ReadOnly, Store::Mode::ReadWrite})
    expect_error([&] { Store::open(dir.file("none.mqs"), mode); },
                 {"no such store", dir.file("none.mqs")});
  expect_error([&] { Store::open(dir.file("no/such/dir.mqs"), Store::Mode::Create); },
               {dir.file("no/such/dir.mqs")});
}

TEST(StoreOpen, NotAStore) {
  TempDir dir;
  const std::string garbage = dir.file("garbage.mqs");
  std::ofstream(garbage) << std::string(5000, 'x');
  const std::string foreign = dir.file("foreign.sqlite");
  raw_sql(foreign, "CREATE TABLE t(x); INSERT INTO t VALUES(1);");
  const std::string empty = dir.file("empty.mqs");
  std::ofstream{empty};
  for (const auto& path : {garbage, foreign})
    for (auto mode : {Store::Mode::ReadOnly, Store::Mode::ReadWrite, Store::Mode::Create})
      expect_error([&] { Store::open(path, mode); }, {path + " is not a Maquette store"});
  // An empty file (not made by us: stores are created whole) is not a store to readers, and
  // becomes one when opened for writing.
  expect_error([&] { Store::open(empty, Store::Mode::ReadOnly); }, {empty, "empty database"});
  EXPECT_NO_THROW(Store::open(empty, Store::Mode::ReadWrite));
  EXPECT_NO_THROW(Store::open(empty, Store::Mode::ReadOnly)->layers());
}

TEST(StoreOpen, NewerSchemaIsRefused) {
  TempDir dir;
  const std::string path = dir.file("new.mqs");
  Store::open(path, Store::Mode::Create);
  raw_sql(path, "PRAGMA user_version = 99");
  expect_error([&] { Store::open(path, Store::Mode::ReadOnly); }, {path, "schema version 99"});
}

TEST(StoreOpen, ReadOnlyFileOpenedForWriting) {
  TempDir dir;
  const std::string path = dir.file("ro.mqs");
  Store::open(path, Store::Mode::Create)->create_layer(dem_layer());
  ASSERT_EQ(::chmod(path.c_str(), 0444), 0);
  for (auto mode : {Store::Mode::ReadWrite, Store::Mode::Create})
    expect_error([&] { Store::open(path, mode); }, {path + " is read-only"});
  auto store = Store::open(path, Store::Mode::ReadOnly);
  EXPECT_TRUE(store->read_only());
  EXPECT_TRUE(store->layer("dem").has_value());
}

TEST(StoreOpen, ReadOnlyStoreRefusesWrites) {
  TempDir dir;
  const std::string path = dir.file("s.mqs");
  Store::open(path, Store::Mode::Create)->create_layer(dem_layer());
  auto store = Store::open(path, Store::Mode::ReadOnly);
  const RawTile tile = smooth_tile(16);
  expect_error([&] { store->put_tile("dem", cell("Q012"), tile); }, {path, "read-only"});
  expect_error([&] { store->create_layer(dem_layer()); }, {"read-only"});
  expect_error([&] { store->begin_run({{"steps", 1}}); }, {"read-only"});
  expect_error([&] { store->put_artifact({"a", "text/plain", {}, {}}); }, {"read-only"});
  expect_error([&] { store->update_overviews("dem"); }, {"read-only"});
  expect_error([&] { Store::Batch batch(*store); }, {"read-only"});
}

TEST(StoreOpen, CreatedOnlyByTheOpenThatMadeTheFile) {
  TempDir dir;
  const std::string path = dir.file("s.mqs");
  EXPECT_TRUE(Store::open(path, Store::Mode::Create)->created());
  EXPECT_FALSE(Store::open(path, Store::Mode::Create)->created());
  EXPECT_FALSE(Store::open(path, Store::Mode::ReadWrite)->created());
}

// The file format's read/write version bytes (offsets 18 and 19): 1 rollback journal, 2 WAL.
int journal_format(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  file.seekg(18);
  return file.get();
}

bool exists(const std::string& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0;
}

// A store CreateBulk makes is filled without a WAL, readable meanwhile by other connections,
// and closed synced in WAL mode with no journal left; CreateBulk on an existing store writes
// through the WAL as usual.
TEST(StoreOpen, CreateBulkFillsWithoutWalAndClosesInWalMode) {
  TempDir dir;
  const std::string path = dir.file("s.mqs");
  auto store = Store::open(path, Store::Mode::CreateBulk);
  EXPECT_TRUE(store->created());
  store->create_layer(dem_layer(3, 16));
  store->put_tile("dem", cell("Q012"), smooth_tile(16, 1));
  EXPECT_EQ(journal_format(path), 1);
  EXPECT_FALSE(exists(path + "-wal"));
  EXPECT_EQ(Store::open(path, Store::Mode::ReadOnly)->tile_cells("dem").size(), 1u);
  store.reset();
  EXPECT_EQ(journal_format(path), 2);
  EXPECT_FALSE(exists(path + "-journal"));
  EXPECT_FALSE(exists(path + "-wal"));
  const auto reopened = Store::open(path, Store::Mode::ReadOnly);
  EXPECT_TRUE(reopened->integrity_ok());
  EXPECT_EQ(reopened->get_tile("dem", cell("Q012"))->bytes, smooth_tile(16, 1).bytes);

  store = Store::open(path, Store::Mode::CreateBulk);
  EXPECT_FALSE(store->created());
  store->put_tile("dem", cell("Q013"), smooth_tile(16, 2));
  EXPECT_TRUE(exists(path + "-wal"));
}

// Another writer opening a store being filled in bulk switches it to WAL; the bulk writer goes
// on writing through the WAL, and every write of both is there after the closes.
TEST(StoreOpen, AnotherWriterSwitchesABulkFillToWal) {
  TempDir dir;
  const std::string path = dir.file("s.mqs");
  auto bulk = Store::open(path, Store::Mode::CreateBulk);
  bulk->create_layer(dem_layer(3, 16));
  bulk->put_tile("dem", cell("Q012"), smooth_tile(16, 1));
  EXPECT_EQ(journal_format(path), 1);
  auto other = Store::open(path, Store::Mode::ReadWrite);
  EXPECT_EQ(journal_format(path), 2);
  other->put_tile("dem", cell("Q013"), smooth_tile(16, 2));
  bulk->put_tile("dem", cell("Q020"), smooth_tile(16, 3));
  bulk.reset();
  other.reset();
  const auto reopened = Store::open(path, Store::Mode::ReadOnly);
  EXPECT_TRUE(reopened->integrity_ok());
  EXPECT_EQ(reopened->tile_cells("dem"),
            (std::vector<CellId>{cell("Q012"), cell("Q013"), cell("Q020")}));
  EXPECT_FALSE(exists(path + "-journal"));
}

TEST(StoreLayers, CreateAndReopen) {
  TempDir dir;
  const std::string path = dir.file("s.mqs");
  LayerInfo classes;
  classes.name = "landcover";
  classes.dtype = DType::U8;
  classes.channels = 1;
  classes.tile_size = 64;
  classes.level = 7;
  classes.semantics = Semantics::Categorical;
  classes.codec = "zstd:9";
  LayerInfo rgb;
  rgb.name = "ortho";
  rgb.dtype = DType::U8;
  rgb.channels = 3;
  rgb.codec = "raw";
  {
    auto store = Store::open(path, Store::Mode::Create);
    EXPECT_EQ(store->path(), path);
    EXPECT_FALSE(store->read_only());
    store->create_layer(dem_layer());
    store->create_layer(rgb);
    store->create_layer(classes);
  }
  auto store = Store::open(path, Store::Mode::ReadOnly);
  const auto layers = store->layers();
  ASSERT_EQ(layers.size(), 3u);
  EXPECT_EQ(layers[0].name, "dem");  // by name
  EXPECT_EQ(layers[1].name, "landcover");
  EXPECT_EQ(layers[2].name, "ortho");
  const LayerInfo dem = store->require_layer("dem");
  EXPECT_EQ(dem.dtype, DType::F32);
  EXPECT_EQ(dem.tile_size, 16);
  EXPECT_EQ(dem.level, 3);
  EXPECT_EQ(dem.nodata, -9999);
  EXPECT_EQ(dem.units, "m");
  EXPECT_EQ(dem.provenance, dem_layer().provenance);
  EXPECT_EQ(layers[1].semantics, Semantics::Categorical);
  EXPECT_EQ(layers[1].codec, "zstd:9");
  EXPECT_FALSE(layers[1].nodata.has_value());
  EXPECT_EQ(layers[2].channels, 3);
  EXPECT_FALSE(store->layer("nope").has_value());
  expect_error([&] { store->require_layer("nope"); }, {"unknown layer 'nope'", path});
  expect_error([&] { store->get_tile("nope", cell("Q")); }, {"unknown layer 'nope'", path});
}

TEST(StoreLayers, CreateIsIdempotentAndRefusesConflicts) {
  TempDir dir;
  auto store = Store::open(dir.file("s.mqs"), Store::Mode::Create);
  store->create_layer(dem_layer());
  store->create_layer(dem_layer());  // same definition: no-op
  LayerInfo other = dem_layer();
  other.dtype = DType::I16;
  expect_error([&] { store->create_layer(other); },
               {"layer 'dem'", "dtype float32 vs int16", store->path()});
  other = dem_layer();
  other.nodata.reset();
  expect_error([&] { store->create_layer(other); }, {"nodata -9999 vs none"});
  other = dem_layer();
  other.provenance = {{"source", "rerun"}};  // not part of the definition: updated
  store->create_layer(other);
  EXPECT_EQ(store->require_layer("dem").provenance["source"], "rerun");
  EXPECT_EQ(store->layers().size(), 1u);
}

TEST(StoreLayers, RejectsBadDefinitions) {
  TempDir dir;
  auto store = Store::open(dir.file("s.mqs"), Store::Mode::Create);
  auto bad = [&](auto change, const char* mentions) {
    LayerInfo l = dem_layer();
    change(l);
    expect_error([&] { store->create_layer(l); }, {mentions});
  };
  bad([](LayerInfo& l) { l.name = ""; }, "name");
  bad([](LayerInfo& l) { l.name = " "; }, "layer name ' ': no blank at either end");
  bad([](LayerInfo& l) { l.name = "dem "; }, "layer name 'dem '");
  bad([](LayerInfo& l) { l.name = "a\tb"; }, "no control character");
  bad([](LayerInfo& l) { l.tile_size = 100; }, "tile size 100");
  bad([](LayerInfo& l) { l.codec = "lz4"; }, "codec 'lz4'");
  bad([](LayerInfo& l) { l.level = 30; }, "level 30");
  bad([](LayerInfo& l) { l.channels = 0; }, "channels 0");
  bad([](LayerInfo& l) { l.dtype = DType::U8, l.nodata = 300; }, "nodata 300");
  bad([](LayerInfo& l) { l.dtype = DType::I16, l.nodata = 0.5; }, "nodata 0.5");
  LayerInfo nan_nodata = dem_layer();
  nan_nodata.name = "nan";
  nan_nodata.nodata = NAN;  // NaN is always missing in float tiles
  store->create_layer(nan_nodata);
  EXPECT_FALSE(store->require_layer("nan").nodata.has_value());
}

TEST(StoreTiles, PutGetAndScanInIdOrderAcrossFacesAndLevels) {
  TempDir dir;
  auto store = Store::open(dir.file("s.mqs"), Store::Mode::Create);
  store->create_layer(dem_layer(3, 16));
  LayerInfo fine = dem_layer(5, 8);
  fine.name = "fine";
  store->create_layer(fine);

  std::vector<CellId> cells = {cell("S333"), cell("N000"), cell("Q201"), cell("Q012"),
                               cell("O320"), cell("Q200"), cell("N301"), cell("R000")};
  std::mt19937 rng(7);
  std::shuffle(cells.begin(), cells.end(), rng);
  {
    Store::Batch batch(*store);
    for (size_t i = 0; i < cells.size(); ++i)
      batch.put_tile("dem", cells[i], smooth_tile(16, float(cells[i].id() % 1000)));
    for (const char* c : {"Q20133", "Q01233", "N00000", "Q20000"})
      batch.put_tile("fine", cell(c), smooth_tile(8));
    batch.commit();
  }
  std::vector<CellId> sorted = cells;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(store->tile_cells("dem"), sorted);
  EXPECT_EQ(sorted.front(), cell("N000"));
  EXPECT_EQ(sorted.back(), cell("S333"));

  // Ranges of coarser cells select their descendants only, in id order.
  const CellId q = cell("Q"), q2 = cell("Q2"), q20 = cell("Q20");
  EXPECT_EQ(store->tile_cells("dem", q.range_min(), q.range_max()),
            (std::vector<CellId>{cell("Q012"), cell("Q200"), cell("Q201")}));
  EXPECT_EQ(store->tile_cells("dem", q2.range_min(), q2.range_max()),
            (std::vector<CellId>{cell("Q200"), cell("Q201")}));
  EXPECT_EQ(store->tile_cells("fine", q20.range_min(), q20.range_max()),
            (std::vector<CellId>{cell("Q20000"), cell("Q20133")}));
  EXPECT_TRUE(store->tile_cells("dem", cell("P").range_min(), cell("P").range_max()).empty());

  std::vector<CellId> visited;
  store->scan("dem", q.range_min(), q.range_max(), [&](CellId c, const RawTile& t) {
    visited.push_back(c);
    EXPECT_EQ(t.bytes, smooth_tile(16, float(c.id() % 1000)).bytes) << c.ToText();
  });
  EXPECT_EQ(visited, store->tile_cells("dem", q.range_min(), q.range_max()));

  EXPECT_TRUE(store->has_tile("dem", cell("R000")));
  EXPECT_FALSE(store->has_tile("dem", cell("R001")));
  EXPECT_FALSE(store->get_tile("dem", cell("R001")).has_value());
  EXPECT_EQ(store->get_tile("dem", cell("O320"))->bytes,
            smooth_tile(16, float(cell("O320").id() % 1000)).bytes);

  // Overwriting replaces.
  store->put_tile("dem", cell("R000"), smooth_tile(16, 42));
  EXPECT_EQ(store->get_tile("dem", cell("R000"))->bytes, smooth_tile(16, 42).bytes);

  const LayerStats s = store->stats("dem");
  EXPECT_EQ(s.tile_count, 8);
  EXPECT_GT(s.bytes, 0);
  EXPECT_LT(s.bytes, 8 * 16 * 16 * 4);
  EXPECT_EQ(s.levels, std::vector<int>{3});
  EXPECT_EQ(s.first, cell("N000"));
  EXPECT_EQ(s.last, cell("S333"));
  EXPECT_GT(store->file_size(), 0);
}

TEST(StoreTiles, RejectsMismatchedTiles) {
  TempDir dir;
  auto store = Store::open(dir.file("s.mqs"), Store::Mode::Create);
  store->create_layer(dem_layer(3, 16));
  expect_error([&] { store->put_tile("dem", cell("Q01"), smooth_tile(16)); },
               {"layer 'dem'", "cell Q01", "level 3"});
  expect_error([&] { store->put_tile("dem", cell("Q012"), smooth_tile(32)); },
               {"cell Q012", "32x32x1 float32"});
  expect_error(
      [&] {
        store->put_tile("dem", cell("Q012"), raw_tile<int16_t>(16, 1, std::vector<int16_t>(256)));
      },
      {"int16"});
  EXPECT_TRUE(store->tile_cells("dem").empty());
}

TEST(StoreTiles, CorruptBlobIsReportedWithLayerAndCell) {
  TempDir dir;
  const std::string path = dir.file("s.mqs");
  const CellId c = cell("Q012");
  Store::open(path, Store::Mode::Create)->create_layer(dem_layer());
  Store::open(path, Store::Mode::ReadWrite)->put_tile("dem", c, smooth_tile(16));
  corrupt_tiles(path);
  auto store = Store::open(path, Store::Mode::ReadOnly);
  expect_error([&] { store->get_tile("dem", c); }, {"corrupt tile", "layer 'dem'", "Q012", path});
  expect_error([&] { store->scan("dem", c, c, [](CellId, const RawTile&) {}); }, {"Q012"});
}

// Old stores wrote "zstd" tiles at zstd level 3; the codec string names the format, not the level:
// such a layer is read, resumed (same definition) and extended at today's level.
TEST(StoreTiles, ZstdLayerWrittenAtAnotherLevelIsReadAndExtended) {
  TempDir dir;
  const std::string path = dir.file("s.mqs");
  const CellId old_cell = cell("Q012"), new_cell = cell("Q013");
  const RawTile old_tile = smooth_tile(16, 1.0), new_tile = smooth_tile(16, 2.0);
  Store::open(path, Store::Mode::Create)->create_layer(dem_layer());
  const std::vector<std::byte> level3 = encode_tile(old_tile, parse_codec("zstd:3"));
  ASSERT_NE(level3, encode_tile(old_tile, parse_codec("zstd")));  // the levels do differ
  std::string hex;
  for (std::byte b : level3)
    hex += {"0123456789abcdef"[int(b) >> 4], "0123456789abcdef"[int(b) & 15]};
  raw_sql(path, "INSERT INTO tiles(layer, cell, blob) SELECT id, " +
                    std::to_string(int64_t(old_cell.id())) + ", X'" + hex +
                    "' FROM layers WHERE name = 'dem'");
  auto store = Store::open(path, Store::Mode::ReadWrite);
  store->create_layer(dem_layer());  // resuming: the same definition, codec "zstd"
  store->put_tile("dem", new_cell, new_tile);
  store->update_overviews("dem");
  EXPECT_EQ(store->get_tile("dem", old_cell)->bytes, old_tile.bytes);
  EXPECT_EQ(store->get_tile("dem", new_cell)->bytes, new_tile.bytes);
  EXPECT_TRUE(store->get_overview("dem", old_cell.parent()).has_value());
}

TEST(StoreBatch, RollbackOnExceptionLeavesNothing) {
  TempDir dir;
  auto store = Store::open(dir.file("s.mqs"), Store::Mode::Create);
  store->create_layer(dem_layer());
  const int64_t run = store->begin_run({{"steps", 1}});
  try {
    Store::Batch batch(*store);
    batch.put_tile("dem", cell("Q012"), smooth_tile(16));
    batch.put_artifact({"model", "application/json", {}, {{"k", 1}}});
    batch.mark_done(run, 0, cell("Q012"));
    batch.put_tile("dem", cell("Q01"), smooth_tile(16));  // wrong level: throws
    batch.commit();
  } catch (const Error&) {
  }
  EXPECT_TRUE(store->tile_cells("dem").empty());
  EXPECT_TRUE(store->artifact_names().empty());
  EXPECT_TRUE(store->done_cells(run, 0).empty());

  Store::Batch batch(*store);
  batch.put_tile("dem", cell("Q012"), smooth_tile(16));
  EXPECT_TRUE(store->tile_cells("dem").empty());  // not visible before commit
  batch.commit();
  EXPECT_EQ(store->tile_cells("dem").size(), 1u);
  EXPECT_THROW(batch.commit(), Error);
  EXPECT_THROW(batch.put_tile("dem", cell("Q013"), smooth_tile(16)), Error);
}

TEST(StoreArtifacts, PutGetOverwrite) {
  TempDir dir;
  const std::string path = dir.file("s.mqs");
  {
    auto store = Store::open(path, Store::Mode::Create);
    const std::string text = R"({"weights":[1,2,3]})";
    Artifact a{"texture.model", "application/json", {}, {{"operator", "texture.fit"}}};
    for (char ch : text) a.data.push_back(std::byte(ch));
    store->put_artifact(a);
    store->put_artifact({"bin", "application/octet-stream", {std::byte{0}, std::byte{255}}, {}});
    store->put_artifact({"empty", "text/plain", {}, {}});
    a.metadata["version"] = 2;
    store->put_artifact(a);
  }
  auto store = Store::open(path, Store::Mode::ReadOnly);
  EXPECT_EQ(store->artifact_names(), (std::vector<std::string>{"bin", "empty", "texture.model"}));
  const auto a = store->get_artifact("texture.model");
  ASSERT_TRUE(a);
  EXPECT_EQ(a->media_type, "application/json");
  EXPECT_EQ(std::string(reinterpret_cast<const char*>(a->data.data()), a->data.size()),
            R"({"weights":[1,2,3]})");
  EXPECT_EQ(a->metadata["version"], 2);
  EXPECT_EQ(store->get_artifact("bin")->data,
            (std::vector<std::byte>{std::byte{0}, std::byte{255}}));
  EXPECT_TRUE(store->get_artifact("empty")->data.empty());
  EXPECT_FALSE(store->get_artifact("none"));
}

TEST(StoreArtifacts, FromTextHoldsTheTextsBytes) {
  const Artifact a = Artifact::FromText("m", "{\"k\":2}", {{"k", 2}});
  EXPECT_EQ(a.name, "m");
  EXPECT_EQ(a.media_type, "application/json");
  EXPECT_EQ(a.data,
            (std::vector<std::byte>{std::byte{'{'}, std::byte{'"'}, std::byte{'k'}, std::byte{'"'},
                                    std::byte{':'}, std::byte{'2'}, std::byte{'}'}}));
  EXPECT_EQ(a.text(), "{\"k\":2}");
  EXPECT_EQ(a.metadata["k"], 2);
}

TEST(StoreRuns, ResumeFindsTheUnfinishedRunOfTheSamePipeline) {
  TempDir dir;
  auto store = Store::open(dir.file("s.mqs"), Store::Mode::Create);
  const nlohmann::json pipeline = {{"level", 5}, {"steps", {{{"op", "terrain.derive"}}}}};
  const nlohmann::json same =
      nlohmann::json::parse(R"({"steps":[{"op":"terrain.derive"}],"level":5})");
  const nlohmann::json other = {{"level", 6}};
  EXPECT_FALSE(store->latest_unfinished_run(pipeline));

  const int64_t first = store->begin_run(pipeline);
  const int64_t unrelated = store->begin_run(other);
  EXPECT_EQ(store->latest_unfinished_run(same), first);
  {
    Store::Batch batch(*store);
    for (const char* c : {"Q3", "Q1", "N2"}) batch.mark_done(first, 0, cell(c));
    batch.mark_done(first, 1, cell("Q1"));
    batch.mark_done(first, 0, cell("Q1"));  // twice is fine
    batch.commit();
  }
  EXPECT_EQ(store->done_cells(first, 0), (std::vector<CellId>{cell("N2"), cell("Q1"), cell("Q3")}));
  EXPECT_EQ(store->done_cells(first, 1), std::vector<CellId>{cell("Q1")});
  EXPECT_TRUE(store->done_cells(unrelated, 0).empty());

  store->finish_run(first, "failed: out of memory");
  EXPECT_EQ(store->latest_unfinished_run(pipeline), first);
  const int64_t second = store->begin_run(pipeline);
  EXPECT_GT(second, first);
  EXPECT_EQ(store->latest_unfinished_run(pipeline), second);
  store->finish_run(second, "ok");
  EXPECT_EQ(store->latest_unfinished_run(pipeline), first);
  store->finish_run(first, "ok");
  EXPECT_FALSE(store->latest_unfinished_run(pipeline));
  EXPECT_EQ(store->latest_unfinished_run(other), unrelated);
  expect_error([&] { store->finish_run(999, "ok"); }, {"no run 999"});
}

TEST(StoreConcurrency, ThreadsWriteAndReadTogether) {
  TempDir dir;
  auto store = Store::open(dir.file("s.mqs"), Store::Mode::Create);
  store->create_layer(dem_layer(4, 32));
  constexpr int kThreads = 4, kBatches = 20, kPerBatch = 4;
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t)
    threads.emplace_back([&, t] {
      for (int b = 0; b < kBatches; ++b) {
        Store::Batch batch(*store);
        for (int i = 0; i < kPerBatch; ++i) {
          const int k = (t * kBatches + b) * kPerBatch + i;
          batch.put_tile("dem", CellId::FromFaceColRow(k % 6, 4, (k / 6) % 16, (k / 6) / 16),
                         smooth_tile(32, float(k)));
        }
        batch.commit();
        // Every committed tile decodes, whatever the other threads are doing.
        store->scan("dem", CellId(0), CellId(uint64_t(INT64_MAX)),
                    [](CellId, const RawTile& tile) { EXPECT_EQ(tile.size, 32); });
      }
    });
  for (auto& th : threads) th.join();
  EXPECT_EQ(store->tile_cells("dem").size(), size_t(kThreads * kBatches * kPerBatch));
  EXPECT_TRUE(store->integrity_ok());
}

// Tiles written while the store is open reach the database file itself, not only the WAL:
// ~9 MiB of barely compressible tiles, below SQLite's own automatic checkpoint (1000 pages,
// 16 MiB), are copied by the background checkpoints every 256 pages (4 MiB), so the file holds
// at least 4 MiB of them before the close (it is ~100 KiB when it only has the schema). Then
// the store closes whole.
TEST(StoreCheckpoints, WalIsCopiedWhileTheStoreIsOpen) {
  TempDir dir;
  const std::string path = dir.file("s.mqs");
  auto store = Store::open(path, Store::Mode::Create);
  store->create_layer(dem_layer(6, 256));
  std::mt19937 random(7);
  std::uniform_real_distribution<float> value(-1000, 1000);
  std::vector<float> samples(256 * 256);
  for (int k = 0; k < 40; ++k) {  // 40 tiles of 256 KiB
    for (float& v : samples) v = value(random);
    store->put_tile("dem", CellId::FromFaceColRow(0, 6, k, 0), raw_tile<float>(256, 1, samples));
  }
  const auto db_bytes = [&] {
    struct stat st {};
    return ::stat(path.c_str(), &st) == 0 ? int64_t(st.st_size) : 0;
  };
  // The checkpoints run in their own thread: wait for them (at most 20 s).
  for (int i = 0; i < 2000 && db_bytes() < 4 << 20; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  EXPECT_GE(db_bytes(), 4 << 20);
  store.reset();
  auto reopened = Store::open(path, Store::Mode::ReadOnly);
  EXPECT_EQ(reopened->tile_cells("dem").size(), size_t(40));
  EXPECT_TRUE(reopened->integrity_ok());
}

TEST(StoreIntegrity, OkAfterManyWrites) {
  TempDir dir;
  const std::string path = dir.file("s.mqs");
  auto store = Store::open(path, Store::Mode::Create);
  store->create_layer(dem_layer(5, 32));
  for (int b = 0; b < 50; ++b) {
    Store::Batch batch(*store);
    for (int i = 0; i < 10; ++i) {
      const int k = b * 7 + i;  // overlapping: rewrites some cells
      batch.put_tile("dem", CellId::FromFaceColRow(k % 6, 5, k % 32, (k / 32) % 32),
                     smooth_tile(32, float(k)));
    }
    batch.commit();
  }
  store->update_overviews("dem");
  EXPECT_TRUE(store->integrity_ok());
  store.reset();
  EXPECT_TRUE(Store::open(path, Store::Mode::ReadOnly)->integrity_ok());
}

}  // namespace
}  // namespace maquette
