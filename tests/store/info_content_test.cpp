// `maquette info` (the real program) on a store with content layers: the cells, objects,
// triangles, instances, voxels and bytes that the blobs' headers hold, as text and as JSON.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "content/content_blob.h"
#include "content/instances_codec.h"
#include "run_cli.h"
#include "store/store.h"
#include "store_test_util.h"

namespace maquette {
namespace {

std::string mesh_blob(ContentStats stats, size_t payload_bytes) {
  ContentEnvelope e;
  e.kind = ContentKind::Mesh;
  e.origin = {7.44, 46.95, 540};
  e.stats = stats;
  return wrap_content(e, std::string(payload_bytes, 'g'));
}

InstancesContent shrubs(size_t n) {
  InstancesContent c;
  c.origin = {7.44, 46.95, 540};
  c.prototypes = {"builtin:shrub"};
  for (size_t i = 0; i < n; ++i) {
    c.prototype.push_back(0);
    c.position.insert(c.position.end(), {float(i), 2, 0});
    c.rotation.insert(c.rotation.end(), {0, 0, 0, 1});
    c.scale.insert(c.scale.end(), {1, 1, 1});
    c.colour.push_back(0xff00ff00u);
  }
  return c;
}

TEST(InfoContent, ListsContentLayersWithTheirCounts) {
  test::TempDir dir;
  const std::string path = dir.file("town.mqs");
  const CellId a = *CellId::FromText("O2101010"), b = *CellId::FromText("O2101011");
  int64_t bytes = 0;
  {
    auto store = Store::open(path, Store::Mode::Create);
    LayerInfo l;
    l.name = "buildings";
    l.kind = LayerKind::Mesh;
    l.level = 7;
    store->create_layer(l);
    l.name = "trees";
    l.kind = LayerKind::Instances;
    store->create_layer(l);
    Store::Batch batch(*store);
    const std::string blobs[] = {mesh_blob({4, 1200, 0}, 3000), mesh_blob({2, 48, 0}, 100),
                                 mesh_blob({6, 400, 0}, 500)};
    batch.put_content("buildings", a, blobs[0]);
    batch.put_content("buildings", b, blobs[1]);
    batch.put_content("buildings", a.parent(), blobs[2]);  // simplified: not counted twice
    for (const auto& blob : blobs) bytes += int64_t(blob.size());
    batch.put_content("trees", a, wrap_instances(shrubs(250)));
    batch.put_content("trees", b, wrap_instances(shrubs(31)));
    batch.commit();
  }

  const test::CliResult json = test::run_maquette("info --json " + path);
  ASSERT_EQ(json.exit_code, 0) << json.err;
  const auto report = nlohmann::json::parse(json.out);
  ASSERT_EQ(report["layers"].size(), 2u);
  const auto& buildings = report["layers"][0];
  EXPECT_EQ(buildings["name"], "buildings");
  EXPECT_EQ(buildings["kind"], "mesh");
  EXPECT_EQ(buildings["cells"], 2);
  EXPECT_EQ(buildings["objects"], 6);
  EXPECT_EQ(buildings["triangles"], 1248);
  EXPECT_EQ(buildings["instances"], 0);
  EXPECT_EQ(buildings["voxels"], 0);
  EXPECT_EQ(buildings["bytes"], bytes);
  EXPECT_EQ(buildings["levels"], nlohmann::json::array({6, 7}));
  EXPECT_FALSE(buildings.contains("pixel_m"));
  const auto& trees = report["layers"][1];
  EXPECT_EQ(trees["kind"], "instances");
  EXPECT_EQ(trees["cells"], 2);
  EXPECT_EQ(trees["objects"], 281);
  EXPECT_EQ(trees["instances"], 281);
  EXPECT_EQ(trees["triangles"], 0);
  // The cells' box: both cells lie in it, and it is no larger than their parent's.
  const auto& bbox = trees["bbox"];
  ASSERT_EQ(bbox.size(), 4u);
  EXPECT_LT(bbox[0].get<double>(), bbox[2].get<double>());
  EXPECT_LT(bbox[1].get<double>(), bbox[3].get<double>());

  const test::CliResult text = test::run_maquette("info " + path);
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("buildings: mesh content in cells at level 7"), std::string::npos)
      << text.out;
  EXPECT_NE(text.out.find("cells  2, objects 6, triangles 1248, instances 0, voxels 0"),
            std::string::npos)
      << text.out;
  EXPECT_NE(text.out.find("trees: instances content in cells at level 7"), std::string::npos);
  EXPECT_NE(text.out.find("cells  2, objects 281, triangles 0, instances 281, voxels 0"),
            std::string::npos)
      << text.out;
}

}  // namespace
}  // namespace maquette
