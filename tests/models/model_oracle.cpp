#include "model_oracle.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "content_fixture.h"

namespace maquette::test {
namespace {

using nlohmann::json;

template <class T>
void append(std::string& bin, const std::vector<T>& values) {
  bin.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
}

// The ENU vectors of `enu` in glTF's axes: (x, y, z) -> (x, z, -y).
std::vector<float> gltf_axes(const std::vector<float>& enu) {
  std::vector<float> out;
  for (size_t i = 0; i < enu.size(); i += 3)
    out.insert(out.end(), {enu[i], enu[i + 2], -enu[i + 1]});
  return out;
}

json view(size_t offset, size_t length) {
  return {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", length}};
}

// The elements of accessor `index` (tightly packed, as box_model writes them).
template <class T>
std::vector<T> accessor(const json& gltf, const std::string& bin, int index, int components) {
  const json& a = gltf["accessors"][index];
  const json& v = gltf["bufferViews"][a["bufferView"].get<int>()];
  const size_t offset = v.value("byteOffset", size_t(0)) + a.value("byteOffset", size_t(0));
  std::vector<T> out(a["count"].get<size_t>() * size_t(components));
  EXPECT_LE(offset + out.size() * sizeof(T), bin.size());
  std::memcpy(out.data(), bin.data() + offset, out.size() * sizeof(T));
  return out;
}

}  // namespace

ModelFile box_model(const std::array<float, 4>& colour) {
  const MeshObject enu = box({-1, -0.5f, 0.5f}, {2, 1, 3});
  const std::vector<float> positions = gltf_axes(enu.positions), normals = gltf_axes(enu.normals);
  std::array<float, 3> lo{1e9f, 1e9f, 1e9f}, hi{-1e9f, -1e9f, -1e9f};
  for (size_t i = 0; i < positions.size(); ++i) {
    lo[i % 3] = std::min(lo[i % 3], positions[i]);
    hi[i % 3] = std::max(hi[i % 3], positions[i]);
  }
  ModelFile m;
  append(m.bin, positions);
  const size_t normals_at = m.bin.size();
  append(m.bin, normals);
  const size_t uvs_at = m.bin.size();
  append(m.bin, enu.uvs);
  const size_t indices_at = m.bin.size();
  append(m.bin, std::vector<uint16_t>(enu.indices.begin(), enu.indices.end()));
  const size_t end = m.bin.size();
  while (m.bin.size() % 4) m.bin.push_back(0);
  const size_t vertices = positions.size() / 3;
  m.image = encoded_image("PNG", 16, 16);
  m.gltf = one_primitive_gltf(
      {{{"mesh", 0}, {"name", "box"}}}, {0},
      {{"name", "crate"},
       {"pbrMetallicRoughness",
        {{"baseColorFactor", colour},
         {"metallicFactor", 0.25},
         {"roughnessFactor", 0.75},
         {"baseColorTexture", {{"index", 0}}}}}},
      {{{"bufferView", 0},
        {"componentType", 5126},
        {"count", vertices},
        {"type", "VEC3"},
        {"min", lo},
        {"max", hi}},
       {{"bufferView", 1}, {"componentType", 5126}, {"count", vertices}, {"type", "VEC3"}},
       {{"bufferView", 2}, {"componentType", 5126}, {"count", vertices}, {"type", "VEC2"}},
       {{"bufferView", 3},
        {"componentType", 5123},
        {"count", enu.indices.size()},
        {"type", "SCALAR"}}},
      {view(0, normals_at), view(normals_at, uvs_at - normals_at),
       view(uvs_at, indices_at - uvs_at), view(indices_at, end - indices_at)},
      m.bin.size());
  m.gltf["asset"]["generator"] = "maquette tests/models";
  return m;
}

MeshObject stored_object_oracle(const std::string& path) {
  const json gltf = json::parse(std::ifstream(path));
  const auto bin_path =
      std::filesystem::path(path).parent_path() / gltf["buffers"][0]["uri"].get<std::string>();
  std::ifstream in(bin_path, std::ios::binary);
  const std::string bin((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const json& attributes = gltf["meshes"][0]["primitives"][0]["attributes"];
  const auto positions = accessor<float>(gltf, bin, attributes["POSITION"], 3);
  const auto normals = accessor<float>(gltf, bin, attributes["NORMAL"], 3);
  MeshObject o;
  o.uvs = accessor<float>(gltf, bin, attributes["TEXCOORD_0"], 2);
  for (uint16_t i : accessor<uint16_t>(gltf, bin, gltf["meshes"][0]["primitives"][0]["indices"], 1))
    o.indices.push_back(i);
  float base = 1e9f;
  for (size_t i = 0; i < positions.size(); i += 3) base = std::min(base, positions[i + 1]);
  for (size_t i = 0; i < positions.size(); i += 3) {
    o.positions.insert(o.positions.end(),
                       {positions[i], -positions[i + 2], positions[i + 1] - base});
    o.normals.insert(o.normals.end(), {normals[i], -normals[i + 2], normals[i + 1]});
  }
  return o;
}

}  // namespace maquette::test
