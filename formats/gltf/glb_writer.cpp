#include "gltf/glb_writer.h"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <limits>

#include "core/error.h"

namespace maquette {
namespace {

using nlohmann::json;

constexpr int kFloat = 5126, kUint32 = 5125;
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;

class GlbBuilder {
 public:
  int view(const void* data, size_t size, int target = 0) {
    while (bin_.size() % 4) bin_.push_back(0);
    json v = {{"buffer", 0}, {"byteOffset", bin_.size()}, {"byteLength", size}};
    if (target) v["target"] = target;
    const char* p = static_cast<const char*>(data);
    bin_.insert(bin_.end(), p, p + size);
    views_.push_back(v);
    return int(views_.size() - 1);
  }
  int accessor(json a) {
    accessors_.push_back(std::move(a));
    return int(accessors_.size() - 1);
  }
  void add(const GlbPrimitive& p);
  std::vector<char> finish(const json& extras);

 private:
  int material(const EncodedImage* image);

  std::vector<char> bin_;
  json views_ = json::array(), accessors_ = json::array(), meshes_ = json::array(),
       nodes_ = json::array(), materials_ = json::array(), images_ = json::array(),
       textures_ = json::array();
  bool draco_ = false;
};

json bounds(const std::vector<float>& pos, bool max) {
  std::array<float, 3> b;
  b.fill(max ? std::numeric_limits<float>::lowest() : std::numeric_limits<float>::max());
  for (size_t i = 0; i < pos.size(); ++i)
    b[i % 3] = max ? std::max(b[i % 3], pos[i]) : std::min(b[i % 3], pos[i]);
  return b;
}

int GlbBuilder::material(const EncodedImage* image) {
  json m = {{"pbrMetallicRoughness", {{"metallicFactor", 0}, {"roughnessFactor", 1}}},
            {"doubleSided", true}};  // skirts are seen from either side
  if (image) {
    images_.push_back({{"bufferView", view(image->bytes.data(), image->bytes.size())},
                       {"mimeType", image->mime_type}});
    textures_.push_back({{"sampler", 0}, {"source", images_.size() - 1}});
    m["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", textures_.size() - 1}};
  } else {
    m["pbrMetallicRoughness"]["baseColorFactor"] = {0.6, 0.6, 0.6, 1.0};
  }
  materials_.push_back(m);
  return int(materials_.size() - 1);
}

void GlbBuilder::add(const GlbPrimitive& p) {
  const TerrainMesh& m = *p.mesh;
  const size_t n = m.vertex_count();
  json pos = {{"componentType", kFloat},
              {"count", n},
              {"type", "VEC3"},
              {"min", bounds(m.positions, false)},
              {"max", bounds(m.positions, true)}};
  json nrm = {{"componentType", kFloat}, {"count", n}, {"type", "VEC3"}};
  json uv = {{"componentType", kFloat}, {"count", n}, {"type", "VEC2"}};
  json idx = {{"componentType", kUint32}, {"count", m.indices.size()}, {"type", "SCALAR"}};
  json prim = {{"mode", 4}};
  if (p.draco) {
    draco_ = true;
    prim["extensions"]["KHR_draco_mesh_compression"] = {
        {"bufferView", view(p.draco->data.data(), p.draco->data.size())},
        {"attributes",
         {{"POSITION", p.draco->position_id},
          {"NORMAL", p.draco->normal_id},
          {"TEXCOORD_0", p.draco->texcoord_id}}}};
  } else {
    pos["bufferView"] = view(m.positions.data(), m.positions.size() * 4, kArrayBuffer);
    nrm["bufferView"] = view(m.normals.data(), m.normals.size() * 4, kArrayBuffer);
    uv["bufferView"] = view(m.texcoords.data(), m.texcoords.size() * 4, kArrayBuffer);
    idx["bufferView"] = view(m.indices.data(), m.indices.size() * 4, kElementArrayBuffer);
  }
  prim["attributes"] = {
      {"POSITION", accessor(pos)}, {"NORMAL", accessor(nrm)}, {"TEXCOORD_0", accessor(uv)}};
  prim["indices"] = accessor(idx);
  prim["material"] = material(p.image);
  meshes_.push_back({{"name", p.name}, {"primitives", json::array({prim})}});
  nodes_.push_back({{"name", p.name}, {"mesh", meshes_.size() - 1}});
}

void append_u32(std::vector<char>& out, uint32_t v) {
  char b[4];
  std::memcpy(b, &v, 4);  // GLB is little-endian, as is every platform Maquette builds on
  out.insert(out.end(), b, b + 4);
}

std::vector<char> GlbBuilder::finish(const json& extras) {
  json nodes_of_scene = json::array();
  for (size_t i = 0; i < nodes_.size(); ++i) nodes_of_scene.push_back(i);
  json gltf = {{"asset", {{"version", "2.0"}, {"generator", "maquette"}}},
               {"scene", 0},
               {"scenes", {{{"nodes", nodes_of_scene}}}},
               {"nodes", nodes_},
               {"meshes", meshes_},
               {"materials", materials_},
               {"accessors", accessors_},
               {"bufferViews", views_}};
  if (!extras.is_null()) gltf["asset"]["extras"] = extras;
  if (!images_.empty()) {
    gltf["images"] = images_;
    gltf["textures"] = textures_;
    gltf["samplers"] = {
        {{"magFilter", 9729}, {"minFilter", 9729}, {"wrapS", 33071}, {"wrapT", 33071}}};
  }
  if (draco_) {
    gltf["extensionsUsed"] = {"KHR_draco_mesh_compression"};
    gltf["extensionsRequired"] = {"KHR_draco_mesh_compression"};
  }
  while (bin_.size() % 4) bin_.push_back(0);
  gltf["buffers"] = {{{"byteLength", bin_.size()}}};
  std::string text = gltf.dump();
  while (text.size() % 4) text.push_back(' ');

  std::vector<char> out;
  append_u32(out, 0x46546C67);  // "glTF"
  append_u32(out, 2);
  append_u32(out, uint32_t(12 + 8 + text.size() + 8 + bin_.size()));
  append_u32(out, uint32_t(text.size()));
  append_u32(out, 0x4E4F534A);  // "JSON"
  out.insert(out.end(), text.begin(), text.end());
  append_u32(out, uint32_t(bin_.size()));
  append_u32(out, 0x004E4942);  // "BIN\0"
  out.insert(out.end(), bin_.begin(), bin_.end());
  return out;
}

}  // namespace

std::vector<char> make_glb(const std::vector<GlbPrimitive>& primitives, const json& extras) {
  GlbBuilder b;
  for (const GlbPrimitive& p : primitives) b.add(p);
  return b.finish(extras);
}

void write_file(const std::string& path, const std::vector<char>& bytes) {
  std::ofstream f(path, std::ios::binary);
  f.write(bytes.data(), std::streamsize(bytes.size()));
  if (!f) throw Error("could not write " + path);
}

}  // namespace maquette
