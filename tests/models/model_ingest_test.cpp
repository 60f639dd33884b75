// `maquette ingest STORE --layer NAME --as model FILE` (the real program) on models the tests
// write: a textured box as a .gltf with its .bin and .png beside it, and packed as a GLB. The
// stored model is decoded and compared with the file's accessors read by the test itself (axes
// turned to z up, base moved to z = 0), within the mesh GLB's declared quantization; material
// and image bytes must be equal. `maquette info` lists it. Each bad input is an error naming the
// file and the fault, and the store stays as it was.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "content/content_blob.h"
#include "content_fixture.h"
#include "gltf/mesh_glb.h"
#include "json_glb.h"
#include "model_oracle.h"
#include "run_cli.h"
#include "store/store.h"

namespace maquette::test {
namespace {

using nlohmann::json;

constexpr std::array<float, 4> kOchre{0.75f, 0.5f, 0.25f, 1}, kTeal{0.25f, 0.5f, 0.5f, 1};

std::string quoted(const std::string& s) { return "'" + s + "'"; }

CliResult ingest_model(const std::string& store, const std::string& layer,
                       const std::string& file) {
  return run_maquette("ingest " + quoted(store) + " --layer " + layer + " --as model " +
                      quoted(file));
}

MeshContent stored_model(const Store& store, const std::string& name) {
  const auto blob = store.get_model(name);
  if (!blob) throw std::runtime_error("no model " + name);
  return decode_mesh_glb(content_payload(*blob), {}, "model " + name);
}

// The model decoded from the store against the oracle read from `gltf` (the .gltf file).
void expect_box(const MeshContent& stored, const std::string& gltf,
                const std::array<float, 4>& colour, const std::string& image) {
  ASSERT_EQ(stored.objects.size(), 1u);
  ASSERT_EQ(stored.materials.size(), 1u);
  const MeshObject oracle = stored_object_oracle(gltf);
  const MeshObject& o = stored.objects[0];
  EXPECT_EQ(o.indices.size(), oracle.indices.size());
  // mesh_glb's positions: quantized over the widest extent (3 m) with a step of at most 1 mm,
  // so within half a step; uvs on 12 bits over their range; normals on 10 octahedral bits.
  const MeshGlbSettings settings;
  const double step = 3.0 / double((uint64_t(1) << position_bits(3.0, settings)) - 1);
  const MeshDifference d = compare_meshes(oracle, o);
  EXPECT_LE(d.position, step / 2 + 1e-6);
  EXPECT_LE(d.uv, 1.0 / 4095);
  EXPECT_LE(d.normal, 0.01);
  float base = 1e9f;
  for (size_t i = 2; i < o.positions.size(); i += 3) base = std::min(base, o.positions[i]);
  EXPECT_NEAR(base, 0, step / 2 + 1e-6);  // the lowest vertex on the ground
  const Material& m = stored.materials[0];
  EXPECT_EQ(m.name, "crate");
  EXPECT_EQ(m.base_colour, colour);
  EXPECT_EQ(m.metallic, 0.25f);
  EXPECT_EQ(m.roughness, 0.75f);
  EXPECT_EQ(m.image_mime, "image/png");
  EXPECT_EQ(m.image, image);  // the PNG's bytes, as they were given
  EXPECT_EQ(o.material, 0);
}

json info_layer(const std::string& store, const std::string& name) {
  const CliResult r = run_maquette("info --json " + quoted(store));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  const json info = json::parse(r.out);
  for (const json& l : info["layers"])
    if (l["name"] == name) return l;
  ADD_FAILURE() << "no layer " << name << " in " << r.out;
  return {};
}

TEST(ModelIngest, GltfAndGlbBoxesAreStoredInTheModelFrame) {
  const std::string dir = temp_dir(), store_path = dir + "/town.mqs";
  const ModelFile box = box_model(kOchre);
  const std::string gltf = write_external(box, dir, "box");
  const std::string glb = write_glb(box, dir, "packed");
  for (const auto& [layer, file] : {std::pair{"box", gltf}, std::pair{"packed", glb}}) {
    const CliResult r = ingest_model(store_path, layer, file);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("model " + std::string(layer) + ": 1 objects, 12 triangles"),
              std::string::npos)
        << r.err;
  }
  const auto store = Store::open(store_path, Store::Mode::ReadOnly);
  const LayerInfo layer = store->require_layer("box");
  EXPECT_EQ(layer.kind, LayerKind::Model);
  EXPECT_EQ(layer.provenance["source"], gltf);
  const std::string blob = *store->get_model("box");
  const ContentEnvelope envelope = read_content_envelope(blob, "box");
  EXPECT_EQ(envelope.kind, ContentKind::Mesh);
  EXPECT_EQ(envelope.origin, EnuOrigin{});
  EXPECT_EQ(envelope.stats, (ContentStats{1, 12, 0}));
  expect_box(stored_model(*store, "box"), gltf, kOchre, box.image);
  expect_box(stored_model(*store, "packed"), gltf, kOchre, box.image);
  // The same model in either container: the same content, so the same bytes.
  EXPECT_EQ(*store->get_model("packed"), blob);

  const json info = info_layer(store_path, "box");
  EXPECT_EQ(info["kind"], "model");
  EXPECT_EQ(info["objects"], 1);
  EXPECT_EQ(info["triangles"], 12);
  EXPECT_EQ(info["materials"], 1);
  EXPECT_EQ(info["bytes"], blob.size());
  const CliResult text = run_maquette("info " + quoted(store_path));
  EXPECT_NE(text.out.find("box: model"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("objects 1, triangles 12, materials 1"), std::string::npos) << text.out;
}

TEST(ModelIngest, IngestingAgainReplacesTheModel) {
  const std::string dir = temp_dir(), store_path = dir + "/town.mqs";
  const ModelFile ochre = box_model(kOchre), teal = box_model(kTeal);
  ASSERT_EQ(ingest_model(store_path, "box", write_external(ochre, dir, "ochre")).exit_code, 0);
  const std::string teal_path = write_external(teal, dir, "teal");
  const CliResult r = ingest_model(store_path, "box", teal_path);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto store = Store::open(store_path, Store::Mode::ReadOnly);
  EXPECT_EQ(store->layers().size(), 1u);
  EXPECT_EQ(store->require_layer("box").provenance["source"], teal_path);
  expect_box(stored_model(*store, "box"), teal_path, kTeal, teal.image);
  EXPECT_EQ(store->stats("box").tile_count, 1);  // one blob, replaced
}

TEST(ModelIngest, APipelineIngestStepWritesAModel) {
  const std::string dir = temp_dir();
  const ModelFile box = box_model(kOchre);
  write_external(box, dir, "box");
  std::ofstream(dir + "/p.json") << json{
      {"store", "p.mqs"},
      {"region", {{"bbox", {7.4, 46.9, 7.5, 47.0}}}},
      {"level", 9},
      {"steps",
       {{{"op", "ingest"},
         {"outputs", {{"layer", "crate"}}},
         {"params", {{"sources", {"box.gltf"}}, {"as", "model"}}}}}}};
  const CliResult r = run_maquette("run " + quoted(dir + "/p.json"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto store = Store::open(dir + "/p.mqs", Store::Mode::ReadOnly);
  expect_box(stored_model(*store, "crate"), dir + "/box.gltf", kOchre, box.image);
}

// A store and what it holds, to check that a refused ingest changed nothing.
struct Snapshot {
  std::vector<std::string> layers;
  std::string box;
  bool operator==(const Snapshot&) const = default;
};

Snapshot snapshot(const std::string& path) {
  const auto store = Store::open(path, Store::Mode::ReadOnly);
  Snapshot s;
  for (const LayerInfo& l : store->layers()) s.layers.push_back(l.name);
  s.box = store->get_model("box").value_or("");
  return s;
}

TEST(ModelIngest, BadModelsAreNamedAndStoreNothing) {
  const std::string dir = temp_dir(), store_path = dir + "/town.mqs";
  const ModelFile box = box_model(kOchre);
  ASSERT_EQ(ingest_model(store_path, "box", write_external(box, dir, "box")).exit_code, 0);
  const Snapshot before = snapshot(store_path);

  struct Case {
    std::string file, fault;
  };
  std::vector<Case> cases;
  write_bytes(dir + "/picture.glb", box.image);
  cases.push_back({dir + "/picture.glb", "not glTF"});
  write_bytes(dir + "/notes.gltf", "a box, 2 m by 1 m by 3 m\n");
  cases.push_back({dir + "/notes.gltf", "not glTF"});
  write_bytes(dir + "/empty.glb", json_glb({{"asset", {{"version", "2.0"}}},
                                            {"scenes", {{{"nodes", json::array()}}}}}));
  cases.push_back({dir + "/empty.glb", "no mesh"});
  {
    json huge = box.gltf;
    huge["buffers"][0] = {{"byteLength", uint64_t(2) << 30}, {"uri", "huge.bin"}};
    huge["images"][0]["uri"] = "box.png";
    write_bytes(dir + "/huge.gltf", huge.dump());
    cases.push_back({dir + "/huge.gltf", "declares 2147483648 bytes"});
  }
  {
    json lost = box.gltf;
    lost["buffers"][0]["uri"] = "box.bin";
    lost["images"][0]["uri"] = "lost.png";
    write_bytes(dir + "/lost.gltf", lost.dump());
    cases.push_back({dir + "/lost.gltf", "lost.png"});
  }
  for (const Case& c : cases)
    for (const std::string layer : {"box", "other"}) {
      const CliResult r = ingest_model(store_path, layer, c.file);
      EXPECT_NE(r.exit_code, 0) << c.file;
      EXPECT_NE(r.err.find(c.file), std::string::npos) << r.err;
      EXPECT_NE(r.err.find(c.fault), std::string::npos) << r.err;
      EXPECT_EQ(snapshot(store_path), before) << c.file;
    }
  // Nor is a store created for a bad model.
  const std::string fresh = dir + "/fresh.mqs";
  EXPECT_NE(ingest_model(fresh, "box", cases.front().file).exit_code, 0);
  EXPECT_FALSE(std::filesystem::exists(fresh));
}

// Instances name their prototypes: a model layer named like a built-in prototype (or in their
// namespace) is refused before the file is read, naming the file and the name; nothing is
// stored, and no store is created.
TEST(ModelIngest, BuiltinNamesAreRefused) {
  const std::string dir = temp_dir(), store_path = dir + "/town.mqs";
  const std::string file = write_external(box_model(kOchre), dir, "box");
  ASSERT_EQ(ingest_model(store_path, "box", file).exit_code, 0);
  const Snapshot before = snapshot(store_path);
  for (const std::string layer : {"builtin:conifer", "builtin:oak"}) {
    const CliResult r = ingest_model(store_path, layer, file);
    EXPECT_NE(r.exit_code, 0) << layer;
    EXPECT_NE(r.err.find(file + ": cannot ingest a model as layer '" + layer + "'"),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("built-in prototypes"), std::string::npos) << r.err;
    EXPECT_EQ(snapshot(store_path), before) << layer;
  }
  const std::string fresh = dir + "/fresh.mqs";
  EXPECT_NE(ingest_model(fresh, "builtin:shrub", file).exit_code, 0);
  EXPECT_FALSE(std::filesystem::exists(fresh));
}

TEST(ModelIngest, ALayerOfAnotherKindIsNotReplaced) {
  const std::string dir = temp_dir(), store_path = dir + "/town.mqs";
  {
    auto store = Store::open(store_path, Store::Mode::Create);
    LayerInfo roads;
    roads.name = "roads";
    roads.kind = LayerKind::Features;
    roads.tile_size = 1;
    roads.dtype = DType::U8;
    roads.codec = "raw";
    roads.level = 12;
    store->create_layer(roads);
  }
  const CliResult r =
      ingest_model(store_path, "roads", write_external(box_model(kOchre), dir, "box"));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("layer 'roads'"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("is of kind features, not a model"), std::string::npos) << r.err;
  EXPECT_EQ(Store::open(store_path, Store::Mode::ReadOnly)->require_layer("roads").kind,
            LayerKind::Features);
}

}  // namespace
}  // namespace maquette::test
