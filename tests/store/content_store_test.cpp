// Content layers in the store (kinds mesh, instances, volume): blobs put and got per cell at the
// layer's level and at coarser ones, cells listed, stats read from the headers, wrong kinds
// refused with nothing stored, on real SQLite files.
#include <sqlite3.h>

#include <algorithm>
#include <map>
#include <random>

#include "content/content_blob.h"
#include "content/instances_codec.h"
#include "store/store.h"
#include "store_test_util.h"

namespace maquette {
namespace {

using test::expect_error;
using test::raw_int;
using test::raw_sql;
using test::TempDir;

CellId cell(std::string_view text) { return *CellId::FromText(text); }

LayerInfo content_layer(const std::string& name, LayerKind kind, int level) {
  LayerInfo l;
  l.name = name;
  l.kind = kind;
  l.level = level;
  l.provenance = {{"tool", "test"}};
  return l;
}

// `n` instances around the origin, their values a function of `seed`.
InstancesContent trees(size_t n, uint32_t seed) {
  std::mt19937 rng(seed);
  InstancesContent c;
  c.origin = {2.35 + seed * 1e-3, 48.85, 35};
  c.prototypes = {"builtin:conifer", "builtin:broadleaf"};
  for (size_t i = 0; i < n; ++i) {
    c.prototype.push_back(uint16_t(rng() % 2));
    for (int k = 0; k < 3; ++k) c.position.push_back(float(rng() % 10000) / 100);
    const float angle = float(rng() % 628) / 100;
    c.rotation.insert(c.rotation.end(), {0, 0, std::sin(angle / 2), std::cos(angle / 2)});
    const float s = 0.5f + float(rng() % 100) / 100;
    c.scale.insert(c.scale.end(), {s, s, s});
    c.colour.push_back(rng());
    c.provenance.push_back({rng(), int64_t(i), "vegetation.trees", {{"height", 10 * s}}});
  }
  return c;
}

// A raster layer "dem" at level 7, beside the content layers.
LayerInfo dem_layer(int tile_size) {
  LayerInfo dem;
  dem.name = "dem";
  dem.tile_size = tile_size;
  dem.level = 7;
  return dem;
}

// Runs `sql` on a store file directly, ?1 bound to `blob`, ?2 to `cell`, ?3 to `layer`.
void raw_blob_sql(const std::string& path, const char* sql, const std::string& blob, CellId cell,
                  const std::string& layer) {
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
  sqlite3_stmt* q = nullptr;
  ASSERT_EQ(sqlite3_prepare_v2(db, sql, -1, &q, nullptr), SQLITE_OK) << sql;
  sqlite3_bind_blob(q, 1, blob.data(), int(blob.size()), SQLITE_TRANSIENT);
  sqlite3_bind_int64(q, 2, int64_t(cell.id()));
  sqlite3_bind_text(q, 3, layer.c_str(), -1, SQLITE_TRANSIENT);
  EXPECT_EQ(sqlite3_step(q), SQLITE_DONE);
  EXPECT_EQ(sqlite3_changes(db), 1) << sql;
  sqlite3_finalize(q);
  sqlite3_close(db);
}

// Replaces the blob of `cell` in the content of `layer` (schema version 4: its parts, here one
// part holding it all), as a foreign program (or a disk fault) would.
void set_blob(const std::string& path, const std::string& layer, CellId cell,
              const std::string& blob) {
  raw_sql(path, "DELETE FROM content WHERE part > 0 AND cell = " + std::to_string(cell.id()) +
                    " AND layer = (SELECT id FROM layers WHERE name = '" + layer + "')");
  raw_blob_sql(path,
               "UPDATE content SET data = ?1 WHERE cell = ?2 AND part = 0 AND "
               "layer = (SELECT id FROM layers WHERE name = ?3)",
               blob, cell, layer);
}

// An envelope of `kind` whose payload is not an encoding at all: the store must not decode it.
std::string opaque_blob(ContentKind kind, ContentStats stats, size_t payload_bytes) {
  ContentEnvelope e;
  e.kind = kind;
  e.origin = {-3.7, 40.4, 650};
  e.stats = stats;
  return wrap_content(e, std::string(payload_bytes, '\x5a'));
}

TEST(StoreContent, LayersOfContentKindsKeepNoRasterFields) {
  TempDir dir;
  const std::string path = dir.file("s.mqs");
  {
    auto store = Store::open(path, Store::Mode::Create);
    for (auto [name, kind] :
         {std::pair{"trees", LayerKind::Instances}, std::pair{"buildings", LayerKind::Mesh},
          std::pair{"water", LayerKind::Volume}}) {
      LayerInfo l = content_layer(name, kind, 17);
      l.dtype = DType::F64;
      l.channels = 3;
      l.tile_size = 512;
      l.nodata = -1;
      l.units = "m";
      store->create_layer(l);
      // Asked again with other raster fields: the same layer.
      store->create_layer(content_layer(name, kind, 17));
    }
    expect_error([&] { store->create_layer(content_layer("trees", LayerKind::Instances, 16)); },
                 {"layer 'trees'", "level 17 vs 16"});
    expect_error([&] { store->create_layer(content_layer("trees", LayerKind::Mesh, 17)); },
                 {"kind instances vs mesh"});
    expect_error([&] { store->create_layer(content_layer("t", LayerKind::Instances, 30)); },
                 {"level 30"});
  }
  auto store = Store::open(path, Store::Mode::ReadOnly);
  const LayerInfo trees = store->require_layer("trees");
  EXPECT_EQ(trees.kind, LayerKind::Instances);
  EXPECT_EQ(layer_kind_name(trees.kind), "instances");
  EXPECT_EQ(parse_layer_kind("instances"), LayerKind::Instances);
  EXPECT_EQ(trees.level, 17);
  EXPECT_EQ(trees.dtype, DType::U8);
  EXPECT_EQ(trees.channels, 1);
  EXPECT_EQ(trees.tile_size, 1);
  EXPECT_FALSE(trees.nodata.has_value());
  EXPECT_EQ(trees.units, "");
  EXPECT_EQ(trees.codec, "mqct");
  EXPECT_EQ(trees.provenance["tool"], "test");
  EXPECT_EQ(store->require_layer("buildings").kind, LayerKind::Mesh);
  EXPECT_EQ(store->require_layer("water").kind, LayerKind::Volume);
  EXPECT_EQ(layer_content_kind(LayerKind::Volume), ContentKind::Volume);
  EXPECT_FALSE(layer_content_kind(LayerKind::Features).has_value());
}

TEST(StoreContent, PutGetCellsAndStatsAtEveryLevel) {
  TempDir dir;
  const std::string path = dir.file("s.mqs");
  const CellId a = cell("N0123012"), b = cell("N0123013"), c = cell("P3000000");
  const CellId coarse = cell("N012301"), coarser = cell("N01230");
  std::map<CellId, InstancesContent> written = {{a, trees(40, 1)},
                                                {b, trees(3, 2)},
                                                {c, trees(1000, 3)},
                                                {coarse, trees(10, 4)},
                                                {coarser, trees(2, 5)}};
  std::map<CellId, std::string> blobs;
  for (const auto& [k, v] : written) blobs[k] = wrap_instances(v);
  {
    auto store = Store::open(path, Store::Mode::Create);
    store->create_layer(content_layer("trees", LayerKind::Instances, 7));
    Store::Batch batch(*store);
    for (const auto& [k, blob] : blobs) batch.put_content("trees", k, blob);
    EXPECT_TRUE(store->content_cells("trees").empty());  // not before the commit
    batch.commit();
  }
  auto store = Store::open(path, Store::Mode::ReadOnly);
  EXPECT_TRUE(store->integrity_ok());
  for (const auto& [k, blob] : blobs) {
    const auto got = store->get_content("trees", k);
    ASSERT_TRUE(got.has_value()) << k.ToText();
    EXPECT_EQ(*got, blob) << k.ToText();
    const InstancesContent back = unwrap_instances(*got, "test");
    EXPECT_EQ(back.origin, written[k].origin);
    EXPECT_EQ(back.position, written[k].position);
    EXPECT_EQ(back.provenance, written[k].provenance);
  }
  EXPECT_FALSE(store->get_content("trees", cell("N0123010")).has_value());
  EXPECT_FALSE(store->get_content("trees", cell("N012300")).has_value());
  EXPECT_EQ(store->content_cells("trees"), (std::vector<CellId>{a, b, c}));
  EXPECT_EQ(store->content_cells("trees", 7, coarser.range_min(), coarser.range_max()),
            (std::vector<CellId>{a, b}));
  EXPECT_EQ(store->content_cells("trees", 6), std::vector<CellId>{coarse});
  EXPECT_EQ(store->content_cells("trees", 5), std::vector<CellId>{coarser});
  EXPECT_TRUE(store->content_cells("trees", 0).empty());
  expect_error([&] { store->content_cells("trees", 8); }, {"no level 8", "levels 0 to 7"});
  expect_error([&] { store->get_content("trees", cell("N01230120")); },
               {"layer 'trees'", "N01230120", "level 7 and the coarser ones"});

  const ContentLayerStats st = store->content_stats("trees");
  EXPECT_EQ(st.cells, 3);
  EXPECT_EQ(st.content.objects, 40u + 3u + 1000u);  // the layer's level only
  EXPECT_EQ(st.content.triangles, 0u);
  EXPECT_EQ(st.content.voxels, 0u);
  int64_t bytes = 0;
  for (const auto& [k, blob] : blobs) bytes += int64_t(blob.size());
  EXPECT_EQ(st.bytes, bytes);
  const LayerStats layer = store->stats("trees");
  EXPECT_EQ(layer.tile_count, 3);
  EXPECT_EQ(layer.bytes, bytes);
  EXPECT_EQ(layer.levels, (std::vector<int>{5, 6, 7}));
}

TEST(StoreContent, ARewrittenCellHoldsTheNewBlob) {
  TempDir dir;
  auto store = Store::open(dir.file("s.mqs"), Store::Mode::Create);
  store->create_layer(content_layer("trees", LayerKind::Instances, 7));
  const CellId a = cell("S0000000");
  Store::Batch first(*store);
  first.put_content("trees", a, wrap_instances(trees(5, 1)));
  first.commit();
  Store::Batch second(*store);
  second.put_content("trees", a, wrap_instances(trees(7, 2)));
  second.commit();
  EXPECT_EQ(*store->get_content("trees", a), wrap_instances(trees(7, 2)));
  EXPECT_EQ(store->content_stats("trees").content.objects, 7u);
  EXPECT_EQ(store->content_stats("trees").cells, 1);
}

// A blob of many parts replaced by a short one leaves none of its parts; removing a cell's content
// leaves nothing of it and marks its parent stale, like a write; removing what is not there is no
// change.
TEST(StoreContent, RewrittenAndRemovedCellsLeaveNoParts) {
  TempDir dir;
  const std::string path = dir.file("s.mqs");
  auto store = Store::open(path, Store::Mode::Create);
  store->create_layer(content_layer("trees", LayerKind::Instances, 7));
  const CellId a = cell("S0000000"), b = cell("S0000001"), parent = cell("S000000");
  const std::string big = wrap_instances(trees(1000, 1)), small = wrap_instances(trees(2, 2));
  ASSERT_GT(big.size(), 8 * small.size());
  {
    Store::Batch batch(*store);
    batch.put_content("trees", a, big);
    batch.put_content("trees", b, big);
    batch.commit();
  }
  const auto rebuild =
      [&] {  // the stale cells at level 6 with their children, as the builder sees them
        std::vector<std::pair<CellId, Store::ContentChildren>> seen;
        store->rebuild_stale_content(
            "trees", 6, 64,
            [&](std::span<const CellId> cells, std::span<const Store::ContentChildren> children,
                std::span<std::optional<std::string>> overviews) {
              for (size_t i = 0; i < cells.size(); ++i) {
                seen.emplace_back(cells[i], children[i]);
                for (const auto& child : children[i])
                  if (child) overviews[i] = *child;  // any blob of the layer's kind will do
              }
            });
        return seen;
      };
  ASSERT_EQ(rebuild().size(), 1u);
  EXPECT_TRUE(store->get_content("trees", parent).has_value());
  {
    Store::Batch batch(*store);
    batch.put_content("trees", a, small);
    batch.remove_content("trees", b);
    batch.remove_content("trees", cell("S0000002"));  // holds nothing: no change
    batch.commit();
  }
  EXPECT_EQ(*store->get_content("trees", a), small);
  EXPECT_FALSE(store->get_content("trees", b).has_value());
  EXPECT_EQ(store->content_cells("trees"), std::vector<CellId>{a});
  EXPECT_EQ(store->content_stats("trees").bytes,
            int64_t(small.size()) + int64_t(store->get_content("trees", parent)->size()));
  const auto seen = rebuild();
  ASSERT_EQ(seen.size(), 1u);
  EXPECT_EQ(seen[0].first, parent);
  EXPECT_EQ(seen[0].second[a.digit(7)], small);
  EXPECT_FALSE(seen[0].second[b.digit(7)].has_value());
  {
    Store::Batch batch(*store);
    batch.remove_content("trees", a);
    batch.commit();
  }
  EXPECT_EQ(rebuild().size(), 1u);  // its parent was marked: its overview goes
  EXPECT_TRUE(store->content_cells("trees", 6).empty());
  EXPECT_EQ(store->content_stats("trees").bytes, 0);
  EXPECT_EQ(raw_int(path, "SELECT count(*) FROM content"), 0);
  expect_error([&] { Store::Batch(*store).remove_content("trees", cell("S00000000")); },
               {"cannot remove content of layer 'trees'", "S00000000", "level 7"});
}

TEST(StoreContent, StatsComeFromTheHeadersWithoutDecoding) {
  TempDir dir;
  const std::string path = dir.file("s.mqs");
  auto store = Store::open(path, Store::Mode::Create);
  store->create_layer(content_layer("buildings", LayerKind::Mesh, 9));
  store->create_layer(content_layer("water", LayerKind::Volume, 9));
  {
    Store::Batch batch(*store);
    // Payloads of 200 kB that are no GLB: the store neither decodes nor needs them.
    batch.put_content("buildings", cell("R012301230"),
                      opaque_blob(ContentKind::Mesh, {12, 3400, 0}, 200000));
    batch.put_content("buildings", cell("R012301231"),
                      opaque_blob(ContentKind::Mesh, {3, 60, 0}, 10));
    batch.put_content("buildings", cell("R01230123"),
                      opaque_blob(ContentKind::Mesh, {15, 900, 0}, 10));
    batch.put_content("water", cell("R012301231"),
                      opaque_blob(ContentKind::Volume, {2, 0, 123456789012}, 7));
    batch.commit();
  }
  ContentLayerStats st = store->content_stats("buildings");
  EXPECT_EQ(st.content, (ContentStats{15, 3460, 0}));
  EXPECT_EQ(st.cells, 2);
  EXPECT_EQ(st.bytes, 64 * 3 + 200000 + 10 + 10);
  EXPECT_EQ(store->content_stats("water").content, (ContentStats{2, 0, 123456789012}));
  // A damaged payload changes nothing the headers say.
  const CellId a = cell("R012301230"), b = cell("R012301231");
  std::string damaged = *store->get_content("buildings", a);
  std::fill(damaged.begin() + 64, damaged.end(), '\0');
  set_blob(path, "buildings", a, damaged);
  st = store->content_stats("buildings");
  EXPECT_EQ(st.content, (ContentStats{15, 3460, 0}));
  EXPECT_EQ(st.bytes, 64 * 3 + 200000 + 10 + 10);
  // A damaged header is named, with the layer and the cell, by every reader of it.
  damaged = *store->get_content("buildings", b);
  damaged[0] = '\0';
  set_blob(path, "buildings", b, damaged);
  expect_error([&] { store->content_stats("buildings"); },
               {"corrupt content blob", "layer 'buildings'", "R012301231", path, "no MQCT magic"});
  expect_error([&] { store->get_content("buildings", b); },
               {"corrupt content blob", "layer 'buildings'", "R012301231", "no MQCT magic"});
  raw_sql(path, "DELETE FROM content WHERE part > 0 AND cell = " + std::to_string(a.id()) +
                    "; UPDATE content SET data = substr(data, 1, 70) WHERE cell = " +
                    std::to_string(a.id()));
  expect_error([&] { store->get_content("buildings", cell("R012301230")); },
               {"header says 200000 payload bytes, the blob holds 6"});
}

TEST(StoreContent, WrongKindsAreRefusedAndNothingIsStored) {
  TempDir dir;
  const std::string path = dir.file("s.mqs");
  auto store = Store::open(path, Store::Mode::Create);
  store->create_layer(content_layer("trees", LayerKind::Instances, 7));
  store->create_layer(dem_layer(16));
  const CellId a = cell("Q0120120"), b = cell("Q0120121");
  const std::string good = wrap_instances(trees(4, 9));
  const int64_t run = store->begin_run({{"step", "trees"}});
  try {
    Store::Batch batch(*store);
    batch.put_content("trees", a, good);
    batch.mark_done(run, 0, a);
    batch.put_content("trees", b, opaque_blob(ContentKind::Mesh, {1, 12, 0}, 5));
    batch.commit();
    ADD_FAILURE() << "a mesh blob went into an instances layer";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), "cannot write content of layer 'trees' at cell Q0120121 in " +
                                         path +
                                         ": the blob holds mesh content, the layer instances");
  }
  EXPECT_TRUE(store->content_cells("trees").empty());
  EXPECT_TRUE(store->done_cells(run, 0).empty());

  Store::Batch batch(*store);
  expect_error([&] { batch.put_content("dem", a, good); },
               {"layer 'dem'", path, "is of kind raster, not a content layer"});
  expect_error([&] { batch.put_content("trees", a.child(0), good); },
               {"layer 'trees'", "Q01201200", "level 7 and the coarser ones"});
  expect_error([&] { batch.put_content("trees", a, good.substr(0, good.size() - 1)); },
               {"corrupt content blob", "layer 'trees', cell Q0120120", "payload bytes"});
  expect_error([&] { batch.put_content("trees", a, "not a blob"); },
               {"corrupt content blob", "shorter than its 64-byte header"});
  expect_error([&] { batch.put_content("nope", a, good); }, {"unknown layer 'nope'"});
  batch.commit();
  EXPECT_TRUE(store->content_cells("trees").empty());
  EXPECT_EQ(store->content_stats("trees").cells, 0);

  // Raster calls on a content layer, and content calls on a raster one, say what the layer is.
  expect_error([&] { store->put_tile("trees", a, test::smooth_tile(1)); },
               {"layer 'trees'", "it holds instances content (put_content)"});
  Store::Batch write(*store);
  write.put_content("trees", a, good);
  write.commit();
  expect_error([&] { store->get_tile("trees", a); },
               {"layer 'trees'", path, "holds instances content (get_content), not raster tiles"});
  expect_error([&] { store->scan("trees", a, a, [](CellId, const RawTile&) {}); },
               {"holds instances content"});
  expect_error([&] { store->get_overview("trees", a.parent()); }, {"holds instances content"});
  expect_error([&] { store->update_overviews("trees"); },
               {"layer 'trees'", "hold what its writer simplified"});
  for (const auto& read : std::vector<std::function<void()>>{[&] { store->get_content("dem", a); },
                                                             [&] { store->content_cells("dem"); },
                                                             [&] { store->content_stats("dem"); }})
    expect_error(read, {"layer 'dem'", "is of kind raster, not a content layer"});
  EXPECT_EQ(*store->get_content("trees", a), good);
  // A blob of another kind put there behind the store's back is named by its readers.
  set_blob(path, "trees", a, opaque_blob(ContentKind::Volume, {1, 0, 8}, 3));
  for (const auto& read : std::vector<std::function<void()>>{
           [&] { store->get_content("trees", a); }, [&] { store->content_stats("trees"); }})
    expect_error(read, {"corrupt content blob (layer 'trees', cell Q0120120, in " + path,
                        "it holds volume content, the layer instances"});
}

// A store of schema version 3 (content and model blobs in tiles and overviews; made here from a
// new store's layers with raw SQL) is read as it is by a read-only open, which leaves it version
// 3, and upgraded to version 4 when opened for writing: the same blobs, now in parts of the
// content table, none left in tiles and overviews, raster tiles untouched.
TEST(StoreContent, Version3StoresAreReadAndUpgradedWhenOpenedForWriting) {
  TempDir dir;
  const std::string path = dir.file("s.mqs");
  const CellId a = cell("N0123012"), coarse = cell("N012301");
  const std::string base = wrap_instances(trees(400, 1)), overview = wrap_instances(trees(100, 2));
  const std::string model = wrap_content(ContentEnvelope{}, std::string(5000, 'g'));  // a mesh
  {
    auto store = Store::open(path, Store::Mode::Create);
    store->create_layer(content_layer("trees", LayerKind::Instances, 7));
    store->create_layer(dem_layer(2));
    store->put_tile("dem", a, test::raw_tile<float>(2, 1, {1, 2, 3, 4}));
    Store::Batch batch(*store);
    batch.put_model("oak", model);  // its layer row is kept, its blob goes with the table
    batch.commit();
  }
  raw_sql(path, "DROP TABLE content; PRAGMA user_version = 3");
  raw_blob_sql(path,
               "INSERT INTO tiles(layer, cell, blob) SELECT id, ?2, ?1 FROM layers WHERE name = ?3",
               base, a, "trees");
  raw_blob_sql(path,
               "INSERT INTO overviews(layer, level, cell, blob) SELECT id, 6, ?2, ?1 FROM layers "
               "WHERE name = ?3",
               overview, coarse, "trees");
  raw_blob_sql(path,
               "INSERT INTO tiles(layer, cell, blob) SELECT id, ?2, ?1 FROM layers WHERE name = ?3",
               model, CellId(0), "oak");

  const auto check = [&](const Store& store) {
    EXPECT_EQ(store.get_content("trees", a), base);
    EXPECT_EQ(store.get_content("trees", coarse), overview);
    EXPECT_EQ(store.content_cells("trees"), std::vector<CellId>{a});
    EXPECT_EQ(store.content_cells("trees", 6), std::vector<CellId>{coarse});
    EXPECT_EQ(store.content_stats("trees").content.objects, 400u);
    EXPECT_EQ(store.content_stats("trees").bytes, int64_t(base.size() + overview.size()));
    EXPECT_EQ(store.stats("trees").levels, (std::vector<int>{6, 7}));
    EXPECT_EQ(store.stats("oak").tile_count, 1);
    EXPECT_EQ(store.get_model("oak"), model);
    EXPECT_EQ(test::values_of<float>(*store.get_tile("dem", a)), (std::vector<float>{1, 2, 3, 4}));
  };
  check(*Store::open(path, Store::Mode::ReadOnly));
  EXPECT_EQ(raw_int(path, "PRAGMA user_version"), 3);  // reading changes nothing
  {
    const auto store = Store::open(path, Store::Mode::ReadWrite);
    EXPECT_TRUE(store->integrity_ok());
    check(*store);
  }
  EXPECT_EQ(raw_int(path, "PRAGMA user_version"), 4);
  EXPECT_EQ(raw_int(path, "SELECT count(*) FROM tiles"), 1);  // the dem's tile alone
  EXPECT_EQ(raw_int(path, "SELECT count(*) FROM overviews"), 0);
  EXPECT_GT(raw_int(path, "SELECT count(*) FROM content WHERE part > 0"), 2);  // in parts now
  check(*Store::open(path, Store::Mode::ReadOnly));
}

// Version 4 came with model layers: a store holding one is version 4, so a Maquette that reads
// up to version 3 refuses it as a newer store before it meets the layer kind it does not know,
// as this one refuses a store of version 5.
TEST(StoreContent, StoresWithModelsAreVersion4AndNewerOnesAreRefused) {
  TempDir dir;
  const std::string path = dir.file("s.mqs");
  {
    auto store = Store::open(path, Store::Mode::Create);
    Store::Batch batch(*store);
    batch.put_model("oak", wrap_content(ContentEnvelope{}, "glb"));
    batch.commit();
  }
  EXPECT_EQ(raw_int(path, "PRAGMA user_version"), 4);
  raw_sql(path, "PRAGMA user_version = 5");
  for (const auto mode : {Store::Mode::ReadOnly, Store::Mode::ReadWrite})
    expect_error([&] { Store::open(path, mode); },
                 {path, "is a newer store (schema version 5)", "reads up to version 4"});
}

}  // namespace
}  // namespace maquette
