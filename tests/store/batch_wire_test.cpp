// Batch::serialize and add_serialized (`maquette run --store-copies`): a batch made on one store
// and committed to another whose layers have other row ids gives the same stored blobs, the
// overview the batch built, the artifact and the run records; bytes naming a layer the store
// lacks, or that are no batch, are refused naming the layer or saying what they are not; content
// put and removed and partial overviews pass too.
#include "content/content_blob.h"
#include "store/store.h"
#include "store_test_util.h"

namespace maquette {
namespace {

LayerInfo raster(const std::string& name) {
  LayerInfo l;
  l.name = name;
  l.tile_size = 16;
  l.level = 3;
  return l;
}

// The stored blob bytes of a layer's tiles and overviews, read behind the store's back.
int64_t blob_bytes(const std::string& path, const std::string& layer) {
  const std::string id = "(SELECT id FROM layers WHERE name = '" + layer + "')";
  return test::raw_int(path, "SELECT sum(length(blob)) FROM tiles WHERE layer = " + id) +
         1000000 * test::raw_int(path, "SELECT count(*) FROM overviews WHERE layer = " + id);
}

TEST(BatchWire, AnotherStoreCommitsTheSameWrites) {
  test::TempDir dir;
  const std::string from_path = dir.file("from.mqt"), to_path = dir.file("to.mqt");
  auto from = Store::open(from_path, Store::Mode::Create);
  auto to = Store::open(to_path, Store::Mode::Create);
  from->create_layer(raster("other"));  // "dem" gets another row id in each store
  from->create_layer(raster("dem"));
  to->create_layer(raster("dem"));
  const CellId parent = *CellId::FromText("Q12");
  const int64_t run = from->begin_run({{"p", 1}});

  Store::Batch batch(*from);
  for (int k = 0; k < 4; ++k) {  // all four children: the batch builds the parent's overview
    batch.put_tile("dem", parent.child(k), test::smooth_tile(16, float(k)));
    batch.mark_done(run, 2, parent.child(k));
  }
  batch.put_artifact(Artifact::FromText("fit", "{\"a\": 1}"));
  const std::string bytes = batch.serialize();
  batch.commit();

  Store::Batch copy(*to);
  copy.add_serialized(bytes);
  copy.commit();
  for (int k = 0; k < 4; ++k)
    EXPECT_EQ(to->get_tile("dem", parent.child(k))->bytes,
              from->get_tile("dem", parent.child(k))->bytes);
  ASSERT_TRUE(to->get_overview("dem", parent));
  EXPECT_EQ(to->get_overview("dem", parent)->bytes, from->get_overview("dem", parent)->bytes);
  EXPECT_GT(blob_bytes(from_path, "dem"), 1000000);
  EXPECT_EQ(blob_bytes(to_path, "dem"), blob_bytes(from_path, "dem"));
  EXPECT_EQ(to->get_artifact("fit")->text(), "{\"a\": 1}");
  EXPECT_EQ(to->done_cells(run, 2), from->done_cells(run, 2));
  EXPECT_EQ(to->done_cells(run, 2).size(), 4u);
}

// Content put and removed, and an overview built from 2 of its 4 children (written because the
// store holds no other child), pass too: the other store ends with the same content blobs and
// overview bytes.
TEST(BatchWire, ContentRemovalAndPartialOverviewsPassToo) {
  test::TempDir dir;
  auto from = Store::open(dir.file("from.mqt"), Store::Mode::Create);
  auto to = Store::open(dir.file("to.mqt"), Store::Mode::Create);
  LayerInfo trees;
  trees.name = "trees";
  trees.kind = LayerKind::Instances;
  trees.level = 3;
  from->create_layer(raster("other"));
  for (Store* store : {from.get(), to.get()}) {
    store->create_layer(raster("dem"));
    store->create_layer(trees);
  }
  const CellId parent = *CellId::FromText("Q12");
  const auto blob = [](double lon) {  // an envelope the store keeps as it is
    ContentEnvelope e;
    e.kind = ContentKind::Instances;
    e.origin = {lon, 10, 0};
    return wrap_content(e, std::string(100, '\x5a'));
  };
  // Both stores take each batch: it is committed on one and its bytes on the other.
  const auto pass = [&](Store::Batch& batch) {
    const std::string bytes = batch.serialize();
    batch.commit();
    Store::Batch copy(*to);
    copy.add_serialized(bytes);
    copy.commit();
  };
  {
    Store::Batch batch(*from);
    for (int k : {1, 2}) batch.put_tile("dem", parent.child(k), test::smooth_tile(16, float(k)));
    batch.put_parent_overview("dem", parent);
    batch.put_content("trees", parent.child(0), blob(1));
    batch.put_content("trees", parent.child(3), blob(2));
    pass(batch);
  }
  {
    Store::Batch batch(*from);
    batch.remove_content("trees", parent.child(3));
    pass(batch);
  }
  ASSERT_TRUE(from->get_overview("dem", parent));
  ASSERT_TRUE(to->get_overview("dem", parent));
  EXPECT_EQ(to->get_overview("dem", parent)->bytes, from->get_overview("dem", parent)->bytes);
  EXPECT_EQ(to->get_content("trees", parent.child(0)), blob(1));
  EXPECT_FALSE(from->get_content("trees", parent.child(3)));
  EXPECT_FALSE(to->get_content("trees", parent.child(3)));
}

TEST(BatchWire, UnknownLayerAndGarbageAreRefused) {
  test::TempDir dir;
  auto from = Store::open(dir.file("from.mqt"), Store::Mode::Create);
  auto to = Store::open(dir.file("to.mqt"), Store::Mode::Create);
  from->create_layer(raster("dem"));
  Store::Batch batch(*from);
  batch.put_tile("dem", *CellId::FromText("Q123"), test::smooth_tile(16));
  const std::string bytes = batch.serialize();

  Store::Batch copy(*to);
  test::expect_error([&] { copy.add_serialized(bytes); }, {"unknown layer 'dem'"});
  test::expect_error([&] { copy.add_serialized("not cbor"); },
                     {"not a serialized batch", "to.mqt"});
}

}  // namespace
}  // namespace maquette
