// Instances as GLB: valid glTF (the Khronos validator, 0 errors) with valid EXT_mesh_gpu_instancing
// (tests/support's checker), each prototype written once, each instance where its ENU transform
// puts it, the same bytes each time, and clear errors for inconsistent content.
#include "gltf/instances_glb.h"

#include <cmath>
#include <map>
#include <numbers>

#include "content/prototypes.h"
#include "core/error.h"
#include "gtest/gtest.h"
#include "instances_fixture.h"

namespace maquette::test {
namespace {

using nlohmann::json;

std::string_view view(const std::vector<char>& bytes) { return {bytes.data(), bytes.size()}; }

// The instancing attributes of `node`.
json instancing(const GlbChunks& glb, size_t node) {
  return glb.json["nodes"][node]["extensions"]["EXT_mesh_gpu_instancing"]["attributes"];
}

TEST(InstancesGlb, AThousandInstancesPassTheValidatorAndTheInstancingChecker) {
  const InstancesContent c = forest(1000, 1);
  const std::vector<char> bytes = builtin_instances_glb(c);
  const std::string dir = std::string(MAQUETTE_INSTANCES_OUT) + "/forest";
  write_bytes(dir + "/forest.glb", bytes);
  const GlbChunks glb = split_glb(view(bytes));
  EXPECT_EQ(gpu_instancing_problems(glb), std::vector<std::string>{});
  if (const auto errors = validator_errors(dir))
    EXPECT_EQ(*errors, "");
  else
    ADD_FAILURE() << "gltf-validator is not installed (tests/tiles3d installs it with npm)";

  // Each prototype's two objects once, sharing one set of instance accessors, as many instances
  // as the content has of it.
  ASSERT_EQ(glb.json["nodes"].size(), 6u);
  ASSERT_EQ(glb.json["meshes"].size(), 6u);
  EXPECT_EQ(glb.json["extensionsRequired"], json::array({"EXT_mesh_gpu_instancing"}));
  std::map<size_t, size_t> per_prototype;
  for (uint16_t p : c.prototype) ++per_prototype[p];
  size_t geometry = 0;  // bytes of the prototypes' positions, normals and indices
  for (size_t p = 0; p < 3; ++p) {
    const json a = instancing(glb, 2 * p), b = instancing(glb, 2 * p + 1);
    EXPECT_EQ(a, b);
    EXPECT_EQ(glb.json["accessors"][size_t(a["TRANSLATION"])]["count"], per_prototype[p]);
    const MeshContent& model = builtin_prototype(c.prototypes[p]);
    const size_t mesh = glb.json["nodes"][2 * p]["mesh"];
    const size_t position = glb.json["meshes"][mesh]["primitives"][0]["attributes"]["POSITION"];
    EXPECT_EQ(glb.json["accessors"][position]["count"], model.objects[0].positions.size() / 3);
    for (const MeshObject& o : model.objects)
      geometry += 4 * (o.positions.size() + o.normals.size() + o.indices.size());
  }
  // Each prototype once, 44 bytes per instance (3 + 4 + 3 floats, 4 colour bytes), the JSON.
  EXPECT_LT(bytes.size(), geometry + 1000 * 44 + 8000);
}

// Instance values come through in glTF's axes: translation (x, z, -y), the rotation's axis as a
// vector, scales swapped as the axes are, the colour's bytes.
TEST(InstancesGlb, KeepsEachInstancesValuesInGltfAxes) {
  const InstancesContent c = forest(300, 2);
  const GlbChunks glb = split_glb(view(builtin_instances_glb(c)));
  std::map<size_t, size_t> next;  // per prototype, its instances met so far
  for (size_t i = 0; i < c.size(); ++i) {
    const size_t p = c.prototype[i], k = next[p]++;
    const json a = instancing(glb, 2 * p);
    const auto t = accessor_values(glb, a["TRANSLATION"]);
    const auto q = accessor_values(glb, a["ROTATION"]);
    const auto s = accessor_values(glb, a["SCALE"]);
    const auto colour = accessor_values(glb, a["_COLOR_0"]);
    const float* x = &c.position[3 * i];
    EXPECT_EQ(t[3 * k], x[0]);
    EXPECT_EQ(t[3 * k + 1], x[2]);
    EXPECT_EQ(t[3 * k + 2], -x[1]);
    const float* r = &c.rotation[4 * i];
    EXPECT_EQ(q[4 * k], r[0]);
    EXPECT_EQ(q[4 * k + 1], r[2]);
    EXPECT_EQ(q[4 * k + 2], -r[1]);
    EXPECT_EQ(q[4 * k + 3], r[3]);
    const float* z = &c.scale[3 * i];
    EXPECT_EQ(s[3 * k], z[0]);
    EXPECT_EQ(s[3 * k + 1], z[2]);
    EXPECT_EQ(s[3 * k + 2], z[1]);
    for (int b = 0; b < 4; ++b)
      EXPECT_EQ(std::lround(colour[4 * k + size_t(b)] * 255), long((c.colour[i] >> (8 * b)) & 255));
  }
}

using V = std::array<double, 3>;

// v turned by the unit quaternion q (x, y, z, w): v + 2w (u x v) + 2 u x (u x v).
V rotate(const std::array<double, 4>& q, const V& v) {
  auto cross = [](const V& a, const V& b) {
    return V{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  };
  const V u = {q[0], q[1], q[2]};
  const V uv = cross(u, v), uuv = cross(u, uv);
  return {v[0] + 2 * (q[3] * uv[0] + uuv[0]), v[1] + 2 * (q[3] * uv[1] + uuv[1]),
          v[2] + 2 * (q[3] * uv[2] + uuv[2])};
}

// A viewer draws vertex p of an instance at T + R (S p) in glTF's axes; that point must be where
// the instance's own transform puts p in the ENU frame. The oracle: a conifer scaled (2, 3, 10)
// and turned 90 degrees anticlockwise seen from above, so that its east side faces north.
TEST(InstancesGlb, PutsEveryVertexWhereTheEnuTransformDoes) {
  InstancesContent c;
  c.prototypes = {"builtin:conifer"};
  c.prototype = {0};
  c.position = {100, 200, 30};
  c.rotation = {0, 0, float(std::sin(std::numbers::pi / 4)), float(std::cos(std::numbers::pi / 4))};
  c.scale = {2, 3, 10};
  c.colour = {0xffffffff};
  const GlbChunks glb = split_glb(view(builtin_instances_glb(c)));
  const json a = instancing(glb, 1);
  const auto t = accessor_values(glb, a["TRANSLATION"]);
  const auto q = accessor_values(glb, a["ROTATION"]);
  const auto s = accessor_values(glb, a["SCALE"]);
  const size_t mesh = glb.json["nodes"][1]["mesh"];
  const auto p =
      accessor_values(glb, glb.json["meshes"][mesh]["primitives"][0]["attributes"]["POSITION"]);
  const MeshObject& crown = builtin_prototype("builtin:conifer").objects[1];
  ASSERT_EQ(p.size(), crown.positions.size());
  for (size_t i = 0; i < p.size(); i += 3) {
    const V drawn =
        rotate({q[0], q[1], q[2], q[3]}, {s[0] * p[i], s[1] * p[i + 1], s[2] * p[i + 2]});
    // ENU: scaled, then (e, n) -> (-n, e), then moved.
    const V e = {2.0 * crown.positions[i], 3.0 * crown.positions[i + 1],
                 10.0 * crown.positions[i + 2]};
    const V enu = {100 - e[1], 200 + e[0], 30 + e[2]};
    EXPECT_NEAR(t[0] + drawn[0], enu[0], 1e-4);
    EXPECT_NEAR(t[1] + drawn[1], enu[2], 1e-4);
    EXPECT_NEAR(t[2] + drawn[2], -enu[1], 1e-4);
  }
}

// The scene of docs/builtin-prototypes.png (tests/instances/grove_picture.mjs): a row of firs
// behind a row of broadleaf trees behind a row of shrubs, of various heights and tints.
TEST(InstancesGlb, WritesTheGroveOfThePicture) {
  InstancesContent c;
  c.prototypes = builtin_prototype_names();
  auto plant = [&c](uint16_t prototype, float x, float y, float height, float yaw, uint32_t tint) {
    c.prototype.push_back(prototype);
    c.position.insert(c.position.end(), {x, y, 0});
    c.rotation.insert(c.rotation.end(), {0, 0, std::sin(yaw / 2), std::cos(yaw / 2)});
    c.scale.insert(c.scale.end(), {height, height, height});
    c.colour.push_back(tint);
  };
  const float firs[] = {11, 14, 9, 12.5f};
  for (int i = 0; i < 4; ++i)
    plant(0, -10.5f + 7 * float(i), 10 + float(i % 2), firs[i], float(i), 0xffffffff);
  const float broadleaves[] = {8, 10, 7};
  const uint32_t leaf_tints[] = {0xffffffff, 0xff40c0ff, 0xffffe8d8};  // olive, bluish
  for (int i = 0; i < 3; ++i)
    plant(1, -8 + 8 * float(i), 2 + float(i % 2), broadleaves[i], float(i), leaf_tints[i]);
  for (int i = 0; i < 6; ++i)
    plant(2, -11 + 4.5f * float(i), -4 - float(i % 2), 1.2f + 0.3f * float(i % 3), float(i),
          i % 2 ? 0xffffffff : 0xffd0f0ff);
  const std::vector<char> bytes = builtin_instances_glb(c);
  const std::string dir = std::string(MAQUETTE_INSTANCES_OUT) + "/grove";
  write_bytes(dir + "/grove.glb", bytes);
  EXPECT_EQ(gpu_instancing_problems(split_glb(view(bytes))), std::vector<std::string>{});
  if (const auto errors = validator_errors(dir)) {
    EXPECT_EQ(*errors, "");
  }
}

TEST(InstancesGlb, IsTheSameBytesEachTime) {
  const InstancesContent c = forest(500, 3);
  EXPECT_EQ(builtin_instances_glb(c), builtin_instances_glb(c));
}

TEST(InstancesGlb, LeavesOutPrototypesWithoutInstances) {
  InstancesContent c = forest(10, 4);
  for (uint16_t& p : c.prototype) p = 2;
  const GlbChunks glb = split_glb(view(builtin_instances_glb(c)));
  ASSERT_EQ(glb.json["nodes"].size(), 2u);
  EXPECT_EQ(glb.json["nodes"][0]["name"], "builtin:shrub bark");
  EXPECT_EQ(gpu_instancing_problems(glb), std::vector<std::string>{});
}

TEST(InstancesGlb, InconsistentContentIsAClearError) {
  auto error_of = [](const InstancesContent& c) -> std::string {
    try {
      builtin_instances_glb(c);
    } catch (const Error& e) {
      return e.what();
    }
    return "no error";
  };
  InstancesContent c = forest(5, 5);
  c.rotation.pop_back();
  EXPECT_EQ(error_of(c),
            "instances content: column rotation has 19 values for 5 instances (4 per instance)");
  c = forest(5, 5);
  c.prototype[3] = 3;
  EXPECT_EQ(error_of(c), "instances content: instance 3 has prototype 3 of 3");
  c = forest(5, 5);
  c.prototypes[1] = "builtin:palm";
  EXPECT_EQ(error_of(c),
            "unknown prototype 'builtin:palm' (built in: builtin:conifer, builtin:broadleaf, "
            "builtin:shrub)");
  EXPECT_EQ(error_of(forest(0, 5)),
            "instances content: no instances (a cell without any has no content)");
  const MeshContent& shrub = builtin_prototype("builtin:shrub");
  EXPECT_THROW(instances_glb(forest(5, 5), {&shrub}), Error);  // one model for three names
  EXPECT_THROW(instances_glb(forest(5, 5), {&shrub, nullptr, &shrub}), Error);
}

}  // namespace
}  // namespace maquette::test
