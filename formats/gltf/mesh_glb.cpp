#include "gltf/mesh_glb.h"

#include <draco/compression/decode.h>
#include <draco/compression/encode.h>
#include <draco/mesh/mesh.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "content/content_blob.h"
#include "core/error.h"
#include "gltf/enu_axes.h"
#include "gltf/glb_writer.h"
#include "gltf/gltf_document.h"

namespace maquette {
namespace {

using nlohmann::json;

constexpr int kUnsignedShort = 5123, kUnsignedInt = 5125, kFloat = 5126;
constexpr int kSpeed = 3;                        // as the terrain's (draco_encode.cpp)
constexpr size_t kMaxObjects = size_t(1) << 24;  // feature ids as exact floats

std::string object_name(const MeshContent& c, size_t i) {
  return "object " + std::to_string(i) + " (id " +
         std::to_string(c.objects[i].provenance.object_id) + ")";
}

void check_object(const MeshContent& c, size_t i) {
  const MeshObject& o = c.objects[i];
  const auto fault = [&](const std::string& what) {
    throw Error("mesh content: " + object_name(c, i) + ": " + what);
  };
  const size_t n = o.positions.size() / 3;
  if (o.positions.size() % 3) fault("positions are not x, y, z triples");
  for (float x : o.positions)
    if (!std::isfinite(x)) fault("a position is not finite");
  if (!o.normals.empty() && o.normals.size() != n * 3) fault("normals are not one per vertex");
  if (!o.uvs.empty() && o.uvs.size() != n * 2) fault("uvs are not one per vertex");
  if (o.indices.empty() || o.indices.size() % 3) fault("indices are not one or more triangles");
  for (uint32_t v : o.indices)
    if (v >= n)
      fault("index " + std::to_string(v) + " is out of its " + std::to_string(n) + " vertices");
  if (o.material < -1 || o.material >= int(c.materials.size()))
    fault("material " + std::to_string(o.material) + " is not one of the " +
          std::to_string(c.materials.size()));
}

// The material of objects without one (content.h's default grey, as structures.prism's faces
// without a texture), written as the GLB's last material: a primitive without a material gets
// glTF's default one, a white metal, which a viewer without an environment map (three.js, as
// `maquette view`) draws pure black wherever its sun does not reach. Marked by kDefaultMarker in
// its extras and read back as -1 by the mark, not by its value: content may have a grey of its own.
constexpr const char* kDefaultMarker = "maquette_default_material";
Material default_grey() {
  Material m;  // not metallic, roughness 1, single-sided
  m.name = "default grey";
  m.base_colour = {0.6f, 0.6f, 0.6f, 1};
  return m;
}

// Objects drawn by one primitive: one material and one attribute set.
struct Group {
  int material;
  bool normals, uvs;
  std::vector<size_t> objects;
};

std::vector<Group> groups_of(const MeshContent& c) {
  std::vector<Group> groups;  // in the order of their first object
  for (size_t i = 0; i < c.objects.size(); ++i) {
    const MeshObject& o = c.objects[i];
    auto g = std::ranges::find_if(groups, [&](const Group& g) {
      return g.material == o.material && g.normals == !o.normals.empty() && g.uvs == !o.uvs.empty();
    });
    if (g == groups.end())
      g = groups.insert(groups.end(), {o.material, !o.normals.empty(), !o.uvs.empty(), {}});
    g->objects.push_back(i);
  }
  return groups;
}

template <class T>
int add_attribute(draco::Mesh& mesh, draco::GeometryAttribute::Type type, draco::DataType data,
                  int components, const std::vector<T>& values) {
  draco::GeometryAttribute ga;
  ga.Init(type, nullptr, uint8_t(components), data, false, int64_t(sizeof(T)) * components, 0);
  const size_t n = values.size() / size_t(components);
  draco::PointAttribute* att = mesh.attribute(mesh.AddAttribute(ga, true, uint32_t(n)));
  for (size_t i = 0; i < n; ++i)
    att->SetAttributeValue(draco::AttributeValueIndex(uint32_t(i)),
                           &values[i * size_t(components)]);
  return int(att->unique_id());
}

// A group's primitive: its Draco stream in the GLB, its accessors and feature ids.
class PrimitiveWriter {
 public:
  PrimitiveWriter(const MeshContent& c, const MeshGlbSettings& s, GlbBuffer& buffer)
      : content_(c), settings_(s), buffer_(buffer) {}

  json write(const Group& g) {
    draco::Mesh mesh;
    std::vector<float> positions, normals, uvs, feature_float;
    std::vector<uint16_t> feature_short;
    std::vector<draco::Mesh::Face> faces;
    const bool short_ids = content_.objects.size() <= 65536;
    for (size_t i : g.objects) {
      const MeshObject& o = content_.objects[i];
      const uint32_t base = uint32_t(positions.size() / 3);
      for (size_t v = 0; v < o.positions.size(); v += 3) {
        append_gltf_axes(&o.positions[v], positions);
        if (g.normals) append_gltf_axes(&o.normals[v], normals);
        if (short_ids)
          feature_short.push_back(uint16_t(i));
        else
          feature_float.push_back(float(i));
      }
      uvs.insert(uvs.end(), o.uvs.begin(), o.uvs.end());
      for (size_t t = 0; t < o.indices.size(); t += 3)
        faces.push_back({draco::PointIndex(base + o.indices[t]),
                         draco::PointIndex(base + o.indices[t + 1]),
                         draco::PointIndex(base + o.indices[t + 2])});
    }
    mesh.set_num_points(uint32_t(positions.size() / 3));
    json ids;
    ids["POSITION"] =
        add_attribute(mesh, draco::GeometryAttribute::POSITION, draco::DT_FLOAT32, 3, positions);
    if (g.normals)
      ids["NORMAL"] =
          add_attribute(mesh, draco::GeometryAttribute::NORMAL, draco::DT_FLOAT32, 3, normals);
    if (g.uvs)
      ids["TEXCOORD_0"] =
          add_attribute(mesh, draco::GeometryAttribute::TEX_COORD, draco::DT_FLOAT32, 2, uvs);
    ids["_FEATURE_ID_0"] = short_ids ? add_attribute(mesh, draco::GeometryAttribute::GENERIC,
                                                     draco::DT_UINT16, 1, feature_short)
                                     : add_attribute(mesh, draco::GeometryAttribute::GENERIC,
                                                     draco::DT_FLOAT32, 1, feature_float);
    for (const draco::Mesh::Face& f : faces) mesh.AddFace(f);
    // Edgebreaker's connectivity follows the position values: without merging equal values,
    // faces split at normal or uv seams (a prism's walls and roof) are disconnected pieces, and
    // the stream was 1.63x larger on the content benchmark's buildings (benchmarks/README.md).
    mesh.DeduplicateAttributeValues();
    mesh.DeduplicatePointIds();

    const std::string stream = encode(mesh, positions);
    // The accessors describe the decoded stream (Draco may split vertices): decode it.
    draco::DecoderBuffer in;
    in.Init(stream.data(), stream.size());
    const auto decoded = draco::Decoder().DecodeMeshFromBuffer(&in);
    if (!decoded.ok()) throw Error("Draco cannot decode its own mesh content stream");
    const draco::Mesh& d = *decoded.value();
    const size_t n = d.num_points();
    json min = json::array(), max = json::array();
    bounds(d, ids["POSITION"].get<int>(), min, max);
    json prim;  // mode: triangles, glTF's default
    prim["attributes"]["POSITION"] = buffer_.accessor(
        {{"componentType", kFloat}, {"count", n}, {"type", "VEC3"}, {"min", min}, {"max", max}});
    if (g.normals)
      prim["attributes"]["NORMAL"] =
          buffer_.accessor({{"componentType", kFloat}, {"count", n}, {"type", "VEC3"}});
    if (g.uvs)
      prim["attributes"]["TEXCOORD_0"] =
          buffer_.accessor({{"componentType", kFloat}, {"count", n}, {"type", "VEC2"}});
    prim["attributes"]["_FEATURE_ID_0"] = buffer_.accessor(
        {{"componentType", short_ids ? kUnsignedShort : kFloat}, {"count", n}, {"type", "SCALAR"}});
    prim["indices"] =
        buffer_.accessor({{"componentType", n > 65535 ? kUnsignedInt : kUnsignedShort},
                          {"count", d.num_faces() * 3},
                          {"type", "SCALAR"}});
    prim["material"] = g.material >= 0 ? g.material : int(content_.materials.size());
    prim["extensions"]["KHR_draco_mesh_compression"] = {
        {"bufferView", buffer_.view(stream.data(), stream.size())}, {"attributes", ids}};
    prim["extensions"]["EXT_mesh_features"] = mesh_feature_ids(g.objects.size());
    return prim;
  }

 private:
  std::string encode(const draco::Mesh& mesh, const std::vector<float>& positions) {
    std::array<float, 3> lo, hi;
    lo.fill(std::numeric_limits<float>::max());
    hi.fill(std::numeric_limits<float>::lowest());
    for (size_t i = 0; i < positions.size(); ++i) {
      lo[i % 3] = std::min(lo[i % 3], positions[i]);
      hi[i % 3] = std::max(hi[i % 3], positions[i]);
    }
    double extent = 0;
    for (int a = 0; a < 3; ++a) extent = std::max(extent, double(hi[a]) - lo[a]);
    draco::Encoder encoder;
    encoder.SetSpeedOptions(kSpeed, kSpeed);
    encoder.SetAttributeQuantization(draco::GeometryAttribute::POSITION,
                                     position_bits(extent, settings_));
    encoder.SetAttributeQuantization(draco::GeometryAttribute::NORMAL, settings_.normal_bits);
    encoder.SetAttributeQuantization(draco::GeometryAttribute::TEX_COORD, settings_.texcoord_bits);
    draco::EncoderBuffer out;
    const draco::Status status = encoder.EncodeMeshToBuffer(mesh, &out);
    if (!status.ok())
      throw Error("Draco encoding of mesh content failed: " + status.error_msg_string());
    return std::string(out.data(), out.size());
  }

  static void bounds(const draco::Mesh& d, int position_id, json& min, json& max) {
    const draco::PointAttribute* att = d.GetAttributeByUniqueId(uint32_t(position_id));
    std::array<float, 3> lo, hi, v;
    lo.fill(std::numeric_limits<float>::max());
    hi.fill(std::numeric_limits<float>::lowest());
    for (uint32_t p = 0; p < d.num_points(); ++p) {
      att->GetValue(att->mapped_index(draco::PointIndex(p)), v.data());
      for (int a = 0; a < 3; ++a) {
        lo[a] = std::min(lo[a], v[a]);
        hi[a] = std::max(hi[a], v[a]);
      }
    }
    min = lo;
    max = hi;
  }

  const MeshContent& content_;
  const MeshGlbSettings& settings_;
  GlbBuffer& buffer_;
};

void check_material(const Material& m, size_t i) {
  const auto fault = [&](const std::string& what) {
    throw Error("mesh content: material " + std::to_string(i) + " (" + m.name + "): " + what);
  };
  for (float f : {m.base_colour[0], m.base_colour[1], m.base_colour[2], m.base_colour[3],
                  m.metallic, m.roughness})
    if (!(f >= 0 && f <= 1)) fault("a factor of " + std::to_string(f) + ", not within 0..1");
  if (!m.image.empty() && m.image_mime != "image/jpeg" && m.image_mime != "image/png" &&
      m.image_mime != "image/webp")
    fault("an image of type '" + m.image_mime + "', not image/jpeg, image/png or image/webp");
}

// A column of unsigned integers in the fewest bytes holding `largest` (UINT8, UINT16, UINT32),
// and the type's name.
std::pair<int, std::string> unsigned_column(const std::vector<uint32_t>& values, uint32_t largest,
                                            GlbBuffer& buffer) {
  const auto narrow = [&]<class T>(T) {
    const std::vector<T> v(values.begin(), values.end());
    return buffer.view(v.data(), v.size() * sizeof(T));
  };
  if (largest <= UINT8_MAX) return {narrow(uint8_t()), "UINT8"};
  if (largest <= UINT16_MAX) return {narrow(uint16_t()), "UINT16"};
  return {buffer.view(values.data(), values.size() * 4), "UINT32"};
}

// A STRING column: the strings' bytes and their offsets (one more than strings) in the fewest
// bytes, UINT32 (the extension's default, then not written) only past 64 KiB of strings.
json string_column(const std::vector<std::string>& strings, GlbBuffer& buffer) {
  std::string bytes;
  std::vector<uint32_t> offsets = {0};
  for (const std::string& s : strings) {
    bytes += s;
    if (bytes.size() > std::numeric_limits<uint32_t>::max())
      throw Error("mesh content: its metadata strings exceed 4 GiB");
    offsets.push_back(uint32_t(bytes.size()));
  }
  const auto [view, type] = unsigned_column(offsets, offsets.back(), buffer);
  json out = {{"values", buffer.view(bytes.data(), bytes.size())}, {"stringOffsets", view}};
  if (type != "UINT32") out["stringOffsetType"] = type;
  return out;
}

// Lean on purpose (each cell's GLB carries it): defaults and descriptions left out, a short
// schema id (benchmarks/README.md, "3D content"). The schema is the same for every content, as
// gltf/glb_merge.h requires of the GLBs it merges.
}  // namespace

json mesh_metadata(const MeshContent& c, GlbBuffer& buffer) {
  std::vector<uint64_t> object_ids;
  std::vector<int64_t> feature_ids;
  std::vector<std::string> tools, attributes;
  for (const MeshObject& o : c.objects) {
    object_ids.push_back(o.provenance.object_id);
    feature_ids.push_back(o.provenance.feature_id);
    tools.push_back(o.provenance.tool);
    attributes.push_back(o.provenance.attributes.dump());  // keys sorted: the same bytes
  }
  const json table = {
      {"class", "object"},
      {"count", c.objects.size()},
      {"properties",
       {{"object_id", {{"values", buffer.view(object_ids.data(), object_ids.size() * 8, 0, 8)}}},
        {"feature_id", {{"values", buffer.view(feature_ids.data(), feature_ids.size() * 8, 0, 8)}}},
        {"tool", string_column(tools, buffer)},
        {"attributes", string_column(attributes, buffer)}}}};
  const json schema = {
      {"id", "mq"},
      {"classes",
       {{"object",
         {{"properties",
           {{"object_id", {{"type", "SCALAR"}, {"componentType", "UINT64"}}},
            {"feature_id", {{"type", "SCALAR"}, {"componentType", "INT64"}, {"noData", -1}}},
            {"tool", {{"type", "STRING"}}},
            {"attributes", {{"type", "STRING"}}}}}}}}}};
  return {{"schema", schema}, {"propertyTables", {table}}};
}

json mesh_feature_ids(size_t count) {
  return {{"featureIds", {{{"featureCount", count}, {"attribute", 0}, {"propertyTable", 0}}}}};
}

namespace {

// Decoding: the property table's columns.
template <class T>
std::vector<T> fixed_column(const GltfDocument& doc, const json& property, size_t count,
                            const std::string& name) {
  const std::string_view bytes =
      buffer_view(doc, gltf_index(doc, property.value("values", json()), name + ".values"));
  if (bytes.size() % sizeof(T) != 0 || bytes.size() / sizeof(T) != count)
    throw Error(doc.where + ": metadata column " + name + " holds " + std::to_string(bytes.size()) +
                " bytes for " + std::to_string(count) + " objects");
  std::vector<T> out(count);
  std::memcpy(out.data(), bytes.data(), bytes.size());
  return out;
}

// A column of UINT8, UINT16 or UINT32 values (`type`) widened.
std::vector<uint32_t> unsigned_values(const GltfDocument& doc, const json& values, size_t count,
                                      const std::string& type, const std::string& name) {
  const json property = {{"values", values}};
  const auto widen = [&]<class T>(T) {
    const std::vector<T> v = fixed_column<T>(doc, property, count, name);
    return std::vector<uint32_t>(v.begin(), v.end());
  };
  if (type == "UINT8") return widen(uint8_t());
  if (type == "UINT16") return widen(uint16_t());
  if (type == "UINT32") return widen(uint32_t());
  throw Error(doc.where + ": metadata column " + name + " has type '" + type +
              "', not UINT8, UINT16 or UINT32");
}

std::vector<std::string> string_values(const GltfDocument& doc, const json& property, size_t count,
                                       const std::string& name) {
  const std::string_view bytes =
      buffer_view(doc, gltf_index(doc, property.value("values", json()), name + ".values"));
  const std::vector<uint32_t> offsets =
      unsigned_values(doc, property.value("stringOffsets", json()), count + 1,
                      property.value("stringOffsetType", "UINT32"), name + " offsets");
  std::vector<std::string> out;
  for (size_t i = 0; i < count; ++i) {
    if (offsets[i] > offsets[i + 1] || offsets[i + 1] > bytes.size())
      throw Error(doc.where + ": metadata column " + name + " has offsets out of its strings");
    out.emplace_back(bytes.substr(offsets[i], offsets[i + 1] - offsets[i]));
  }
  return out;
}

std::vector<ObjectProvenance> read_metadata(const GltfDocument& doc) {
  const json& ext = doc.json.value("extensions", json::object());
  const json* table = nullptr;
  if (ext.contains("EXT_structural_metadata") &&
      !ext["EXT_structural_metadata"].value("propertyTables", json::array()).empty())
    table = &ext["EXT_structural_metadata"]["propertyTables"][0];
  if (!table || !table->is_object() || !table->value("count", json()).is_number_unsigned())
    throw Error(doc.where + ": not mesh content: no EXT_structural_metadata property table");
  const size_t n = table->at("count").get<size_t>();
  const json& p = table->value("properties", json::object());
  for (const char* name : {"object_id", "feature_id", "tool", "attributes"})
    if (!p.contains(name)) throw Error(doc.where + ": no metadata column " + name);
  const auto ids = fixed_column<uint64_t>(doc, p["object_id"], n, "object_id");
  const auto fids = fixed_column<int64_t>(doc, p["feature_id"], n, "feature_id");
  const auto tools = string_values(doc, p["tool"], n, "tool");
  const auto attributes = string_values(doc, p["attributes"], n, "attributes");
  std::vector<ObjectProvenance> out(n);
  for (size_t i = 0; i < n; ++i) {
    out[i] = {ids[i], fids[i], tools[i], json::parse(attributes[i], nullptr, false)};
    if (!out[i].attributes.is_object())
      throw Error(doc.where + ": the attributes of object " + std::to_string(i) +
                  " are not a JSON object");
  }
  return out;
}

// Adds the triangles of a decoded primitive to their objects (by their vertices' feature ids).
void split_primitive(const GltfDocument& doc, const GltfPrimitive& p, const std::string& what,
                     std::vector<MeshObject>& objects, std::vector<int>& primitive_of,
                     int primitive) {
  if (p.feature_ids.empty()) throw Error(doc.where + ": " + what + " has no _FEATURE_ID_0");
  std::vector<uint32_t> new_index(p.positions.size() / 3, UINT32_MAX);
  for (size_t t = 0; t < p.indices.size(); t += 3) {
    const uint32_t f = p.feature_ids[p.indices[t]];
    if (f >= objects.size() || p.feature_ids[p.indices[t + 1]] != f ||
        p.feature_ids[p.indices[t + 2]] != f)
      throw Error(doc.where + ": " + what + ": triangle " + std::to_string(t / 3) +
                  " has feature ids out of the property table or of several objects");
    if (primitive_of[f] != primitive && primitive_of[f] != -1)
      throw Error(doc.where + ": object " + std::to_string(f) + " is in two primitives");
    primitive_of[f] = primitive;
    MeshObject& o = objects[f];
    o.material = p.material;
    for (size_t c = 0; c < 3; ++c) {
      const uint32_t v = p.indices[t + c];
      if (new_index[v] == UINT32_MAX) {
        new_index[v] = uint32_t(o.positions.size() / 3);
        append_enu_axes(&p.positions[v * 3], o.positions);
        if (!p.normals.empty()) append_enu_axes(&p.normals[v * 3], o.normals);
        if (!p.uvs.empty()) o.uvs.insert(o.uvs.end(), &p.uvs[v * 2], &p.uvs[v * 2 + 2]);
      }
      o.indices.push_back(new_index[v]);
    }
  }
}

}  // namespace

int position_bits(double extent, const MeshGlbSettings& settings) {
  int bits = 1;
  while (bits < 30 && extent / double((uint64_t(1) << bits) - 1) > settings.position_error) ++bits;
  return bits;
}

std::string encode_mesh_glb(const MeshContent& content, const MeshGlbSettings& settings) {
  if (content.objects.empty()) throw Error("mesh content: no objects to encode");
  if (content.objects.size() > kMaxObjects)
    throw Error("mesh content: " + std::to_string(content.objects.size()) +
                " objects, more than the 2^24 of one GLB");
  for (size_t i = 0; i < content.objects.size(); ++i) check_object(content, i);
  GlbBuffer buffer;
  json images = json::array(), textures = json::array(), materials = json::array();
  bool webp = false;
  for (size_t i = 0; i < content.materials.size(); ++i) {
    check_material(content.materials[i], i);
    materials.push_back(content_material(content.materials[i], buffer, images, textures, 0));
    webp |= content.materials[i].image_mime == "image/webp";
  }
  if (std::ranges::any_of(content.objects, [](const MeshObject& o) { return o.material < 0; })) {
    materials.push_back(content_material(default_grey(), buffer, images, textures, 0));
    materials.back()["extras"][kDefaultMarker] = true;
  }
  PrimitiveWriter writer(content, settings, buffer);
  json primitives = json::array();
  for (const Group& g : groups_of(content)) primitives.push_back(writer.write(g));
  json gltf = {{"asset", {{"version", "2.0"}, {"generator", "maquette"}}},
               {"scene", 0},
               {"scenes", {{{"nodes", {0}}}}},
               {"nodes", {{{"mesh", 0}}}},
               {"meshes", {{{"primitives", primitives}}}},
               {"extensionsUsed",
                {"EXT_mesh_features", "EXT_structural_metadata", "KHR_draco_mesh_compression"}},
               {"extensionsRequired", {"KHR_draco_mesh_compression"}}};
  if (webp) {  // no fallback image: required
    gltf["extensionsUsed"].push_back("EXT_texture_webp");
    gltf["extensionsRequired"].push_back("EXT_texture_webp");
  }
  if (!materials.empty()) gltf["materials"] = materials;
  if (!images.empty()) {
    gltf["images"] = images;
    gltf["textures"] = textures;
    gltf["samplers"] = {content_sampler()};
  }
  gltf["extensions"]["EXT_structural_metadata"] = mesh_metadata(content, buffer);
  const std::vector<char> glb = buffer.finish(std::move(gltf));
  return std::string(glb.begin(), glb.end());
}

MeshContent decode_mesh_glb(std::string_view glb, const EnuOrigin& origin,
                            const std::string& where) try {
  const GltfDocument doc = parse_gltf(glb, where, {});
  MeshContent out{origin, read_materials(doc), {}};
  int default_material = -1;  // the GLB's index of default_grey(), if written
  const json& written = doc.json.value("materials", json::array());
  if (!written.empty() && written.back().value("extras", json::object()).contains(kDefaultMarker)) {
    default_material = int(out.materials.size()) - 1;
    out.materials.pop_back();
  }
  const std::vector<ObjectProvenance> provenance = read_metadata(doc);
  out.objects.resize(provenance.size());
  for (size_t i = 0; i < provenance.size(); ++i) out.objects[i].provenance = provenance[i];
  std::vector<int> primitive_of(provenance.size(), -1);
  const json& meshes = doc.json.value("meshes", json::array());
  int primitive = 0;
  for (size_t m = 0; m < meshes.size(); ++m)
    for (size_t i = 0; i < meshes[m].value("primitives", json::array()).size(); ++i, ++primitive) {
      GltfPrimitive p = read_primitive(doc, int(m), int(i));
      if (p.material == default_material) p.material = -1;
      const std::string what =
          "meshes[" + std::to_string(m) + "].primitives[" + std::to_string(i) + "]";
      if (p.material >= int(out.materials.size()))
        throw Error(where + ": " + what + " has material " + std::to_string(p.material) + " of " +
                    std::to_string(out.materials.size()));
      split_primitive(doc, p, what, out.objects, primitive_of, primitive);
    }
  for (size_t i = 0; i < primitive_of.size(); ++i)
    if (primitive_of[i] < 0)
      throw Error(where + ": object " + std::to_string(i) +
                  " of the property table has no triangles");
  return out;
} catch (const json::exception& e) {
  throw Error(where + ": malformed glTF: " + e.what());
}

std::string mesh_content_blob(const MeshContent& content) {
  ContentEnvelope envelope;
  envelope.kind = ContentKind::Mesh;
  envelope.origin = content.origin;
  envelope.stats.objects = content.objects.size();
  for (const MeshObject& o : content.objects) envelope.stats.triangles += o.indices.size() / 3;
  return wrap_content(envelope, encode_mesh_glb(content));
}

}  // namespace maquette
