// Mesh layers' GLB payloads (gltf/mesh_glb.h): round trips of a textured box and of a few objects
// through Draco (positions within the declared quantization, normals and uvs within theirs,
// materials, images byte for byte, metadata), the Khronos glTF validator, the same bytes twice,
// bad content refused.
#include "gltf/mesh_glb.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "content_fixture.h"
#include "core/error.h"
#include "validator.h"

namespace maquette::test {
namespace {

using nlohmann::json;

const EnuOrigin kOrigin{-122.4194155, 37.7749295, 16.25};

// Normals: Draco's octahedral quantization of 10 bits is within 0.2 degrees (measured 0.16).
const double kNormalTolerance = 0.2 * std::numbers::pi / 180;

MeshContent textured_box() {
  MeshContent c;
  c.origin = kOrigin;
  c.materials.push_back({"brick",
                         {0.9f, 0.8f, 0.7f, 1},
                         0.f,
                         0.8f,
                         encoded_image("PNG", 32, 16),
                         "image/png",
                         false});
  c.objects.push_back(box({-5, -3, 0}, {10, 6, 12.5f}));
  c.objects[0].material = 0;
  c.objects[0].provenance = {0xFEEDFACECAFEBEEFull, 42, "structures.buildings", {{"height", 12.5}}};
  return c;
}

// Four objects in three primitives: two textured boxes (one far out: 1 km), a sphere of a plain
// material and one of glTF's default material.
MeshContent town() {
  MeshContent c;
  c.origin = kOrigin;
  c.materials.push_back(
      {"roof", {1, 1, 1, 1}, 0.f, 0.9f, encoded_image("JPEG", 64, 64), "image/jpeg", true});
  c.materials.push_back({"metal", {0.2f, 0.4f, 0.8f, 0.5f}, 0.75f, 0.3f, "", "", false});
  c.objects.push_back(box({12.25f, 40, 1.5f}, {8, 8, 20}));
  c.objects.push_back(sphere({3, -4, 10}, 2.5f, 24, 12));
  c.objects.push_back(box({996, -1000, 180}, {4, 3, 2}));
  c.objects.push_back(sphere({-20, 7, 3}, 1, 8, 5));
  c.objects[0].material = 0, c.objects[1].material = 1, c.objects[2].material = 0;
  c.objects[0].provenance = {
      1,
      7,
      "structures.buildings",
      {{"height", 20.0}, {"name", "Tower \"A\" \u00e9"}, {"floors", {1, 2}}}};
  c.objects[1].provenance = {2, -1, "water.tanks", json::object()};
  c.objects[2].provenance = {UINT64_MAX, INT64_MAX, "", {{"x", nullptr}}};
  c.objects[3].provenance = {4, 0, "t", {{"a", json::array()}}};
  return c;
}

// The GLB's JSON and BIN chunks.
std::pair<json, std::string> chunks(const std::string& glb) {
  uint32_t json_bytes;
  std::memcpy(&json_bytes, glb.data() + 12, 4);
  return {json::parse(glb.substr(20, json_bytes)), glb.substr(20 + json_bytes + 8)};
}

void expect_round_trip(const MeshContent& in, const MeshGlbSettings& settings = {}) {
  const std::string glb = encode_mesh_glb(in, settings);
  const MeshContent out = decode_mesh_glb(glb, in.origin, "test blob");
  EXPECT_EQ(out.origin, in.origin);
  EXPECT_EQ(out.materials, in.materials);  // images byte for byte, factors as float
  ASSERT_EQ(out.objects.size(), in.objects.size());
  for (size_t i = 0; i < in.objects.size(); ++i) {
    SCOPED_TRACE("object " + std::to_string(i));
    const MeshObject &a = in.objects[i], &b = out.objects[i];
    EXPECT_EQ(b.provenance, a.provenance);
    EXPECT_EQ(b.material, a.material);
    const MeshDifference d = compare_meshes(a, b);
    // Positions: a step of at most position_error, decoded within half of it.
    EXPECT_LE(d.position, settings.position_error / 2 * 1.001);
    EXPECT_LE(d.normal, kNormalTolerance);
    // uvs within 0..1: a step of at most 1 / (2^bits - 1), within half of it.
    EXPECT_LE(d.uv, 0.5 / ((1 << settings.texcoord_bits) - 1) * 1.001);
  }
}

TEST(MeshGlb, TexturedBoxRoundTrips) { expect_round_trip(textured_box()); }

TEST(MeshGlb, ObjectsOfSeveralMaterialsRoundTrip) { expect_round_trip(town()); }

TEST(MeshGlb, CoarserQuantizationStaysWithinItsStep) {
  MeshGlbSettings coarse;
  coarse.position_error = 0.05;
  coarse.texcoord_bits = 8;
  expect_round_trip(town(), coarse);
}

TEST(MeshGlb, WebpImagesGoThroughExtTextureWebp) {
  MeshContent c = textured_box();
  c.materials[0].image = encoded_image("WEBP", 16, 16);
  c.materials[0].image_mime = "image/webp";
  expect_round_trip(c);
  const json j = chunks(encode_mesh_glb(c)).first;
  EXPECT_EQ(j["textures"][0]["extensions"]["EXT_texture_webp"]["source"], 0);
  EXPECT_FALSE(j["textures"][0].contains("source"));
  EXPECT_EQ(j["extensionsRequired"],
            json::array({"KHR_draco_mesh_compression", "EXT_texture_webp"}));
}

TEST(MeshGlb, PositionBitsKeepTheStepWithinTheError) {
  const MeshGlbSettings s;
  EXPECT_EQ(position_bits(2000, s), 21);  // 2000 / (2^21 - 1) = 0.95 mm
  EXPECT_EQ(position_bits(1000, s), 20);
  EXPECT_EQ(position_bits(0, s), 1);
  EXPECT_EQ(position_bits(1e9, s), 30);  // Draco's largest
  for (double extent : {0.5, 7.3, 1234.5, 20000.0}) {
    const int bits = position_bits(extent, s);
    EXPECT_LE(extent / ((1 << bits) - 1), s.position_error);
    EXPECT_GT(extent / ((1 << (bits - 1)) - 1), s.position_error);
  }
}

TEST(MeshGlb, SameContentSameBytes) {
  EXPECT_EQ(encode_mesh_glb(town()), encode_mesh_glb(town()));
  const std::string a = encode_mesh_glb(textured_box());
  EXPECT_EQ(a, encode_mesh_glb(textured_box()));
}

TEST(MeshGlb, LayoutIsOnePrimitivePerMaterialWithFeatureIdsAndOnePropertyTable) {
  const json j = chunks(encode_mesh_glb(town())).first;
  const json& primitives = j["meshes"][0]["primitives"];
  ASSERT_EQ(primitives.size(), 3u);  // material 0 (two boxes), 1, none
  EXPECT_EQ(primitives[0]["material"], 0);
  EXPECT_EQ(primitives[1]["material"], 1);
  EXPECT_EQ(primitives[2]["material"], 2);  // the default grey, after the content's two
  EXPECT_EQ(primitives[0]["extensions"]["EXT_mesh_features"]["featureIds"][0]["featureCount"], 2);
  const json& table = j["extensions"]["EXT_structural_metadata"]["propertyTables"][0];
  EXPECT_EQ(table["count"], 4);
  EXPECT_EQ(j["extensionsRequired"], json::array({"KHR_draco_mesh_compression"}));
  EXPECT_EQ(j["images"][0]["mimeType"], "image/jpeg");
}

// Every primitive names its material, none a metal: glTF's default material (a primitive without
// `material`) and an absent metallicFactor mean metallic 1, which three.js without an environment
// map draws pure black wherever its sun does not reach (the campus picture's walls). The default
// grey is read back as no material (the round trips above).
TEST(MeshGlb, ObjectsWithoutAMaterialAreDrawnGreyNotMetal) {
  const json j = chunks(encode_mesh_glb(town())).first;
  ASSERT_EQ(j["materials"].size(), 3u);
  for (const json& prim : j["meshes"][0]["primitives"]) {
    ASSERT_TRUE(prim.contains("material"));
    const json& pbr = j["materials"][prim["material"].get<size_t>()]["pbrMetallicRoughness"];
    EXPECT_LT(pbr.value("metallicFactor", 1.0), 1) << prim["material"];
  }
  const json& grey = j["materials"][2];
  EXPECT_EQ(grey["name"], "default grey");
  EXPECT_EQ(grey["pbrMetallicRoughness"]["metallicFactor"], 0);
  EXPECT_EQ(grey["pbrMetallicRoughness"].value("roughnessFactor", 1.0), 1);
  EXPECT_NEAR(grey["pbrMetallicRoughness"]["baseColorFactor"][0].get<double>(), 0.6, 1e-6);
  // Content with a material for every object has no default grey.
  EXPECT_EQ(chunks(encode_mesh_glb(textured_box())).first["materials"].size(), 1u);
}

// The default grey is known by its mark, not its value: content's own material that equals it
// (name and factors) stays the object's material through a round trip.
TEST(MeshGlb, ContentsOwnGreyIsNotTakenForTheDefault) {
  MeshContent c = textured_box();
  Material grey;
  grey.name = "default grey";
  grey.base_colour = {0.6f, 0.6f, 0.6f, 1};
  c.materials = {grey};
  c.objects[0].material = 0;
  const std::string glb = encode_mesh_glb(c);
  EXPECT_EQ(chunks(glb).first["materials"].size(), 1u);
  const MeshContent out = decode_mesh_glb(glb, c.origin, "test blob");
  ASSERT_EQ(out.materials.size(), 1u);
  EXPECT_EQ(out.materials[0], grey);
  EXPECT_EQ(out.objects[0].material, 0);
}

// Read as EXT_structural_metadata specifies, without the decoder: the gltf-validator does not
// check this extension (nor EXT_mesh_features: it reports them as unsupported).
TEST(MeshGlb, PropertyTableFollowsExtStructuralMetadata) {
  const MeshContent c = town();
  const auto [j, bin] = chunks(encode_mesh_glb(c));
  const json& ext = j["extensions"]["EXT_structural_metadata"];
  const json& table = ext["propertyTables"][0];
  EXPECT_EQ(table["class"], "object");
  const json& properties = table["properties"];
  EXPECT_EQ(properties.size(), ext["schema"]["classes"]["object"]["properties"].size());
  // (&j = j, ...: clang 14, the fuzz build's compiler, cannot capture a structured binding)
  const auto view = [&j = j, &bin = bin](const json& index) {
    const json& v = j["bufferViews"][index.get<size_t>()];
    return std::pair{v["byteOffset"].get<size_t>(),
                     bin.substr(v["byteOffset"].get<size_t>(), v["byteLength"].get<size_t>())};
  };
  const auto [id_offset, ids] = view(properties["object_id"]["values"]);
  const auto [fid_offset, fids] = view(properties["feature_id"]["values"]);
  EXPECT_EQ(id_offset % 8, 0u);  // 64-bit values at offsets aligned to 8 bytes
  EXPECT_EQ(fid_offset % 8, 0u);
  ASSERT_EQ(ids.size(), 8 * c.objects.size());
  ASSERT_EQ(fids.size(), 8 * c.objects.size());
  // Unsigned integers of `type` (UINT8, UINT16, UINT32: the fewest bytes holding them).
  const auto integers = [&](const json& index, const std::string& type, size_t count) {
    const size_t size = type == "UINT8" ? 1 : type == "UINT16" ? 2 : 4;
    const std::string bytes = view(index).second;
    EXPECT_EQ(bytes.size(), size * count);
    std::vector<uint32_t> out(count, 0);
    for (size_t i = 0; i < count && bytes.size() == size * count; ++i)
      std::memcpy(&out[i], bytes.data() + size * i, size);  // little-endian
    return out;
  };
  // 4 objects' short strings: offsets of one byte.
  const auto strings = [&](const char* name) {
    EXPECT_EQ(properties[name]["stringOffsetType"], "UINT8");
    const std::string values = view(properties[name]["values"]).second;
    const auto offsets = integers(properties[name]["stringOffsets"], "UINT8", c.objects.size() + 1);
    std::vector<std::string> out;
    for (size_t i = 0; i < c.objects.size(); ++i)
      out.push_back(values.substr(offsets[i], offsets[i + 1] - offsets[i]));
    return out;
  };
  const auto tools = strings("tool"), attributes = strings("attributes");
  for (size_t i = 0; i < c.objects.size(); ++i) {
    uint64_t id;
    int64_t fid;
    std::memcpy(&id, ids.data() + 8 * i, 8);
    std::memcpy(&fid, fids.data() + 8 * i, 8);
    EXPECT_EQ(id, c.objects[i].provenance.object_id);
    EXPECT_EQ(fid, c.objects[i].provenance.feature_id);
    EXPECT_EQ(tools[i], c.objects[i].provenance.tool);
    EXPECT_EQ(json::parse(attributes[i]), c.objects[i].provenance.attributes);
  }
  for (const json& p : j["meshes"][0]["primitives"]) {
    const json& ids = p["extensions"]["EXT_mesh_features"]["featureIds"][0];
    EXPECT_EQ(ids["attribute"], 0);  // _FEATURE_ID_0, also in the Draco stream
    EXPECT_EQ(ids["propertyTable"], 0);
    EXPECT_TRUE(
        p["extensions"]["KHR_draco_mesh_compression"]["attributes"].contains("_FEATURE_ID_0"));
    EXPECT_EQ(j["accessors"][p["attributes"]["_FEATURE_ID_0"].get<size_t>()]["componentType"],
              5123);
  }
}

TEST(MeshGlb, ValidatorFindsNoErrorAndNoWarning) {
  const auto dir = std::filesystem::temp_directory_path() / "maquette_gltf_content_validator";
  std::filesystem::create_directories(dir);
  for (const auto& [name, content] : {std::pair{"box", textured_box()}, {"town", town()}}) {
    SCOPED_TRACE(name);
    const auto path = (dir / (std::string(name) + ".glb")).string();
    std::ofstream(path, std::ios::binary) << encode_mesh_glb(content);
    const auto report = validate_glb(path);
    if (!report) GTEST_SKIP() << "gltf-validator not installed";
    EXPECT_EQ(report->errors, 0) << report->messages;
    EXPECT_EQ(report->warnings, 0) << report->messages;
  }
  std::filesystem::remove_all(dir);
}

void expect_refused(const MeshContent& c, const std::string& fault) {
  try {
    encode_mesh_glb(c);
    ADD_FAILURE() << "encoded: " << fault;
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(fault), std::string::npos) << e.what();
  }
}

TEST(MeshGlb, BadContentIsRefusedNamingTheObject) {
  MeshContent c = town();
  c.objects[1].positions[4] = NAN;
  expect_refused(c, "object 1 (id 2): a position is not finite");
  c = town();
  c.objects[2].indices.back() = 9999;
  expect_refused(c, "object 2 (id 18446744073709551615): index 9999 is out of its 24 vertices");
  c = town();
  c.objects[0].material = 2;
  expect_refused(c, "object 0 (id 1): material 2 is not one of the 2");
  c = town();
  c.objects[3].normals.pop_back();
  expect_refused(c, "normals are not one per vertex");
  c = town();
  c.objects[3].indices.clear();
  expect_refused(c, "indices are not one or more triangles");
  expect_refused(MeshContent{}, "no objects");
  c = town();
  c.materials[1].roughness = 1.5f;
  expect_refused(c, "material 1 (metal): a factor of 1.500000, not within 0..1");
  c = town();
  c.materials[0].image_mime = "image/gif";
  expect_refused(c, "material 0 (roof): an image of type 'image/gif'");
}

TEST(MeshGlb, BadBlobsAreRefusedNamingWhere) {
  std::string glb = encode_mesh_glb(town());
  EXPECT_THROW(
      try { decode_mesh_glb(glb.substr(0, 10), kOrigin, "cell N3021"); } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("cell N3021: a GLB whose header"), std::string::npos)
            << e.what();
        throw;
      },
      Error);
  glb[glb.size() - 40] ^= 0x5A;  // inside the metadata strings: still decodes or says why
  try {
    decode_mesh_glb(glb, kOrigin, "cell N3021");
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("cell N3021"), std::string::npos) << e.what();
  }
  const std::string cut = encode_mesh_glb(town()).substr(0, 400);
  EXPECT_THROW(decode_mesh_glb(cut, kOrigin, "cell N3021"), Error);
}

}  // namespace
}  // namespace maquette::test
