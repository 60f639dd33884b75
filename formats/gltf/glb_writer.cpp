#include "gltf/glb_writer.h"

#include <algorithm>
#include <cstring>
#include <limits>
#include <map>

#include "core/error.h"
#include "core/output_file.h"

namespace maquette {
namespace {

using nlohmann::json;

constexpr int kFloat = 5126, kUint32 = 5125, kUint8 = 5121;
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;

class GlbBuilder {
 public:
  void add(const GlbPrimitive& p);
  std::vector<char> finish(const json& extras);

 private:
  int material(const GlbPrimitive& p);
  int content_material_index(const Material& m);
  // The index of `sampler` in the file, added on first use.
  int sampler(const json& sampler);
  // A float accessor of its own bufferView (instance attributes).
  int floats(const std::vector<float>& values, int components, const char* type);
  void use(const std::string& extension);

  GlbBuffer buffer_;
  json meshes_ = json::array(), nodes_ = json::array(), materials_ = json::array(),
       images_ = json::array(), textures_ = json::array(), samplers_ = json::array();
  std::vector<std::string> extensions_;
  std::map<const Material*, int> content_materials_;      // the index written for each
  std::map<const InstanceTransforms*, json> instancing_;  // the accessors written for each
};

json bounds(const std::vector<float>& pos, bool max) {
  std::array<float, 3> b;
  b.fill(max ? std::numeric_limits<float>::lowest() : std::numeric_limits<float>::max());
  for (size_t i = 0; i < pos.size(); ++i)
    b[i % 3] = max ? std::max(b[i % 3], pos[i]) : std::min(b[i % 3], pos[i]);
  return b;
}

int GlbBuilder::floats(const std::vector<float>& values, int components, const char* type) {
  return buffer_.accessor({{"componentType", kFloat},
                           {"count", values.size() / size_t(components)},
                           {"type", type},
                           {"bufferView", buffer_.view(values.data(), values.size() * 4)}});
}

void GlbBuilder::use(const std::string& extension) {
  if (std::ranges::find(extensions_, extension) == extensions_.end())
    extensions_.push_back(extension);
}

int GlbBuilder::sampler(const json& sampler) {
  auto it = std::ranges::find(samplers_, sampler);
  if (it != samplers_.end()) return int(it - samplers_.begin());
  samplers_.push_back(sampler);
  return int(samplers_.size() - 1);
}

int GlbBuilder::content_material_index(const Material& m) {
  auto [it, added] = content_materials_.emplace(&m, int(materials_.size()));
  if (added) {
    const int s = m.image.empty() ? 0 : sampler(content_sampler());
    materials_.push_back(content_material(m, buffer_, images_, textures_, s));
    if (m.image_mime == "image/webp") use("EXT_texture_webp");
  }
  return it->second;
}

int GlbBuilder::material(const GlbPrimitive& p) {
  if (p.material) return content_material_index(*p.material);
  const EncodedImage* image = p.image;
  // Single-sided (glTF's default): a double-sided material lights back faces with the normal
  // reversed, and a terrain tile's own skirt, seen from behind along the tile's edge where it
  // meets the surface, drew dark dotted lines along every seam.
  json m = {{"pbrMetallicRoughness", {{"metallicFactor", 0}, {"roughnessFactor", 1}}}};
  if (image) {
    images_.push_back({{"bufferView", buffer_.view(image->bytes.data(), image->bytes.size())},
                       {"mimeType", image->mime_type}});
    // Clamped, not mipmapped: a terrain tile's texture ends at the tile's edge.
    const int s =
        sampler({{"magFilter", 9729}, {"minFilter", 9729}, {"wrapS", 33071}, {"wrapT", 33071}});
    textures_.push_back({{"sampler", s}, {"source", images_.size() - 1}});
    m["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", textures_.size() - 1}};
  } else {
    m["pbrMetallicRoughness"]["baseColorFactor"] = {p.color[0], p.color[1], p.color[2], 1.0};
  }
  materials_.push_back(m);
  return int(materials_.size() - 1);
}

void GlbBuilder::add(const GlbPrimitive& p) {
  const TerrainMesh& m = *p.mesh;
  const size_t n = m.vertex_count();
  const std::vector<float> positions(m.positions.begin(), m.positions.end());
  json pos = {{"componentType", kFloat},
              {"count", n},
              {"type", "VEC3"},
              {"min", bounds(positions, false)},
              {"max", bounds(positions, true)}};
  json idx = {{"componentType", kUint32}, {"count", m.indices.size()}, {"type", "SCALAR"}};
  // The attributes present: name, values, draco id, accessor.
  struct Attribute {
    const char* name;
    const std::vector<float>& values;
    int draco_id;
    json accessor;
  };
  std::vector<Attribute> atts = {{"POSITION", positions, p.draco ? p.draco->position_id : -1, pos}};
  if (!m.normals.empty())
    atts.push_back({"NORMAL",
                    m.normals,
                    p.draco ? p.draco->normal_id : -1,
                    {{"componentType", kFloat}, {"count", n}, {"type", "VEC3"}}});
  if (!m.texcoords.empty())
    atts.push_back({"TEXCOORD_0",
                    m.texcoords,
                    p.draco ? p.draco->texcoord_id : -1,
                    {{"componentType", kFloat}, {"count", n}, {"type", "VEC2"}}});
  json prim = {{"mode", 4}};
  if (p.draco) {
    use("KHR_draco_mesh_compression");
    json ids;
    for (const Attribute& a : atts) ids[a.name] = a.draco_id;
    prim["extensions"]["KHR_draco_mesh_compression"] = {
        {"bufferView", buffer_.view(p.draco->data.data(), p.draco->data.size())},
        {"attributes", ids}};
  } else {
    for (Attribute& a : atts)
      a.accessor["bufferView"] = buffer_.view(a.values.data(), a.values.size() * 4, kArrayBuffer);
    idx["bufferView"] = buffer_.view(m.indices.data(), m.indices.size() * 4, kElementArrayBuffer);
  }
  for (const Attribute& a : atts) prim["attributes"][a.name] = buffer_.accessor(a.accessor);
  prim["indices"] = buffer_.accessor(idx);
  prim["material"] = material(p);
  meshes_.push_back({{"name", p.name}, {"primitives", json::array({prim})}});
  json node = {{"name", p.name}, {"mesh", meshes_.size() - 1}};
  if (m.offset != Vec3{}) node["translation"] = m.offset;  // in double: precise far away
  if (p.instances) {
    use("EXT_mesh_gpu_instancing");
    json& attributes = instancing_[p.instances];
    if (attributes.is_null()) {
      const InstanceTransforms& t = *p.instances;
      attributes = {{"TRANSLATION", floats(t.translation, 3, "VEC3")},
                    {"ROTATION", floats(t.rotation, 4, "VEC4")},
                    {"SCALE", floats(t.scale, 3, "VEC3")}};
      if (!t.colour.empty())
        attributes["_COLOR_0"] =
            buffer_.accessor({{"componentType", kUint8},
                              {"normalized", true},
                              {"count", t.colour.size() / 4},
                              {"type", "VEC4"},
                              {"bufferView", buffer_.view(t.colour.data(), t.colour.size())}});
    }
    node["extensions"]["EXT_mesh_gpu_instancing"]["attributes"] = attributes;
  }
  nodes_.push_back(node);
}

std::vector<char> GlbBuilder::finish(const json& extras) {
  json nodes_of_scene = json::array();
  for (size_t i = 0; i < nodes_.size(); ++i) nodes_of_scene.push_back(i);
  json gltf = {{"asset", {{"version", "2.0"}, {"generator", "maquette"}}},
               {"scene", 0},
               {"scenes", {{{"nodes", nodes_of_scene}}}},
               {"nodes", nodes_},
               {"meshes", meshes_},
               {"materials", materials_}};
  if (!extras.is_null()) gltf["asset"]["extras"] = extras;
  if (!images_.empty()) {
    gltf["images"] = images_;
    gltf["textures"] = textures_;
    gltf["samplers"] = samplers_;
  }
  if (!extensions_.empty()) {  // each is required to draw the content correctly
    gltf["extensionsUsed"] = extensions_;
    gltf["extensionsRequired"] = extensions_;
  }
  return buffer_.finish(std::move(gltf));
}

void append_u32(std::vector<char>& out, uint32_t v) {
  char b[4];
  std::memcpy(b, &v, 4);  // GLB is little-endian, as is every platform Maquette builds on
  out.insert(out.end(), b, b + 4);
}

}  // namespace

json content_material(const Material& m, GlbBuffer& buffer, json& images, json& textures,
                      int sampler) {
  json pbr = json::object();  // glTF's defaults (1) left out: every cell's GLB repeats them
  if (m.base_colour != std::array<float, 4>{1, 1, 1, 1}) pbr["baseColorFactor"] = m.base_colour;
  if (m.metallic != 1) pbr["metallicFactor"] = m.metallic;
  if (m.roughness != 1) pbr["roughnessFactor"] = m.roughness;
  if (!m.image.empty()) {
    images.push_back(
        {{"bufferView", buffer.view(m.image.data(), m.image.size())}, {"mimeType", m.image_mime}});
    json texture = {{"sampler", sampler}};
    if (m.image_mime == "image/webp")
      texture["extensions"]["EXT_texture_webp"]["source"] = images.size() - 1;
    else
      texture["source"] = images.size() - 1;
    textures.push_back(texture);
    pbr["baseColorTexture"] = {{"index", textures.size() - 1}};
  }
  json out = {{"pbrMetallicRoughness", pbr}};
  if (!m.name.empty()) out["name"] = m.name;
  if (m.double_sided) out["doubleSided"] = true;
  return out;
}

json content_sampler() { return {{"magFilter", 9729}, {"minFilter", 9987}}; }

int GlbBuffer::view(const void* data, size_t size, int target, size_t alignment) {
  while (bin_.size() % alignment) bin_.push_back(0);
  // glTF requires byteLength >= 1: an empty column (e.g. EXT_structural_metadata strings that are
  // all empty) is one zero byte that nothing reads.
  json v = {{"buffer", 0}, {"byteOffset", bin_.size()}, {"byteLength", std::max<size_t>(size, 1)}};
  if (target) v["target"] = target;
  const char* p = static_cast<const char*>(data);
  bin_.insert(bin_.end(), p, p + size);
  if (size == 0) bin_.push_back(0);
  views_.push_back(v);
  return int(views_.size() - 1);
}

int GlbBuffer::accessor(json a) {
  accessors_.push_back(std::move(a));
  return int(accessors_.size() - 1);
}

std::vector<char> GlbBuffer::finish(json gltf) {
  if (!accessors_.empty()) gltf["accessors"] = accessors_;
  if (!views_.empty()) gltf["bufferViews"] = views_;
  while (bin_.size() % 4) bin_.push_back(0);
  if (!bin_.empty()) gltf["buffers"] = {{{"byteLength", bin_.size()}}};
  return glb_file(gltf, {bin_.data(), bin_.size()});
}

std::vector<char> glb_file(const json& gltf, std::string_view bin) {
  std::string text = gltf.dump();
  while (text.size() % 4) text.push_back(' ');
  const size_t bin_padded = (bin.size() + 3) / 4 * 4;

  std::vector<char> out;
  append_u32(out, 0x46546C67);  // "glTF"
  append_u32(out, 2);
  append_u32(out, uint32_t(12 + 8 + text.size() + (bin.empty() ? 0 : 8 + bin_padded)));
  append_u32(out, uint32_t(text.size()));
  append_u32(out, 0x4E4F534A);  // "JSON"
  out.insert(out.end(), text.begin(), text.end());
  if (!bin.empty()) {
    append_u32(out, uint32_t(bin_padded));
    append_u32(out, 0x004E4942);  // "BIN\0"
    out.insert(out.end(), bin.begin(), bin.end());
    out.resize(out.size() + bin_padded - bin.size(), 0);
  }
  return out;
}

std::vector<char> make_glb(const std::vector<GlbPrimitive>& primitives, const json& extras) {
  GlbBuilder b;
  for (const GlbPrimitive& p : primitives) b.add(p);
  return b.finish(extras);
}

void write_file(const std::string& path, const std::vector<char>& bytes) {
  write_file_whole(path, bytes);
}

}  // namespace maquette
