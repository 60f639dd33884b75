// Outside models (gltf/gltf_model.h): a .gltf with its buffer and image beside it, one with data
// URIs, a GLB, a Draco GLB (mesh_glb's own output), node transforms composed (checked against
// the transforms worked out by hand), and each bad input refused naming the file and the fault.
#include "gltf/gltf_model.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "content_fixture.h"
#include "core/error.h"
#include "gltf/mesh_glb.h"
#include "model_files.h"

namespace maquette::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

class GltfModel : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = (fs::temp_directory_path() /
            ("maquette_gltf_model_" +
             std::string(::testing::UnitTest::GetInstance()->current_test_info()->name())))
               .string();
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  void expect_refused(const std::string& path, const std::string& fault) {
    try {
      read_gltf_model(path);
      ADD_FAILURE() << "read: " << fault;
    } catch (const Error& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find(path), std::string::npos) << message;
      EXPECT_NE(message.find(fault), std::string::npos) << message;
    }
  }

  std::string dir_;
};

// The quad's vertex p (glTF axes) where node 1 puts it, in ENU: T (10, 20, 30) after a rotation
// of 90 degrees about y ((x, y, z) -> (z, y, -x)) after a scale of 2, then (x, -z, y).
std::array<float, 3> placed_by_node1(std::array<float, 3> p) {
  return {10 + 2 * p[2], -(30 - 2 * p[0]), 20 + 2 * p[1]};
}

void expect_quad(const MeshContent& c, const ModelFile& m) {
  ASSERT_EQ(c.objects.size(), 2u);  // node 1 (below node 0), node 2
  ASSERT_EQ(c.materials.size(), 1u);
  EXPECT_EQ(c.materials[0].name, "quad");
  EXPECT_EQ(c.materials[0].base_colour, (std::array<float, 4>{0.5f, 0.25f, 1, 1}));
  EXPECT_EQ(c.materials[0].metallic, 1.f);  // glTF's default
  EXPECT_EQ(c.materials[0].roughness, 0.5f);
  EXPECT_EQ(c.materials[0].image, m.image);
  EXPECT_EQ(c.materials[0].image_mime, "image/png");
  const std::array<std::array<float, 3>, 4> quad = {{{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}}};
  const MeshObject &a = c.objects[0], &b = c.objects[1];
  ASSERT_EQ(a.positions.size(), 12u);
  ASSERT_EQ(b.positions.size(), 12u);
  for (size_t v = 0; v < 4; ++v) {
    const auto expected = placed_by_node1(quad[v]);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(a.positions[v * 3 + k], expected[k], 1e-5) << v;
    // Node 2 mirrors x: (-x, y, z), in ENU (-x, -z, y).
    EXPECT_EQ(b.positions[v * 3], -quad[v][0]);
    EXPECT_EQ(b.positions[v * 3 + 1], -quad[v][2]);
    EXPECT_EQ(b.positions[v * 3 + 2], quad[v][1]);
    for (const MeshObject* o : {&a, &b}) {  // up stays up
      EXPECT_NEAR(o->normals[v * 3], 0, 1e-6);
      EXPECT_NEAR(o->normals[v * 3 + 1], 0, 1e-6);
      EXPECT_NEAR(o->normals[v * 3 + 2], 1, 1e-6);
    }
  }
  EXPECT_EQ(a.uvs, (std::vector<float>{0, 0, 1, 0, 1, 1, 0, 1}));  // normalized unsigned shorts
  EXPECT_EQ(a.indices, (std::vector<uint32_t>{0, 3, 2, 0, 2, 1}));
  EXPECT_EQ(b.indices, (std::vector<uint32_t>{0, 2, 3, 0, 1, 2}));  // the mirror keeps the winding
  EXPECT_EQ(a.provenance.object_id, 0u);
  EXPECT_EQ(b.provenance.object_id, 1u);
  EXPECT_EQ(b.provenance.attributes["node"], 2);
}

TEST_F(GltfModel, ExternalBufferAndImage) {
  const ModelFile m = quad_model();
  expect_quad(read_gltf_model(write_external(m, dir_, "quad")), m);
}

TEST_F(GltfModel, DataUris) {
  const ModelFile m = quad_model();
  expect_quad(read_gltf_model(write_data_uris(m, dir_, "quad")), m);
}

TEST_F(GltfModel, Glb) {
  const ModelFile m = quad_model();
  expect_quad(read_gltf_model(write_glb(m, dir_, "quad")), m);
}

TEST_F(GltfModel, DracoGlbOfMeshContent) {
  MeshContent c;
  c.materials.push_back({"a", {1, 0, 0, 1}, 0.f, 1.f, "", "", false});
  c.objects.push_back(box({1, 2, 3}, {4, 5, 6}));
  c.objects.push_back(sphere({-3, 0, 2}, 1.5f, 12, 6));
  c.objects[0].material = 0;
  const std::string glb = encode_mesh_glb(c);
  write_bytes(dir_ + "/content.glb", glb);
  const MeshContent model = read_gltf_model(dir_ + "/content.glb");
  const MeshContent decoded = decode_mesh_glb(glb, c.origin, "content.glb");
  ASSERT_EQ(model.objects.size(), 2u);  // one per primitive: here one per object
  // The sphere has no material: the GLB draws it with its last, the default grey (mesh_glb.h),
  // which the model reader reads as any other.
  ASSERT_EQ(model.materials.size(), 2u);
  EXPECT_EQ(model.materials[0], decoded.materials[0]);
  EXPECT_EQ(model.materials[1].name, "default grey");
  EXPECT_EQ(model.materials[1].metallic, 0);
  EXPECT_EQ(model.objects[1].material, 1);
  EXPECT_EQ(decoded.materials.size(), 1u);
  EXPECT_EQ(decoded.objects[1].material, -1);
  for (size_t i = 0; i < 2; ++i) {
    const MeshDifference d = compare_meshes(decoded.objects[i], model.objects[i]);
    EXPECT_EQ(d.position, 0);   // the same decoded floats, the same axes
    EXPECT_LT(d.normal, 1e-6);  // the model reader normalizes them again
    EXPECT_LE(compare_meshes(c.objects[i], model.objects[i]).position, 0.0005);
  }
}

TEST_F(GltfModel, NotGltf) {
  write_bytes(dir_ + "/text.gltf", "hello, world");
  expect_refused(dir_ + "/text.gltf", "not glTF");
  write_bytes(dir_ + "/magic.glb", std::string("glTX\2\0\0\0\40\0\0\0", 12) + std::string(20, 'x'));
  expect_refused(dir_ + "/magic.glb", "not glTF");
  write_bytes(dir_ + "/v1.gltf", R"({"asset": {"version": "1.0"}})");
  expect_refused(dir_ + "/v1.gltf", "not glTF 2.0");
  expect_refused(dir_ + "/absent.glb", "no such file");
}

// Quoting a value nested a million deep overflowed the stack (fuzz/corpus/gltf_model/regress-*).
TEST_F(GltfModel, DeepNestingIsRefused) {
  const std::string path = dir_ + "/deep.gltf";
  const size_t depth = 1000000;
  std::ofstream(path) << R"({"asset": {"version": )" << std::string(depth, '[')
                      << std::string(depth, ']') << "}}";
  expect_refused(path, "not glTF: JSON: line 1, column 149: asset.version[0]");
  expect_refused(path, "nested deeper than 128 levels");
}

TEST_F(GltfModel, NoMesh) {
  ModelFile m = quad_model();
  m.gltf.erase("meshes");
  m.gltf["nodes"][1].erase("mesh");
  m.gltf["nodes"][2].erase("mesh");
  expect_refused(write_glb(m, dir_, "empty"), "no mesh");
}

TEST_F(GltfModel, BufferOfTwoGigabytesIsRefusedBeforeReading) {
  ModelFile m = quad_model();
  m.gltf["buffers"][0]["byteLength"] = 2147483648u;
  expect_refused(write_external(m, dir_, "huge"),
                 "buffers[0] declares 2147483648 bytes, more than the 1073741824 (1 GiB) read");
}

TEST_F(GltfModel, AccessorOutOfItsBufferView) {
  ModelFile m = quad_model();
  m.gltf["accessors"][0]["count"] = 5;
  expect_refused(write_external(m, dir_, "oob"),
                 "accessors[0]: 5 elements of 12 bytes from byte 0 (stride 16) are out of its "
                 "bufferView of 64 bytes");
  m = quad_model();
  m.gltf["bufferViews"][3]["byteOffset"] = 1000;
  expect_refused(write_external(m, dir_, "view"),
                 "bufferViews[3]: 6 bytes from byte 1000 are out of");
  // Sizes that wrap around 2^64 when added or multiplied are out of range too.
  m = quad_model();
  m.gltf["accessors"][0]["byteOffset"] = 18446744073709551612u;
  expect_refused(write_external(m, dir_, "wrap"), "from byte 18446744073709551612");
  m = quad_model();
  m.gltf["bufferViews"][0]["byteStride"] = 9223372036854775808u;
  expect_refused(write_external(m, dir_, "stride"),
                 "byteStride 9223372036854775808 is not a multiple of 4 in 4..252");
}

TEST_F(GltfModel, NodesMustFormTrees) {
  ModelFile m = quad_model();
  m.gltf["nodes"][2]["children"] = {1};  // node 1 is node 0's child already
  expect_refused(write_external(m, dir_, "two_parents"), "nodes[1] has more than one parent");
  m = quad_model();
  m.gltf["nodes"][0]["children"] = {7};
  expect_refused(write_external(m, dir_, "no_child"), "nodes[0].children lists node 7");
}

// Rewrites the buffer's and the image's URIs of the .gltf at `path`.
void set_uris(const std::string& path, const std::string& buffer, const std::string& image) {
  std::ifstream in(path);
  json j = json::parse(in);
  j["buffers"][0]["uri"] = buffer;
  j["images"][0]["uri"] = image;
  std::ofstream(path) << j.dump();
}

TEST_F(GltfModel, UrisArePercentDecodedAndStayInTheModelsFolder) {
  const std::string path = write_external(quad_model(), dir_, "my quad");
  set_uris(path, "my%20quad.bin", "my%20quad.png");
  expect_quad(read_gltf_model(path), quad_model());
  set_uris(path, "../my%20quad.bin", "my%20quad.png");
  expect_refused(path, "buffers[0]: the URI '../my%20quad.bin' leaves the model's folder");
  set_uris(path, "my%20quad.bin", dir_ + "/my%20quad.png");
  expect_refused(path, "images[0]: the URI '" + dir_ + "/my%20quad.png' leaves the model's folder");
  set_uris(path, "my%2quad.bin", "my%20quad.png");
  expect_refused(path, "buffers[0]: the URI 'my%2quad.bin' has a bad percent-encoding");
}

TEST_F(GltfModel, RelativePathFindsItsFiles) {
  const std::string path = write_external(quad_model(), dir_, "quad");
  const fs::path before = fs::current_path();
  fs::current_path(dir_);
  const MeshContent content = read_gltf_model(fs::path(path).filename().string());
  fs::current_path(before);
  EXPECT_EQ(content.objects.size(), 2u);
}

TEST_F(GltfModel, IndexOutOfTheVertices) {
  ModelFile m = quad_model();
  m.bin[m.gltf["bufferViews"][3]["byteOffset"].get<size_t>() + 4] = char(200);
  expect_refused(write_external(m, dir_, "index"), "index 200 is out of its 4 vertices");
}

TEST_F(GltfModel, LinesAreNotTriangles) {
  ModelFile m = quad_model();
  m.gltf["meshes"][0]["primitives"][0]["mode"] = 1;
  expect_refused(write_external(m, dir_, "lines"),
                 "meshes[0].primitives[0] has mode 1: only triangles (mode 4) are read");
}

TEST_F(GltfModel, MissingFiles) {
  const ModelFile m = quad_model();
  const std::string path = write_external(m, dir_, "quad");
  fs::remove(dir_ + "/quad.png");
  expect_refused(path, "images[0]: cannot read '" + dir_ + "/quad.png': no such file");
  fs::remove(dir_ + "/quad.bin");
  expect_refused(path, "buffers[0]: cannot read '" + dir_ + "/quad.bin': no such file");
}

TEST_F(GltfModel, BufferShorterThanDeclared) {
  ModelFile m = quad_model();
  m.gltf["buffers"][0]["byteLength"] = m.bin.size() + 100;
  expect_refused(write_external(m, dir_, "short"), "holds " + std::to_string(m.bin.size()));
}

TEST_F(GltfModel, FieldOfTheWrongType) {
  ModelFile m = quad_model();
  m.gltf["meshes"][0]["primitives"][0]["material"] = "zero";
  expect_refused(write_external(m, dir_, "type"),
                 "meshes[0].primitives[0].material is \"zero\", not an index");
  m = quad_model();
  m.gltf["meshes"][0]["primitives"][0]["material"] = -7;
  expect_refused(write_external(m, dir_, "negative"),
                 "meshes[0].primitives[0].material is -7, not an index");
}

TEST_F(GltfModel, UnknownRequiredExtension) {
  ModelFile m = quad_model();
  m.gltf["extensionsRequired"] = {"EXT_meshopt_compression"};
  expect_refused(write_external(m, dir_, "meshopt"),
                 "requires the extension \"EXT_meshopt_compression\", which is not read");
}

}  // namespace
}  // namespace maquette::test
