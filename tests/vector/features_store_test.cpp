// The store's features layers: stored once, indexed in every cell, range queries, stats,
// rewrites, and stores of schema version 1.
#include <sqlite3.h>

#include "core/grid.h"
#include "vector_test_util.h"

namespace maquette::test {
namespace {

LayerInfo features_layer(const std::string& name, int level) {
  LayerInfo l;
  l.name = name;
  l.kind = LayerKind::Features;
  l.dtype = DType::U8;
  l.tile_size = 1;
  l.level = level;
  l.codec = "raw";
  return l;
}

Feature feature(int64_t fid, const std::string& label) {
  return {fid, {std::byte(1), std::byte(fid)}, {{"label", label}}, {1, 2, 3, 4}};
}

// Four cells at level 6: the children of one level-5 cell, and one elsewhere.
struct Cells {
  CellId parent = default_grid().cell_from_point({10, 45}, 5);
  std::vector<CellId> children{parent.child(0), parent.child(1), parent.child(2), parent.child(3)};
  CellId far = default_grid().cell_from_point({-60, -20}, 6);
};

TEST(FeaturesStore, AFeatureCrossingCellsIsStoredOnceAndIndexedInEach) {
  TempDir dir;
  auto store = new_store(dir);
  store->create_layer(features_layer("f", 6));
  const Cells c;
  Store::Batch batch(*store);
  batch.put_feature("f", feature(7, "big"), c.children);
  batch.put_feature("f", feature(3, "small"), std::vector<CellId>{c.children[1], c.far});
  batch.commit();

  EXPECT_EQ(store->feature_count("f"), 2);
  for (CellId cell : c.children) {
    const auto in = store->features_in("f", cell.range_min(), cell.range_max());
    ASSERT_FALSE(in.empty());
    EXPECT_EQ(in.back().fid, 7);
    EXPECT_EQ(in.back().attributes["label"], "big");
    EXPECT_EQ(in.back().wkb, (std::vector<std::byte>{std::byte(1), std::byte(7)}));
    EXPECT_EQ(in.back().bbox, (std::array<double, 4>{1, 2, 3, 4}));
  }
  // The parent's range holds both, each once, ordered by fid.
  const auto both = store->features_in("f", c.parent.range_min(), c.parent.range_max());
  ASSERT_EQ(both.size(), 2u);
  EXPECT_EQ(both[0].fid, 3);
  EXPECT_EQ(both[1].fid, 7);
  EXPECT_EQ(store->features_in("f", c.far.range_min(), c.far.range_max()).size(), 1u);
  EXPECT_EQ(store->feature_cells("f", 7), c.children);

  const LayerStats s = store->stats("f");
  EXPECT_EQ(s.feature_count, 2);
  EXPECT_EQ(s.tile_count, 5);  // distinct cells indexed
  EXPECT_EQ(s.levels, std::vector<int>{6});
  EXPECT_GT(s.bytes, 0);
  EXPECT_EQ(s.first, std::min(c.children.front(), c.far));
}

TEST(FeaturesStore, RewritingAFeatureReplacesItsIndexEntries) {
  TempDir dir;
  auto store = new_store(dir);
  store->create_layer(features_layer("f", 6));
  const Cells c;
  {
    Store::Batch batch(*store);
    batch.put_feature("f", feature(1, "old"), c.children);
    batch.commit();
  }
  Store::Batch batch(*store);
  batch.put_feature("f", feature(1, "new"), std::vector<CellId>{c.far});
  batch.commit();
  EXPECT_EQ(store->feature_count("f"), 1);
  EXPECT_TRUE(store->features_in("f", c.parent.range_min(), c.parent.range_max()).empty());
  const auto in = store->features_in("f", c.far.range_min(), c.far.range_max());
  ASSERT_EQ(in.size(), 1u);
  EXPECT_EQ(in[0].attributes["label"], "new");
  EXPECT_EQ(store->stats("f").tile_count, 1);
}

TEST(FeaturesStore, BadWritesAreRefused) {
  TempDir dir;
  auto store = new_store(dir);
  store->create_layer(features_layer("f", 6));
  LayerInfo raster;
  raster.name = "dem";
  raster.level = 6;
  store->create_layer(raster);
  const Cells c;
  Store::Batch batch(*store);
  expect_error([&] { batch.put_feature("f", feature(1, "x"), std::vector<CellId>{c.parent}); },
               {"feature 1", "layer 'f'", "level 6"});
  expect_error([&] { batch.put_feature("dem", feature(1, "x"), c.children); },
               {"'dem'", "not a features layer"});
  expect_error([&] { store->features_in("dem", c.parent.range_min(), c.parent.range_max()); },
               {"not a features layer"});
}

void raw_sql(const std::string& path, const char* sql) {
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
  EXPECT_EQ(sqlite3_exec(db, sql, nullptr, nullptr, nullptr), SQLITE_OK) << sqlite3_errmsg(db);
  sqlite3_close(db);
}

TEST(FeaturesStore, VersionOneStoresAreReadAndMigratedWhenWritten) {
  TempDir dir;
  const std::string path = dir.file("v1.mqt");
  new_store(dir, "v1.mqt")->put_artifact({"a", "text/plain", {std::byte('x')}, {}});
  raw_sql(path, "DROP TABLE features; DROP TABLE feature_cells; PRAGMA user_version = 1");

  EXPECT_EQ(Store::open(path, Store::Mode::ReadOnly)->artifact_names(),
            std::vector<std::string>{"a"});
  auto store = Store::open(path, Store::Mode::ReadWrite);
  store->create_layer(features_layer("f", 6));
  Store::Batch batch(*store);
  batch.put_feature("f", feature(1, "x"), Cells().children);
  batch.commit();
  EXPECT_EQ(store->feature_count("f"), 1);
  EXPECT_TRUE(store->integrity_ok());
}

}  // namespace
}  // namespace maquette::test
