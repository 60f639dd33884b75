// The EXT_mesh_gpu_instancing checker (tests/support) finds each kind of broken instancing in a
// GLB that it otherwise accepts.
#include <cmath>
#include <cstring>
#include <limits>

#include "gtest/gtest.h"
#include "instances_fixture.h"

namespace maquette::test {
namespace {

using nlohmann::json;

class Checker : public testing::Test {
 protected:
  void SetUp() override {
    const std::vector<char> bytes = builtin_instances_glb(forest(50, 7));
    glb = split_glb({bytes.data(), bytes.size()});
    ASSERT_EQ(gpu_instancing_problems(glb), std::vector<std::string>{});
  }
  json& accessor(const char* attribute) {
    const size_t i =
        glb.json["nodes"][0]["extensions"]["EXT_mesh_gpu_instancing"]["attributes"][attribute];
    return glb.json["accessors"][i];
  }
  // Overwrites the float at component k of instance 0's value of the attribute.
  void set_float(const char* attribute, size_t k, float value) {
    const json& view = glb.json["bufferViews"][size_t(accessor(attribute)["bufferView"])];
    std::memcpy(glb.bin.data() + size_t(view.value("byteOffset", 0)) + 4 * k, &value, 4);
  }
  // The one problem found, or all of them joined.
  std::string problem() {
    std::string all;
    for (const std::string& p : gpu_instancing_problems(glb)) all += (all.empty() ? "" : " | ") + p;
    return all;
  }
  GlbChunks glb;
};

TEST_F(Checker, FindsANonUnitQuaternion) {
  set_float("ROTATION", 3, 2);
  EXPECT_TRUE(problem().starts_with("node 0 ROTATION (accessor ")) << problem();
  EXPECT_NE(problem().find("instance 0: quaternion"), std::string::npos) << problem();
  // Twice the node's accessors: the crown's node shares them.
  EXPECT_EQ(gpu_instancing_problems(glb).size(), 2u);
}

TEST_F(Checker, AcceptsAQuaternionWithinItsTolerance) {
  const json& view = glb.json["bufferViews"][size_t(accessor("ROTATION")["bufferView"])];
  float q[4];
  std::memcpy(q, glb.bin.data() + size_t(view.value("byteOffset", 0)), 16);
  set_float("ROTATION", 3, q[3] * 1.0004f);  // |q| grows by less than 4e-4
  EXPECT_EQ(problem(), "");
}

TEST_F(Checker, FindsMismatchedCounts) {
  accessor("SCALE")["count"] = int(accessor("SCALE")["count"]) - 1;
  EXPECT_NE(problem().find("SCALE"), std::string::npos) << problem();
  EXPECT_NE(problem().find("instances, "), std::string::npos) << problem();
}

TEST_F(Checker, FindsZeroAndNonFiniteValues) {
  set_float("SCALE", 1, 0);
  EXPECT_NE(problem().find("SCALE (accessor"), std::string::npos) << problem();
  EXPECT_NE(problem().find("instance 0: component 1 is 0"), std::string::npos) << problem();
  SetUp();
  set_float("TRANSLATION", 2, std::numeric_limits<float>::quiet_NaN());
  EXPECT_NE(problem().find("instance 0: component 2 is not finite"), std::string::npos)
      << problem();
}

TEST_F(Checker, FindsWrongTypes) {
  accessor("ROTATION")["type"] = "VEC3";
  EXPECT_NE(problem().find("ROTATION (accessor"), std::string::npos) << problem();
  EXPECT_NE(problem().find("must be VEC4"), std::string::npos) << problem();
  SetUp();
  accessor("TRANSLATION")["componentType"] = 5122;  // shorts
  EXPECT_NE(problem().find("must be VEC3 of floats"), std::string::npos) << problem();
  SetUp();
  glb.json["nodes"][0]["extensions"]["EXT_mesh_gpu_instancing"]["attributes"]["COLOR_1"] = 0;
  EXPECT_NE(problem().find("neither TRANSLATION"), std::string::npos) << problem();
}

TEST_F(Checker, FindsAccessorsBeyondTheirBufferViewOrTheBinChunk) {
  accessor("TRANSLATION")["count"] = int(accessor("TRANSLATION")["count"]) * 2;
  EXPECT_NE(problem().find("exceed its"), std::string::npos) << problem();
  SetUp();
  glb.json["bufferViews"][size_t(accessor("SCALE")["bufferView"])]["byteLength"] =
      glb.bin.size() * 2;
  EXPECT_NE(problem().find("not within the BIN chunk"), std::string::npos) << problem();
}

TEST_F(Checker, FindsAnInstancedNodeWithoutMesh) {
  glb.json["nodes"][0].erase("mesh");
  EXPECT_EQ(problem(), "node 0: instanced but has no mesh");
}

TEST(SplitGlb, RefusesWhatIsNotAGlb) {
  EXPECT_THROW(split_glb("glTF"), std::runtime_error);
  std::vector<char> bytes = builtin_instances_glb(forest(3, 8));
  bytes.pop_back();
  EXPECT_THROW(split_glb({bytes.data(), bytes.size()}), std::runtime_error);
}

}  // namespace
}  // namespace maquette::test
