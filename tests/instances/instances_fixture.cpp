#include "instances_fixture.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <random>

#include "content/prototypes.h"
#include "gltf/instances_glb.h"

namespace maquette::test {

InstancesContent forest(size_t count, uint32_t seed) {
  std::mt19937 rng(seed);
  auto uniform = [&rng](double lo, double hi) { return lo + (hi - lo) * (rng() / 4294967296.0); };
  InstancesContent c;
  c.origin = {7.25, 46.5, 600};
  c.prototypes = builtin_prototype_names();
  for (size_t i = 0; i < count; ++i) {
    c.prototype.push_back(uint16_t(rng() % 3));
    c.position.insert(c.position.end(), {float(uniform(-500, 500)), float(uniform(-500, 500)),
                                         float(uniform(-20, 20))});
    // A turn about the vertical, then a tilt of up to 0.1 rad about an horizontal axis.
    const double yaw = uniform(0, 2 * std::numbers::pi), tilt = uniform(0, 0.1);
    const double axis = uniform(0, 2 * std::numbers::pi);
    const std::array<double, 4> turn = {0, 0, std::sin(yaw / 2), std::cos(yaw / 2)};
    const std::array<double, 4> lean = {std::cos(axis) * std::sin(tilt / 2),
                                        std::sin(axis) * std::sin(tilt / 2), 0, std::cos(tilt / 2)};
    // lean * turn (Hamilton product, x y z w).
    const auto& a = lean;
    const auto& b = turn;
    const std::array<double, 4> q = {a[3] * b[0] + a[0] * b[3] + a[1] * b[2] - a[2] * b[1],
                                     a[3] * b[1] - a[0] * b[2] + a[1] * b[3] + a[2] * b[0],
                                     a[3] * b[2] + a[0] * b[1] - a[1] * b[0] + a[2] * b[3],
                                     a[3] * b[3] - a[0] * b[0] - a[1] * b[1] - a[2] * b[2]};
    for (double v : q) c.rotation.push_back(float(v));
    const double s = uniform(1, 20);
    c.scale.insert(c.scale.end(),
                   {float(s * uniform(0.9, 1.1)), float(s * uniform(0.9, 1.1)), float(s)});
    const uint32_t r = 200 + rng() % 56, g = 200 + rng() % 56, bl = 200 + rng() % 56;
    c.colour.push_back(r | g << 8 | bl << 16 | 255u << 24);
  }
  return c;
}

std::vector<char> builtin_instances_glb(const InstancesContent& content) {
  std::vector<const MeshContent*> models;
  for (const std::string& name : content.prototypes) models.push_back(&builtin_prototype(name));
  return instances_glb(content, models);
}

void write_bytes(const std::string& path, const std::vector<char>& bytes) {
  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  std::ofstream(path, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
}

std::optional<std::string> validator_errors(const std::string& dir) {
  const std::string node = MAQUETTE_NODE_DIR;
  if (!std::filesystem::exists(node + "/node_modules/gltf-validator")) return std::nullopt;
  const std::string cmd = "node " + node + "/validate.mjs " + dir + " 2>&1";
  FILE* pipe = popen(cmd.c_str(), "r");
  std::string out;
  char buffer[4096];
  for (size_t n; (n = fread(buffer, 1, sizeof buffer, pipe)) > 0;) out.append(buffer, n);
  return pclose(pipe) == 0 ? "" : "validate.mjs: " + out;
}

}  // namespace maquette::test
