// Overview pyramids: hand-computed means and modes with nodata, and rebuilding only what a
// write made stale.
#include <sqlite3.h>

#include <cmath>

#include "core/error.h"
#include "store/codec.h"
#include "store/store.h"
#include "store_test_util.h"

namespace maquette {
namespace {

using test::raw_tile;
using test::TempDir;
using test::values_of;

CellId cell(std::string_view text) { return *CellId::FromText(text); }

LayerInfo layer(std::string name, DType dtype, Semantics semantics, int level,
                std::optional<double> nodata) {
  LayerInfo l;
  l.name = std::move(name);
  l.dtype = dtype;
  l.tile_size = 2;
  l.level = level;
  l.semantics = semantics;
  l.nodata = nodata;
  return l;
}

// Layer at level 1 with 2x2 tiles: the overview tile of face Q has one sample per child,
// sample (col, row) coming from child digit 2 * row + col.
TEST(Overviews, MeanOfValidSamples) {
  TempDir dir;
  auto store = Store::open(dir.file("s.mqs"), Store::Mode::Create);
  store->create_layer(layer("dem", DType::F32, Semantics::Continuous, 1, -9999));
  store->put_tile("dem", cell("Q0"), raw_tile<float>(2, 1, {1, 2, 3, 4}));          // mean 2.5
  store->put_tile("dem", cell("Q1"), raw_tile<float>(2, 1, {10, -9999, NAN, 20}));  // 15
  store->put_tile("dem", cell("Q2"), raw_tile<float>(2, 1, {-9999, -9999, NAN, -9999}));
  // Q3 has no tile: its quadrant is nodata.
  store->update_overviews("dem");
  const auto overview = store->get_overview("dem", cell("Q"));
  ASSERT_TRUE(overview);
  EXPECT_EQ(values_of<float>(*overview), (std::vector<float>{2.5f, 15, -9999, -9999}));
  EXPECT_EQ(store->stats("dem").levels, (std::vector<int>{0, 1}));
  EXPECT_FALSE(store->get_overview("dem", cell("N")));
  EXPECT_THROW(store->get_overview("dem", cell("Q0")), Error);  // base level, not an overview
}

TEST(Overviews, MeanRoundsForIntegersAndUsesNaNWithoutNodata) {
  TempDir dir;
  auto store = Store::open(dir.file("s.mqs"), Store::Mode::Create);
  store->create_layer(layer("counts", DType::U16, Semantics::Continuous, 1, std::nullopt));
  store->put_tile("counts", cell("S3"), raw_tile<uint16_t>(2, 1, {1, 2, 2, 2}));  // 1.75 -> 2
  store->create_layer(layer("temp", DType::F64, Semantics::Continuous, 1, std::nullopt));
  store->put_tile("temp", cell("S0"), raw_tile<double>(2, 1, {NAN, NAN, NAN, 1.5}));
  store->update_overviews("counts");
  store->update_overviews("temp");
  EXPECT_EQ(values_of<uint16_t>(*store->get_overview("counts", cell("S"))),
            (std::vector<uint16_t>{0, 0, 0, 2}));
  const auto temp = values_of<double>(*store->get_overview("temp", cell("S")));
  EXPECT_EQ(temp[0], 1.5);
  EXPECT_TRUE(std::isnan(temp[1]) && std::isnan(temp[2]) && std::isnan(temp[3]));
}

TEST(Overviews, ModeWithTiesToTheSmallest) {
  TempDir dir;
  auto store = Store::open(dir.file("s.mqs"), Store::Mode::Create);
  store->create_layer(layer("classes", DType::U8, Semantics::Categorical, 1, 0));
  store->put_tile("classes", cell("N0"), raw_tile<uint8_t>(2, 1, {5, 3, 5, 7}));  // 5
  store->put_tile("classes", cell("N1"), raw_tile<uint8_t>(2, 1, {9, 4, 4, 9}));  // tie: 4
  store->put_tile("classes", cell("N2"), raw_tile<uint8_t>(2, 1, {0, 0, 0, 8}));  // nodata: 8
  store->put_tile("classes", cell("N3"), raw_tile<uint8_t>(2, 1, {0, 6, 0, 6}));  // 6
  store->update_overviews("classes");
  EXPECT_EQ(values_of<uint8_t>(*store->get_overview("classes", cell("N"))),
            (std::vector<uint8_t>{5, 4, 8, 6}));
}

TEST(Overviews, InterleavedChannelsReduceSeparately) {
  TempDir dir;
  auto store = Store::open(dir.file("s.mqs"), Store::Mode::Create);
  LayerInfo rgb = layer("rgb", DType::U8, Semantics::Continuous, 1, std::nullopt);
  rgb.channels = 2;
  store->create_layer(rgb);
  store->put_tile("rgb", cell("O0"), raw_tile<uint8_t>(2, 2, {10, 100, 20, 100, 30, 200, 40, 201}));
  store->update_overviews("rgb");
  EXPECT_EQ(values_of<uint8_t>(*store->get_overview("rgb", cell("O"))),
            (std::vector<uint8_t>{25, 150, 0, 0, 0, 0, 0, 0}));  // 150.25 -> 150
}

// Replaces the stored overview tile of `cell` behind the store's back, so that the test can
// tell whether update_overviews rebuilt it.
void plant_overview(const std::string& path, CellId cell, const RawTile& tile) {
  const auto blob = encode_tile(tile, parse_codec("raw"));
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
  sqlite3_stmt* st = nullptr;
  sqlite3_prepare_v2(db, "UPDATE overviews SET blob = ? WHERE level = ? AND cell = ?", -1, &st,
                     nullptr);
  sqlite3_bind_blob(st, 1, blob.data(), int(blob.size()), SQLITE_TRANSIENT);
  sqlite3_bind_int(st, 2, cell.level());
  sqlite3_bind_int64(st, 3, int64_t(cell.id()));
  EXPECT_EQ(sqlite3_step(st), SQLITE_DONE);
  EXPECT_EQ(sqlite3_changes(db), 1);
  sqlite3_finalize(st);
  sqlite3_close(db);
}

TEST(Overviews, RebuildsOnlyStaleAncestors) {
  TempDir dir;
  const std::string path = dir.file("s.mqs");
  auto store = Store::open(path, Store::Mode::Create);
  store->create_layer(layer("dem", DType::F32, Semantics::Continuous, 2, std::nullopt));
  // Every level-2 cell of face Q holds a constant tile: 10 * child digit + grandchild digit.
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) {
      const float v = float(10 * a + b);
      store->put_tile("dem", cell("Q").child(a).child(b), raw_tile<float>(2, 1, {v, v, v, v}));
    }
  store->update_overviews("dem", 1);  // level 1 only: Q stays stale for now
  EXPECT_FALSE(store->get_overview("dem", cell("Q")));
  EXPECT_EQ(values_of<float>(*store->get_overview("dem", cell("Q2"))),
            (std::vector<float>{20, 21, 22, 23}));
  store->update_overviews("dem");
  EXPECT_EQ(values_of<float>(*store->get_overview("dem", cell("Q"))),
            (std::vector<float>{1.5f, 11.5f, 21.5f, 31.5f}));

  // Plant marker values in the overviews of Q1 and Q, then change one tile under Q2: only
  // Q2 and Q are rebuilt; Q1 keeps its marker, and Q is rebuilt from it.
  plant_overview(path, cell("Q1"), raw_tile<float>(2, 1, {100, 100, 100, 100}));
  plant_overview(path, cell("Q"), raw_tile<float>(2, 1, {-1, -1, -1, -1}));
  store->put_tile("dem", cell("Q23"), raw_tile<float>(2, 1, {40, 40, 40, 40}));
  store->update_overviews("dem");
  EXPECT_EQ(values_of<float>(*store->get_overview("dem", cell("Q1"))),
            (std::vector<float>{100, 100, 100, 100}));
  EXPECT_EQ(values_of<float>(*store->get_overview("dem", cell("Q2"))),
            (std::vector<float>{20, 21, 22, 40}));
  EXPECT_EQ(values_of<float>(*store->get_overview("dem", cell("Q"))),
            (std::vector<float>{1.5f, 100, 25.75f, 31.5f}));

  // Nothing stale: nothing changes.
  plant_overview(path, cell("Q"), raw_tile<float>(2, 1, {-1, -1, -1, -1}));
  store->update_overviews("dem");
  EXPECT_EQ(values_of<float>(*store->get_overview("dem", cell("Q"))),
            (std::vector<float>{-1, -1, -1, -1}));
  const LayerStats s = store->stats("dem");
  EXPECT_EQ(s.tile_count, 16);
  EXPECT_EQ(s.levels, (std::vector<int>{0, 1, 2}));
}

// A batch holding all four children of a parent writes the parent's overview (hand-computed
// means) and marks the grandparent stale, with no update_overviews; a batch with three of them
// leaves the parent stale, and its overview to update_overviews.
TEST(Overviews, BatchOfAllFourChildrenWritesTheirParent) {
  TempDir dir;
  auto store = Store::open(dir.file("s.mqs"), Store::Mode::Create);
  store->create_layer(layer("dem", DType::F32, Semantics::Continuous, 2, std::nullopt));
  const auto put_children = [&](CellId parent, int count) {
    Store::Batch batch(*store);
    for (int d = 0; d < count; ++d) {
      const float v = float(10 * parent.digit(1) + d);
      batch.put_tile("dem", parent.child(d), raw_tile<float>(2, 1, {v, v + 1, v + 2, NAN}));
    }
    batch.commit();
  };
  put_children(cell("Q2"), 4);
  put_children(cell("Q3"), 3);
  // Q2's overview is there before any update: per child, the mean of v, v + 1, v + 2 = v + 1.
  EXPECT_EQ(values_of<float>(*store->get_overview("dem", cell("Q2"))),
            (std::vector<float>{21, 22, 23, 24}));
  EXPECT_FALSE(store->get_overview("dem", cell("Q3")));
  store->update_overviews("dem");
  const std::vector<float> q3 = values_of<float>(*store->get_overview("dem", cell("Q3")));
  EXPECT_EQ(q3[0], 31);
  EXPECT_EQ(q3[2], 33);
  EXPECT_TRUE(std::isnan(q3[3]));  // Q33 has no tile
  // Q was stale from both batches: its Q2 and Q3 quadrants are the means of those overviews.
  const std::vector<float> q = values_of<float>(*store->get_overview("dem", cell("Q")));
  EXPECT_EQ(q[2], 22.5f);
  EXPECT_EQ(q[3], 32);  // NaN of Q33 left out
}

// put_parent_overview: a batch with two children of Q1 writes Q1's overview at commit
// (hand-computed means, nodata for the missing quadrants, no update_overviews). For Q2, whose
// child Q20 an earlier batch stored, it does not: Q2 stays stale and update_overviews builds it
// from all three children.
TEST(Overviews, BatchWritesTheParentOfFewerChildrenWhenNoOtherIsStored) {
  TempDir dir;
  auto store = Store::open(dir.file("s.mqs"), Store::Mode::Create);
  store->create_layer(layer("dem", DType::F32, Semantics::Continuous, 2, -9999));
  const auto put = [&](CellId parent, std::vector<int> digits) {
    Store::Batch batch(*store);
    for (int d : digits) {
      const float v = float(10 * parent.digit(1) + d);
      batch.put_tile("dem", parent.child(d), raw_tile<float>(2, 1, {v, v, v + 2, v + 2}));
    }
    batch.put_parent_overview("dem", parent);
    batch.commit();
  };
  put(cell("Q1"), {0, 3});
  EXPECT_EQ(values_of<float>(*store->get_overview("dem", cell("Q1"))),
            (std::vector<float>{11, -9999, -9999, 14}));
  put(cell("Q2"), {0});
  put(cell("Q2"), {1, 2});  // Q20 is stored already: this batch's overview is not written
  EXPECT_EQ(values_of<float>(*store->get_overview("dem", cell("Q2"))),
            (std::vector<float>{21, -9999, -9999, -9999}));  // the first batch's
  store->update_overviews("dem");
  EXPECT_EQ(values_of<float>(*store->get_overview("dem", cell("Q2"))),
            (std::vector<float>{21, 22, 23, -9999}));
  EXPECT_EQ(values_of<float>(*store->get_overview("dem", cell("Q1"))),
            (std::vector<float>{11, -9999, -9999, 14}));
}

TEST(Overviews, BadArguments) {
  TempDir dir;
  auto store = Store::open(dir.file("s.mqs"), Store::Mode::Create);
  store->create_layer(layer("dem", DType::F32, Semantics::Continuous, 2, std::nullopt));
  EXPECT_THROW(store->update_overviews("dem", 3), Error);
  EXPECT_THROW(store->update_overviews("dem", -1), Error);
  EXPECT_THROW(store->update_overviews("none"), Error);
  EXPECT_NO_THROW(store->update_overviews("dem", 2));  // nothing to do
}

}  // namespace
}  // namespace maquette
