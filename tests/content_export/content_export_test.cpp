// maquette export tiles3d --content on mesh, instances and volume layers of a real store: every
// content a tile of its cell, placed by its node's matrix and the tileset's transform where
// GeographicLib puts its frame's points, its region holding it (tileset_reader), the mesh shipped
// as stored, the instances checked by the EXT_mesh_gpu_instancing checker, every GLB passing the
// Khronos glTF validator, and bad input refused.
#include <gtest/gtest.h>

#include <GeographicLib/Geocentric.hpp>
#include <GeographicLib/LocalCartesian.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>

#include "content/content_blob.h"
#include "content_fixture.h"
#include "content_store.h"
#include "gltf/mesh_glb.h"
#include "gpu_instancing_check.h"
#include "run_cli.h"
#include "store/store.h"
#include "tileset_reader.h"

namespace maquette::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// Adds a textured mesh layer `roofs` on block[3]: a 40 m box with a PNG texture
// (tests/gltf_content's box), for merging several mesh GLBs with their textures and metadata.
void add_roofs(const ContentStore& s) {
  MeshContent m;
  m.origin = s.origins[3];
  m.materials.push_back(
      {"tiles", {1, 1, 1, 1}, 0.f, 0.9f, encoded_image("PNG", 16, 16), "image/png", false});
  m.objects.push_back(box({-20, -20, 0}, {40, 40, 30}));
  m.objects[0].material = 0;
  m.objects[0].provenance = {7, 3, "structures.roofs", {{"height", 30}}};
  ContentEnvelope e;
  e.kind = ContentKind::Mesh;
  e.origin = m.origin;
  e.stats = {1, 12, 0};
  auto store = Store::open(s.path, Store::Mode::ReadWrite);
  LayerInfo roofs;
  roofs.name = "roofs";
  roofs.kind = LayerKind::Mesh;
  roofs.level = kLevel;
  store->create_layer(roofs);
  Store::Batch batch(*store);
  batch.put_content("roofs", s.block[3], wrap_content(e, encode_mesh_glb(m)));
  batch.commit();
}

const ContentStore& content_store() {
  static const ContentStore s = [] {
    const ContentStore written = write_content_store(temp_dir() + "/content.maquette");
    add_roofs(written);
    return written;
  }();
  return s;
}

const Export& content_export() {
  static const Export e = [] {
    const std::string dir = temp_dir() + "/content_tiles";
    const auto r = run_maquette("export tiles3d " + content_store().path + " " + dir +
                                " --dem dem --levels " + std::to_string(kLevel - 2) + ".." +
                                std::to_string(kLevel) + " --content buildings trees lakes");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return read_export(dir);
  }();
  return e;
}

std::string uri(CellId c, const std::string& layer) {
  return "tiles/" + std::to_string(c.level()) + "/" + c.ToText() + "." + layer + ".glb";
}

std::string file_bytes(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

using Ecef = std::array<double, 3>;

// A point of the export's frame (glTF axes) in ECEF through the root tile's transform (3D Tiles'
// y-up to z-up, then the transform).
Ecef ecef_of(const std::vector<double>& m, const Pos& p) {
  const double e = p[0], n = -p[2], u = p[1];
  Ecef x;
  for (int r = 0; r < 3; ++r) x[r] = m[r] * e + m[4 + r] * n + m[8 + r] * u + m[12 + r];
  return x;
}

// GeographicLib's ECEF of a point (east, north, up metres) of the frame at `o`.
Ecef ecef_of(const EnuOrigin& o, const Ecef& enu) {
  double lat, lon, h;
  GeographicLib::LocalCartesian(o.lat, o.lon, o.height)
      .Reverse(enu[0], enu[1], enu[2], lat, lon, h);
  Ecef x;
  GeographicLib::Geocentric::WGS84().Forward(lat, lon, h, x[0], x[1], x[2]);
  return x;
}

double distance(const Ecef& a, const Ecef& b) {
  return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
}

// The node holding mesh 0.
int mesh_node(const Glb& glb) {
  for (size_t n = 0; n < glb.json["nodes"].size(); ++n)
    if (glb.json["nodes"][n].contains("mesh")) return int(n);
  return -1;
}

TEST(ContentExport, EachLayerIsAContentOfItsCellsTiles) {
  const Export& e = content_export();
  const auto& s = content_store();
  std::set<std::string> contents;
  for (const auto& [u, glb] : e.glbs)
    if (fs::path(u).stem().has_extension()) contents.insert(u);
  // The box at its level and as the simplified copy of its parent; trees and lake at their level
  // only (no overviews).
  EXPECT_EQ(contents, (std::set<std::string>{uri(s.block[0].parent(), "buildings"),
                                             uri(s.block[0], "buildings"), uri(s.block[2], "lakes"),
                                             uri(s.block[1], "trees")}));
}

TEST(ContentExport, MeshIsShippedAsStoredAndPlaced) {
  const Export& e = content_export();
  const auto& s = content_store();
  const GlbChunks written = split_glb(file_bytes(e.dir + "/" + uri(s.block[0], "buildings")));
  auto store = Store::open(s.path, Store::Mode::ReadOnly);
  const std::string blob = *store->get_content("buildings", s.block[0]);
  const GlbChunks stored = split_glb(content_payload(blob));
  EXPECT_EQ(written.bin, stored.bin);  // the Draco geometry is not encoded again
  EXPECT_EQ(written.json["meshes"], stored.json["meshes"]);

  const Glb& glb = e.glbs.at(uri(s.block[0], "buildings"));
  const auto m = e.tileset["root"]["transform"].get<std::vector<double>>();
  const int node = mesh_node(glb);
  ASSERT_GE(node, 0);
  // Each corner (glTF axes: x east, y up, z south) where GeographicLib puts it, within 1 cm.
  for (int i = 0; i < 8; ++i) {
    const Ecef enu = {i & 1 ? kBoxHalf : -kBoxHalf, i & 2 ? kBoxHalf : -kBoxHalf,
                      i & 4 ? kBoxHeight : 0};
    const Ecef want = ecef_of(s.origins[0], enu);
    EXPECT_LT(distance(ecef_of(m, glb.place(node, {enu[0], enu[2], -enu[1]})), want), 0.01) << i;
    // and a decoded vertex there (Draco's step is at most 1 mm)
    double nearest = 1e9;
    for (const Pos& p : glb.primitives.at(0).positions)
      nearest = std::min(nearest, distance(ecef_of(m, p), want));
    EXPECT_LT(nearest, 0.01) << i;
  }
  // Red, as stored.
  EXPECT_NEAR(glb.json["materials"][0]["pbrMetallicRoughness"]["baseColorFactor"][0].get<double>(),
              0.9, 1e-6);
}

TEST(ContentExport, InstancesUseThePrototypesMaterialsAndColours) {
  const Export& e = content_export();
  const auto& s = content_store();
  const std::string path = e.dir + "/" + uri(s.block[1], "trees");
  const GlbChunks chunks = split_glb(file_bytes(path));
  EXPECT_EQ(gpu_instancing_problems(chunks), std::vector<std::string>{});
  const Glb& glb = e.glbs.at(uri(s.block[1], "trees"));
  EXPECT_EQ(glb.json["extensionsRequired"], json({"EXT_mesh_gpu_instancing"}));
  // The conifer's own bark and foliage, each drawn per instance with the instance's colour.
  ASSERT_EQ(glb.json["materials"].size(), 2u);
  const auto inst = instancing(glb);
  ASSERT_TRUE(inst);
  ASSERT_TRUE(inst->contains("_COLOR_0"));
  const auto colour = accessor_values(chunks, (*inst)["_COLOR_0"].get<size_t>());
  ASSERT_EQ(colour.size(), size_t(4 * kTreeCount));
  EXPECT_NEAR(colour[1], 0xD0 / 255.0, 1e-9);  // green
  const auto t = glb.floats((*inst)["TRANSLATION"]), sc = glb.floats((*inst)["SCALE"]);
  const auto m = e.tileset["root"]["transform"].get<std::vector<double>>();
  for (int i = 0; i < kTreeCount; ++i) {
    const auto [east, north] = tree_offset(i);
    const Ecef want = ecef_of(s.origins[1], {east, north, 0});
    const Pos base = glb.place(0, {t[3 * i], t[3 * i + 1], t[3 * i + 2]});
    EXPECT_LT(distance(ecef_of(m, base), want), 0.01) << i;
    EXPECT_EQ(sc[3 * i + 1], float(kTreeHeight));
  }
}

// A model layer (store/README.md, "Model layers") is a prototype: once the store holds a model
// named "oak", the orchard's instance (refused in BadInput) is drawn with that model's mesh and
// material.
TEST(ContentExport, ModelLayersArePrototypes) {
  const ContentStore s = write_content_store(temp_dir() + "/models.maquette");
  MeshContent oak;
  oak.materials.push_back({"leaves", {0.2f, 0.5f, 0.1f, 1}, 0.f, 0.8f, "", "", false});
  oak.objects.push_back(box({-2, -2, 0}, {4, 4, 12}));
  oak.objects[0].material = 0;
  ContentEnvelope model;
  model.kind = ContentKind::Mesh;
  model.stats = {1, 12, 0};
  {
    auto store = Store::open(s.path, Store::Mode::ReadWrite);
    Store::Batch batch(*store);
    batch.put_model("oak", wrap_content(model, encode_mesh_glb(oak)));
    batch.commit();
  }
  const std::string dir = temp_dir() + "/model_tiles";
  fs::remove_all(dir);
  const auto r =
      run_maquette("export tiles3d " + s.path + " " + dir + " --dem dem --content orchard");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string u = uri(s.block[3], "orchard");
  EXPECT_EQ(gpu_instancing_problems(split_glb(file_bytes(dir + "/" + u))),
            std::vector<std::string>{});
  const Export x = read_export(dir);
  const Glb& glb = x.glbs.at(u);
  ASSERT_EQ(glb.json["meshes"].size(), 1u);
  EXPECT_EQ(glb.json["meshes"][0]["name"], "oak leaves");
  const auto colour = glb.json["materials"][0]["pbrMetallicRoughness"]["baseColorFactor"];
  EXPECT_NEAR(colour[1].get<double>(), 0.5, 1e-6);
  EXPECT_EQ(glb.json["accessors"][glb.json["meshes"][0]["primitives"][0]["indices"].get<size_t>()]
                    ["count"],
            36);
}

TEST(ContentExport, VolumesAreMeshed) {
  const Export& e = content_export();
  const auto& s = content_store();
  const Glb& glb = e.glbs.at(uri(s.block[2], "lakes"));
  ASSERT_EQ(glb.primitives.size(), 1u);
  const auto m = e.tileset["root"]["transform"].get<std::vector<double>>();
  // The fog box's surface (density 0.5) spans 80 m x 80 m x 20 m from the origin up, within a
  // voxel (2 m).
  double lo[3] = {1e9, 1e9, 1e9}, hi[3] = {-1e9, -1e9, -1e9};
  const GeographicLib::LocalCartesian enu(s.origins[2].lat, s.origins[2].lon, s.origins[2].height);
  for (const Pos& p : glb.primitives[0].positions) {
    const auto g = geodetic(m, p);
    double x[3];
    enu.Forward(g[1], g[0], g[2], x[0], x[1], x[2]);
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], x[k]);
      hi[k] = std::max(hi[k], x[k]);
    }
  }
  for (int k = 0; k < 2; ++k) {
    EXPECT_NEAR(lo[k], -40, 2) << k;
    EXPECT_NEAR(hi[k], 40, 2) << k;
  }
  EXPECT_NEAR(lo[2], 0, 2);
  EXPECT_NEAR(hi[2], 20, 2);
}

// The node of `glb` holding a mesh (the first with EXT_mesh_gpu_instancing when `instanced`)
// under the node named `name`.
int node_under(const Glb& glb, const std::string& name, bool instanced) {
  const json& nodes = glb.json["nodes"];
  for (const json& n : nodes)
    if (n.value("name", "") == name)
      for (const json& c : n["children"]) {
        const json& child = nodes[c.get<size_t>()];
        if (child.contains("mesh") && child.contains("extensions") == instanced)
          return c.get<int>();
      }
  return -1;
}

// The orchard's prototype "oak" as a textured model: a box with a JPEG, written as a GLB file and
// ingested as a user would (`maquette ingest --as model`).
struct TexturedModel {
  ContentStore store;
  std::string image;       // the JPEG's bytes
  std::vector<float> uvs;  // the box's, as given
};

const TexturedModel& textured_model() {
  static const TexturedModel t = [] {
    TexturedModel m{write_content_store(temp_dir() + "/textured_model.maquette"),
                    encoded_image("JPEG", 32, 16),
                    {}};
    MeshContent crate;
    crate.materials.push_back({"planks", {1, 1, 1, 1}, 0.f, 0.7f, m.image, "image/jpeg", false});
    crate.objects.push_back(box({-2, -2, 0}, {4, 4, 6}));
    crate.objects[0].material = 0;
    m.uvs = crate.objects[0].uvs;
    const std::string file = temp_dir() + "/crate.glb";
    std::ofstream(file, std::ios::binary) << encode_mesh_glb(crate);
    const auto r = run_maquette("ingest " + m.store.path + " --layer oak --as model " + file);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return m;
  }();
  return t;
}

// The instanced file's one textured material: the model's JPEG byte for byte, its uvs (the
// model went through Draco at ingest: 12 bits over 0.13..0.87), and each instance's colour
// (multiplying the texture).
void expect_textured_instances(const Glb& glb, const std::string& bytes, int node) {
  const TexturedModel& t = textured_model();
  const json& j = glb.json;
  ASSERT_EQ(j["images"].size(), 1u);
  EXPECT_EQ(j["images"][0]["mimeType"], "image/jpeg");
  const std::vector<char> image = glb.image(0);
  EXPECT_EQ(std::string(image.begin(), image.end()), t.image);
  const json& prim = j["meshes"][j["nodes"][node]["mesh"].get<int>()]["primitives"][0];
  const json& material = j["materials"][prim["material"].get<int>()];
  EXPECT_EQ(material["name"], "planks");
  EXPECT_EQ(j["textures"][material["pbrMetallicRoughness"]["baseColorTexture"]["index"].get<int>()]
             ["source"],
            0);
  const std::vector<float> uvs = glb.floats(prim["attributes"]["TEXCOORD_0"].get<int>());
  ASSERT_EQ(uvs.size(), t.uvs.size());  // 24 vertices: 4 per face
  for (size_t i = 0; i < uvs.size(); ++i) {
    double nearest = 1;
    for (size_t k = i % 2; k < t.uvs.size(); k += 2)
      nearest = std::min(nearest, double(std::abs(uvs[i] - t.uvs[k])));
    EXPECT_LT(nearest, 1.0 / 8190) << i;
  }
  const GlbChunks chunks = split_glb(bytes);
  EXPECT_EQ(gpu_instancing_problems(chunks), std::vector<std::string>{});
  const auto colour = accessor_values(
      chunks, j["nodes"][node]["extensions"]["EXT_mesh_gpu_instancing"]["attributes"]["_COLOR_0"]
                  .get<size_t>());
  ASSERT_EQ(colour.size(), 4u);
  for (int k = 0; k < 4; ++k)
    EXPECT_NEAR(colour[size_t(k)], ((kTreeColour >> (8 * k)) & 0xFF) / 255.0, 1e-9) << k;
}

TEST(ContentExport, TexturedModelsArePrototypes) {
  const TexturedModel& t = textured_model();
  const std::string dir = temp_dir() + "/textured_model_tiles";
  fs::remove_all(dir);
  const auto r =
      run_maquette("export tiles3d " + t.store.path + " " + dir + " --dem dem --content orchard");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string u = uri(t.store.block[3], "orchard");
  const Export x = read_export(dir);
  const Glb& glb = x.glbs.at(u);
  expect_textured_instances(glb, file_bytes(dir + "/" + u), mesh_node(glb));
  const auto ok = gltf_validator_passes(dir);
  if (!ok) GTEST_SKIP() << "gltf-validator not installed";
  EXPECT_TRUE(*ok);
}

TEST(ContentExport, GlbOfATexturedPrototype) {
  const TexturedModel& t = textured_model();
  const std::string dir = temp_dir() + "/textured_model_glb";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string out = dir + "/orchard.glb";
  const auto r = run_maquette("export glb " + t.store.path + " " + out + " --dem dem --cells " +
                              t.store.block[3].ToText() + " --content orchard");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Glb glb = read_glb(out);
  const int node = node_under(glb, "orchard " + t.store.block[3].ToText(), true);
  ASSERT_GE(node, 0);
  expect_textured_instances(glb, file_bytes(out), node);
  const auto ok = gltf_validator_passes(dir);
  if (!ok) GTEST_SKIP() << "gltf-validator not installed";
  EXPECT_TRUE(*ok);
}

TEST(ContentExport, GlbOfTwoCells) {
  const auto& s = content_store();
  const std::string dir = temp_dir() + "/content_glb";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string out = dir + "/two.glb";
  const auto r =
      run_maquette("export glb " + s.path + " " + out + " --dem dem --cells " +
                   s.block[0].ToText() + " " + s.block[1].ToText() + " --content buildings trees");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Glb glb = read_glb(out);
  const GlbChunks chunks = split_glb(file_bytes(out));
  EXPECT_EQ(gpu_instancing_problems(chunks), std::vector<std::string>{});
  // The file's frame: east-north-up at its origin, glTF axes.
  const json& origin = glb.json["asset"]["extras"]["maquette_frame"]["origin"];
  const GeographicLib::LocalCartesian frame(origin["lat"].get<double>(),
                                            origin["lon"].get<double>(), 0);
  auto ecef_in_file = [&](const Pos& p) {
    double lat, lon, h;
    frame.Reverse(p[0], -p[2], p[1], lat, lon, h);
    Ecef x;
    GeographicLib::Geocentric::WGS84().Forward(lat, lon, h, x[0], x[1], x[2]);
    return x;
  };
  ASSERT_GE(node_under(glb, "terrain", false), 0);
  const int box = node_under(glb, "buildings " + s.block[0].ToText(), false);
  const int trees = node_under(glb, "trees " + s.block[1].ToText(), true);
  ASSERT_GE(box, 0);
  ASSERT_GE(trees, 0);
  for (int i = 0; i < 8; ++i) {
    const Ecef enu = {i & 1 ? kBoxHalf : -kBoxHalf, i & 2 ? kBoxHalf : -kBoxHalf,
                      i & 4 ? kBoxHeight : 0};
    EXPECT_LT(distance(ecef_in_file(glb.place(box, {enu[0], enu[2], -enu[1]})),
                       ecef_of(s.origins[0], enu)),
              0.01)
        << i;
  }
  const auto t = glb.floats(
      glb.json["nodes"][trees]["extensions"]["EXT_mesh_gpu_instancing"]["attributes"]["TRANSLATION"]
          .get<int>());
  ASSERT_EQ(t.size(), size_t(3 * kTreeCount));
  for (int i = 0; i < kTreeCount; ++i) {
    const auto [east, north] = tree_offset(i);
    EXPECT_LT(distance(ecef_in_file(glb.place(trees, {t[3 * i], t[3 * i + 1], t[3 * i + 2]})),
                       ecef_of(s.origins[1], {east, north, 0})),
              0.01)
        << i;
  }
  // Content alone (a volume, meshed), no terrain.
  const auto lake = run_maquette("export glb " + s.path + " " + dir + "/lake.glb --cells " +
                                 s.block[2].ToText() + " --content lakes");
  ASSERT_EQ(lake.exit_code, 0) << lake.err;
  EXPECT_EQ(read_glb(dir + "/lake.glb").primitives.size(), 1u);
  const auto ok = gltf_validator_passes(dir);
  if (!ok) GTEST_SKIP() << "gltf-validator not installed";
  EXPECT_TRUE(*ok);
}

// Two mesh GLBs in one: the textured one's image, texture and property table follow the first's.
TEST(ContentExport, GlbOfTwoMeshLayersKeepsTexturesAndMetadata) {
  const auto& s = content_store();
  const std::string dir = temp_dir() + "/content_glb_meshes";
  fs::create_directories(dir);
  const std::string out = dir + "/meshes.glb";
  const auto r =
      run_maquette("export glb " + s.path + " " + out + " --cells " + s.block[0].ToText() + " " +
                   s.block[3].ToText() + " --content buildings roofs");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Glb glb = read_glb(out);
  const json& j = glb.json;
  ASSERT_EQ(j["materials"].size(), 2u);
  EXPECT_EQ(j["images"].size(), 1u);
  EXPECT_EQ(j["images"][0]["mimeType"], "image/png");
  EXPECT_EQ(j["materials"][1]["pbrMetallicRoughness"]["baseColorTexture"]["index"], 0);
  const json& tables = j["extensions"]["EXT_structural_metadata"]["propertyTables"];
  ASSERT_EQ(tables.size(), 2u);
  const int roofs = node_under(glb, "roofs " + s.block[3].ToText(), false);
  ASSERT_GE(roofs, 0);
  const json& prim = j["meshes"][j["nodes"][roofs]["mesh"].get<int>()]["primitives"][0];
  EXPECT_EQ(prim["material"], 1);
  EXPECT_EQ(prim["extensions"]["EXT_mesh_features"]["featureIds"][0]["propertyTable"], 1);
  // The roofs' tool string, read through the second table's bufferViews.
  const auto& tool = tables[1]["properties"]["tool"];
  const auto& view = j["bufferViews"][tool["values"].get<int>()];
  const std::string text(
      glb.bin.begin() + view["byteOffset"].get<long>(),
      glb.bin.begin() + view["byteOffset"].get<long>() + view["byteLength"].get<long>());
  EXPECT_EQ(text, "structures.roofs");
  const auto ok = gltf_validator_passes(dir);
  if (!ok) GTEST_SKIP() << "gltf-validator not installed";
  EXPECT_TRUE(*ok);
}

TEST(ContentExport, GltfValidator) {
  const auto ok = gltf_validator_passes(content_export().dir);
  if (!ok) GTEST_SKIP() << "gltf-validator not installed (npm ci in " MAQUETTE_NODE_DIR " failed)";
  EXPECT_TRUE(*ok);
}

TEST(ContentExport, BadInput) {
  const auto& s = content_store();
  auto fails = [&](const std::string& args, const std::string& message) {
    const std::string out = temp_dir() + "/bad_content";
    fs::remove_all(out);
    const auto r = run_maquette("export tiles3d " + s.path + " " + out + " --dem dem " + args);
    EXPECT_NE(r.exit_code, 0) << args;
    EXPECT_NE(r.err.find(message), std::string::npos) << args << ": " << r.err;
  };
  fails("--content orchard",
        "layer orchard, cell " + s.block[3].ToText() + ": unknown prototype 'oak'");
  fails("--content shrubs", "no content layer 'shrubs'");
  fails("--content dem", "no content layer 'dem'");
  // Tiles finer than a content layer's level would replace the tiles holding its content.
  fails("--content parks", "content layer 'parks' is at level " + std::to_string(kLevel - 1) +
                               ", coarser than the finest tiles (level " + std::to_string(kLevel) +
                               ")");
  const std::string glb = temp_dir() + "/bad.glb";
  const auto none =
      run_maquette("export glb " + s.path + " " + glb + " --cells " + s.block[0].ToText());
  EXPECT_NE(none.exit_code, 0);
  EXPECT_NE(none.err.find("nothing to export"), std::string::npos) << none.err;
  const auto empty = run_maquette("export glb " + s.path + " " + glb + " --cells " +
                                  s.block[3].ToText() + " --content buildings");
  EXPECT_NE(empty.exit_code, 0);
  EXPECT_NE(empty.err.find("no content"), std::string::npos) << empty.err;
  EXPECT_FALSE(fs::exists(glb));
}

}  // namespace
}  // namespace maquette::test
