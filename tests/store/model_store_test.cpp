// Model layers in the store (kind model): one mesh blob per layer, put (creating the layer) and
// replaced in one transaction, got back byte for byte, counted from the envelope and the GLB's
// JSON chunk; bad blobs, layers of other kinds and raster or cell-content calls refused with
// nothing stored, on real SQLite files.
#include <nlohmann/json.hpp>

#include "content/content_blob.h"
#include "json_glb.h"
#include "store/store.h"
#include "store_test_util.h"

namespace maquette {
namespace {

using nlohmann::json;
using test::expect_error;
using test::json_glb;
using test::raw_sql;
using test::TempDir;

// A model blob whose header counts `stats` and whose GLB declares `materials` materials (the
// store decodes no mesh, so the payload needs no geometry).
std::string model_blob(ContentStats stats, int materials, EnuOrigin origin = {},
                       ContentKind kind = ContentKind::Mesh) {
  ContentEnvelope e;
  e.kind = kind;
  e.origin = origin;
  e.stats = stats;
  json gltf = {{"asset", {{"version", "2.0"}}}, {"materials", json::array()}};
  for (int i = 0; i < materials; ++i) gltf["materials"].push_back({{"name", std::to_string(i)}});
  return wrap_content(e, json_glb(gltf));
}

LayerInfo raster_layer(const std::string& name) {
  LayerInfo l;
  l.name = name;
  l.level = 4;
  l.tile_size = 4;
  return l;
}

TEST(ModelStore, AModelIsPutGotCountedAndReplaced) {
  TempDir dir;
  const std::string path = dir.file("s.mqs");
  const std::string oak = model_blob({3, 120, 0}, 2), pine = model_blob({1, 36, 0}, 1);
  {
    auto store = Store::open(path, Store::Mode::Create);
    Store::Batch batch(*store);
    batch.put_model("oak", oak, {{"source", "oak.glb"}});
    EXPECT_FALSE(store->layer("oak"));  // nothing until the commit
    batch.commit();
  }
  auto store = Store::open(path, Store::Mode::ReadWrite);
  const LayerInfo l = store->require_layer("oak");
  EXPECT_EQ(l.kind, LayerKind::Model);
  EXPECT_EQ(l.level, 0);
  EXPECT_EQ(l.codec, "mqct");
  EXPECT_EQ(l.provenance, (json{{"source", "oak.glb"}}));
  EXPECT_EQ(store->get_model("oak"), oak);
  const ModelStats st = store->model_stats("oak");
  EXPECT_EQ(st.content, (ContentStats{3, 120, 0}));
  EXPECT_EQ(st.materials, 2);
  EXPECT_EQ(st.bytes, int64_t(oak.size()));
  EXPECT_EQ(store->stats("oak").tile_count, 1);
  EXPECT_EQ(store->stats("oak").bytes, int64_t(oak.size()));
  EXPECT_FALSE(store->get_model("birch"));
  expect_error([&] { store->model_stats("birch"); }, {"no model 'birch'"});

  {
    Store::Batch batch(*store);
    batch.put_model("oak", pine, {{"source", "pine.glb"}});
    batch.commit();
  }
  EXPECT_EQ(store->get_model("oak"), pine);
  EXPECT_EQ(store->require_layer("oak").provenance, (json{{"source", "pine.glb"}}));
  EXPECT_EQ(store->model_stats("oak").materials, 1);
  EXPECT_EQ(store->layers().size(), 1u);
  EXPECT_EQ(store->stats("oak").tile_count, 1);
  EXPECT_EQ(parse_layer_kind("model"), LayerKind::Model);
  EXPECT_FALSE(layer_content_kind(LayerKind::Model));
  EXPECT_TRUE(store->integrity_ok());
}

TEST(ModelStore, BadModelsAndOtherKindsAreRefusedWithNothingStored) {
  TempDir dir;
  auto store = Store::open(dir.file("s.mqs"), Store::Mode::Create);
  store->create_layer(raster_layer("dem"));
  const std::string oak = model_blob({3, 120, 0}, 2);
  {
    Store::Batch batch(*store);
    batch.put_model("oak", oak);
    batch.commit();
  }
  const auto refused = [&](const std::string& name, const std::string& blob,
                           std::initializer_list<std::string> parts) {
    expect_error(
        [&] {
          Store::Batch batch(*store);
          batch.put_model(name, blob);
          batch.commit();
        },
        parts);
  };
  refused("birch", model_blob({1, 12, 0}, 1, {2.35, 48.85, 35}), {"model 'birch'", "origin"});
  refused("birch", model_blob({1, 0, 0}, 0, {}, ContentKind::Instances),
          {"model 'birch'", "instances content, not a mesh"});
  refused("birch", oak.substr(0, oak.size() - 1), {"model 'birch'", "corrupt content blob"});
  refused("dem", oak, {"layer 'dem'", "is of kind raster, not a model"});
  refused("", oak, {"a model needs a name"});
  EXPECT_EQ(store->layers().size(), 2u);
  EXPECT_EQ(store->get_model("oak"), oak);
  expect_error([&] { store->get_model("dem"); }, {"layer 'dem'", "not a model"});

  // A model layer is no raster and no layer of cell content.
  const CellId cell = *CellId::FromText("N0123");
  expect_error([&] { store->get_tile("oak", cell); }, {"layer 'oak'", "model content (get_model)"});
  expect_error([&] { store->put_tile("oak", cell, test::smooth_tile(4)); },
               {"layer 'oak'", "model content (put_model)"});
  expect_error([&] { store->update_overviews("oak"); }, {"a model has no coarser levels"});
  expect_error([&] { store->get_content("oak", CellId::FromFace(0)); },
               {"layer 'oak'", "not a content layer"});
  expect_error([&] { store->content_stats("oak"); }, {"not a content layer"});

  // Asked for as a layer definition, a model layer is its name and kind alone.
  LayerInfo l;
  l.name = "oak";
  l.kind = LayerKind::Model;
  l.level = 9;
  l.dtype = DType::F64;
  store->create_layer(l);
  EXPECT_EQ(store->require_layer("oak").level, 0);
  EXPECT_EQ(store->get_model("oak"), oak);
}

TEST(ModelStore, ADamagedModelBlobIsNamed) {
  TempDir dir;
  const std::string path = dir.file("s.mqs");
  {
    auto store = Store::open(path, Store::Mode::Create);
    Store::Batch batch(*store);
    ContentEnvelope e;
    batch.put_model("rock", wrap_content(e, "not a glb, but the store decodes no payload"));
    batch.put_model("oak", model_blob({3, 120, 0}, 2));
    batch.commit();
    expect_error([&] { store->model_stats("rock"); }, {"model 'rock'", "its payload: not a GLB"});
  }
  raw_sql(path,
          "DELETE FROM content WHERE part > 0 AND layer = (SELECT id FROM layers WHERE name = "
          "'oak'); UPDATE content SET data = x'4d514354' WHERE layer = "
          "(SELECT id FROM layers WHERE name = 'oak')");
  auto store = Store::open(path, Store::Mode::ReadOnly);
  expect_error([&] { store->get_model("oak"); }, {"model 'oak'", path, "corrupt content blob"});
}

}  // namespace
}  // namespace maquette
