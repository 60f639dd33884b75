#include "model_files.h"

#include <gtest/gtest.h>

#include <cstring>
#include <fstream>

#include "content_fixture.h"

namespace maquette::test {
namespace {

using nlohmann::json;

template <class T>
void append(std::string& bin, std::initializer_list<T> values) {
  for (T v : values) bin.append(reinterpret_cast<const char*>(&v), sizeof v);
}

std::string base64(const std::string& bytes) {
  static const char* kDigits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < bytes.size(); i += 3) {
    const size_t n = std::min<size_t>(3, bytes.size() - i);
    uint32_t v = 0;
    for (size_t k = 0; k < 3; ++k) v = (v << 8) | (k < n ? uint8_t(bytes[i + k]) : 0u);
    for (size_t k = 0; k < 4; ++k) out.push_back(k <= n ? kDigits[(v >> (18 - 6 * k)) & 63] : '=');
  }
  return out;
}

}  // namespace

json one_primitive_gltf(const json& nodes, const json& roots, const json& material,
                        const json& accessors, const json& views, size_t buffer_bytes) {
  return {{"asset", {{"version", "2.0"}}},
          {"scene", 0},
          {"scenes", {{{"nodes", roots}}}},
          {"nodes", nodes},
          {"meshes",
           {{{"primitives",
              {{{"attributes", {{"POSITION", 0}, {"NORMAL", 1}, {"TEXCOORD_0", 2}}},
                {"indices", 3},
                {"material", 0}}}}}}},
          {"materials", {material}},
          {"textures", {{{"source", 0}}}},
          {"images", {json::object()}},
          {"accessors", accessors},
          {"bufferViews", views},
          {"buffers", {{{"byteLength", buffer_bytes}}}}};
}

ModelFile quad_model() {
  ModelFile m;
  // Positions, 16 bytes apart (x, y, z, padding).
  for (auto p : {std::array<float, 3>{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}})
    append<float>(m.bin, {p[0], p[1], p[2], -999.f});
  const size_t normals = m.bin.size();
  for (int i = 0; i < 4; ++i) append<float>(m.bin, {0, 1, 0});
  const size_t uvs = m.bin.size();
  append<uint16_t>(m.bin, {0, 0, 65535, 0, 65535, 65535, 0, 65535});
  const size_t indices = m.bin.size();
  append<uint8_t>(m.bin, {0, 3, 2, 0, 2, 1});  // counter-clockwise seen from +y
  while (m.bin.size() % 4) m.bin.push_back(0);
  m.image = encoded_image("PNG", 8, 8);
  m.gltf = one_primitive_gltf(
      {{{"translation", {10, 20, 30}}, {"children", {1}}},
       {{"rotation", {0, std::sqrt(0.5), 0, std::sqrt(0.5)}}, {"scale", {2, 2, 2}}, {"mesh", 0}},
       {{"scale", {-1, 1, 1}}, {"mesh", 0}}},
      {0, 2},
      {{"name", "quad"},
       {"pbrMetallicRoughness",
        {{"baseColorFactor", {0.5, 0.25, 1, 1}},
         {"roughnessFactor", 0.5},
         {"baseColorTexture", {{"index", 0}}}}}},
      {{{"bufferView", 0},
        {"componentType", 5126},
        {"count", 4},
        {"type", "VEC3"},
        {"min", {0, 0, 0}},
        {"max", {1, 0, 1}}},
       {{"bufferView", 1}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}},
       {{"bufferView", 2},
        {"componentType", 5123},
        {"normalized", true},
        {"count", 4},
        {"type", "VEC2"}},
       {{"bufferView", 3}, {"componentType", 5121}, {"count", 6}, {"type", "SCALAR"}}},
      {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", normals}, {"byteStride", 16}},
       {{"buffer", 0}, {"byteOffset", normals}, {"byteLength", uvs - normals}},
       {{"buffer", 0}, {"byteOffset", uvs}, {"byteLength", indices - uvs}},
       {{"buffer", 0}, {"byteOffset", indices}, {"byteLength", 6}}},
      m.bin.size());
  return m;
}

void write_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out << bytes;
  EXPECT_TRUE(out.good()) << path;
}

std::string write_external(const ModelFile& m, const std::string& dir, const std::string& name) {
  json j = m.gltf;
  j["buffers"][0]["uri"] = name + ".bin";
  j["images"][0]["uri"] = name + ".png";
  write_bytes(dir + "/" + name + ".bin", m.bin);
  write_bytes(dir + "/" + name + ".png", m.image);
  write_bytes(dir + "/" + name + ".gltf", j.dump(1));
  return dir + "/" + name + ".gltf";
}

std::string write_data_uris(const ModelFile& m, const std::string& dir, const std::string& name) {
  json j = m.gltf;
  j["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64(m.bin);
  j["images"][0]["uri"] = "data:image/png;base64," + base64(m.image);
  write_bytes(dir + "/" + name + ".gltf", j.dump());
  return dir + "/" + name + ".gltf";
}

std::string write_glb(const ModelFile& m, const std::string& dir, const std::string& name) {
  json j = m.gltf;
  std::string bin = m.bin;
  j["bufferViews"].push_back(
      {{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", m.image.size()}});
  j["images"][0] = {{"bufferView", j["bufferViews"].size() - 1}, {"mimeType", "image/png"}};
  bin += m.image;
  while (bin.size() % 4) bin.push_back(0);
  j["buffers"][0]["byteLength"] = bin.size();
  std::string text = j.dump();
  while (text.size() % 4) text.push_back(' ');
  std::string glb = "glTF";
  const auto u32 = [&](uint32_t v) { glb.append(reinterpret_cast<const char*>(&v), 4); };
  u32(2);
  u32(uint32_t(12 + 8 + text.size() + 8 + bin.size()));
  u32(uint32_t(text.size()));
  glb += "JSON" + text;
  u32(uint32_t(bin.size()));
  glb += std::string("BIN\0", 4) + bin;
  write_bytes(dir + "/" + name + ".glb", glb);
  return dir + "/" + name + ".glb";
}

}  // namespace maquette::test
