#include "gltf/gltf_document.h"

#include <draco/compression/decode.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>

#include "core/error.h"
#include "core/file_access.h"
#include "core/json_file.h"

namespace maquette {
namespace {

using nlohmann::json;

constexpr uint32_t kGlbMagic = 0x46546C67, kJsonChunk = 0x4E4F534A, kBinChunk = 0x004E4942;
constexpr int kByte = 5120, kUnsignedByte = 5121, kShort = 5122, kUnsignedShort = 5123,
              kUnsignedInt = 5125, kFloat = 5126;

template <class T>
T load(const char* p) {
  T x;
  std::memcpy(&x, p, sizeof x);
  return x;
}

// GLB is little-endian, as every platform Maquette builds on.
uint32_t u32(std::string_view bytes, size_t at) { return load<uint32_t>(bytes.data() + at); }

[[noreturn]] void fail(const GltfDocument& doc, const std::string& what) {
  throw Error(doc.where + ": " + what);
}

// The element `index` of the top-level array `array` (e.g. "accessors"), checked.
const json& element(const GltfDocument& doc, const char* array, const json& index) {
  const json* list = doc.json.contains(array) ? &doc.json[array] : nullptr;
  if (!index.is_number_integer() || index.get<int64_t>() < 0 || !list || !list->is_array() ||
      index.get<uint64_t>() >= list->size())
    fail(doc, std::string("no ") + array + "[" + index.dump() + "]");
  return (*list)[index.get<size_t>()];
}

uint64_t unsigned_field(const GltfDocument& doc, const json& object, const char* key,
                        const std::string& what, uint64_t fallback) {
  if (!object.contains(key)) return fallback;
  if (!object[key].is_number_unsigned())
    fail(doc, what + "." + key + " is " + object[key].dump() + ", not a count");
  return object[key].get<uint64_t>();
}

std::string base64_decode(const GltfDocument& doc, std::string_view text, const std::string& what) {
  std::string out;
  out.reserve(text.size() / 4 * 3);
  uint32_t acc = 0;
  int bits = 0;
  for (char c : text) {
    int v;
    if (c >= 'A' && c <= 'Z')
      v = c - 'A';
    else if (c >= 'a' && c <= 'z')
      v = c - 'a' + 26;
    else if (c >= '0' && c <= '9')
      v = c - '0' + 52;
    else if (c == '+' || c == '-')
      v = 62;
    else if (c == '/' || c == '_')
      v = 63;
    else if (c == '=')
      break;
    else
      fail(doc, what + ": not base64 (character '" + std::string(1, c) + "')");
    acc = (acc << 6) | uint32_t(v);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out.push_back(char((acc >> bits) & 0xFF));
    }
  }
  return out;
}

// The bytes a URI names: a data URI, or a file relative to the document's base_dir, at most `limit`
// bytes.
std::string percent_decoded(const GltfDocument& doc, const std::string& uri,
                            const std::string& what) {
  std::string out;
  for (size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] != '%') {
      out += uri[i];
      continue;
    }
    const auto hex = [&](size_t at) {
      const char c = at < uri.size() ? uri[at] : '\0';
      if (c >= '0' && c <= '9') return c - '0';
      if (c >= 'a' && c <= 'f') return c - 'a' + 10;
      if (c >= 'A' && c <= 'F') return c - 'A' + 10;
      fail(doc, what + ": the URI '" + uri + "' has a bad percent-encoding");
    };
    const int value = hex(i + 1) * 16 + hex(i + 2);
    if (value == 0) fail(doc, what + ": the URI '" + uri + "' encodes a NUL byte");
    out += char(value);
    i += 2;
  }
  return out;
}

std::string read_uri(const GltfDocument& doc, const std::string& uri, const std::string& what,
                     uint64_t limit) {
  if (uri.starts_with("data:")) {
    const size_t comma = uri.find(',');
    if (comma == std::string::npos || uri.substr(0, comma).find(";base64") == std::string::npos)
      fail(doc, what + ": a data URI that is not base64");
    return base64_decode(doc, std::string_view(uri).substr(comma + 1), what);
  }
  if (doc.base_dir.empty()) fail(doc, what + ": an external URI '" + uri + "' where none may be");
  if (uri.find("://") != std::string::npos) fail(doc, what + ": a remote URI '" + uri + "'");
  // glTF's URIs are relative references, percent-encoded (RFC 3986); a model reads files of its
  // own folder and below only, so a file it names cannot point anywhere else on the machine.
  const std::filesystem::path relative = percent_decoded(doc, uri, what);
  if (relative.empty() || relative.is_absolute() ||
      std::any_of(relative.begin(), relative.end(), [](const auto& part) { return part == ".."; }))
    fail(doc, what + ": the URI '" + uri + "' leaves the model's folder");
  const std::string path = (doc.base_dir / relative).string();
  if (const auto problem = file_access_problem(path))
    fail(doc, what + ": cannot read '" + path + "': " + *problem);
  const uint64_t size = std::filesystem::file_size(path);
  if (size > limit)
    fail(doc, what + ": '" + path + "' has " + std::to_string(size) + " bytes, more than " +
                  std::to_string(limit));
  std::string bytes(size, '\0');
  std::ifstream in(path, std::ios::binary);
  if (!in.read(bytes.data(), std::streamsize(size)))
    fail(doc, what + ": cannot read '" + path + "'");
  return bytes;
}

void read_buffers(GltfDocument& doc, std::string_view bin) {
  const json& buffers = doc.json.value("buffers", json::array());
  for (size_t i = 0; i < buffers.size(); ++i) {
    const std::string what = "buffers[" + std::to_string(i) + "]";
    const uint64_t length = unsigned_field(doc, buffers[i], "byteLength", what, ~uint64_t(0));
    if (length == ~uint64_t(0)) fail(doc, what + " has no byteLength");
    if (length > kMaxGltfBufferBytes)  // checked before anything is read or allocated
      fail(doc, what + " declares " + std::to_string(length) + " bytes, more than the " +
                    std::to_string(kMaxGltfBufferBytes) + " (1 GiB) read");
    std::string data;
    if (!buffers[i].contains("uri")) {
      if (i != 0 || bin.data() == nullptr)
        fail(doc, what + " has no uri and is not a GLB's BIN chunk");
      data = std::string(bin);
    } else {
      data = read_uri(doc, buffers[i]["uri"].get<std::string>(), what, length + 3);
    }
    if (data.size() < length)
      fail(doc, what + " declares " + std::to_string(length) + " bytes but holds " +
                    std::to_string(data.size()));
    data.resize(length);
    doc.buffers.push_back(std::move(data));
  }
}

size_t component_bytes(int type) {
  switch (type) {
    case kByte:
    case kUnsignedByte:
      return 1;
    case kShort:
    case kUnsignedShort:
      return 2;
    case kUnsignedInt:
    case kFloat:
      return 4;
    default:
      return 0;
  }
}

size_t components_of(const std::string& type) {
  if (type == "SCALAR") return 1;
  if (type == "VEC2") return 2;
  if (type == "VEC3") return 3;
  if (type == "VEC4") return 4;
  return 0;
}

// One component at `p` (normalized integers mapped to [0, 1] or [-1, 1] as glTF specifies).
double component(const char* p, int type, bool normalized) {
  switch (type) {
    case kByte:
      return normalized ? std::max(load<int8_t>(p) / 127.0, -1.0) : load<int8_t>(p);
    case kUnsignedByte:
      return load<uint8_t>(p) / (normalized ? 255.0 : 1.0);
    case kShort:
      return normalized ? std::max(load<int16_t>(p) / 32767.0, -1.0) : load<int16_t>(p);
    case kUnsignedShort:
      return load<uint16_t>(p) / (normalized ? 65535.0 : 1.0);
    case kUnsignedInt:
      return load<uint32_t>(p);
    default:
      return load<float>(p);
  }
}

// The values of accessor `index` as doubles, with `components` each (normalized integers mapped
// to [0, 1] or [-1, 1] as glTF specifies).
std::vector<double> read_accessor(const GltfDocument& doc, const json& index, size_t components) {
  const json& a = element(doc, "accessors", index);
  const std::string what = "accessors[" + index.dump() + "]";
  if (a.contains("sparse")) fail(doc, what + " is sparse, which is not read");
  const int type = a.value("componentType", 0);
  const size_t size = component_bytes(type);
  const size_t n = components_of(a.value("type", ""));
  if (size == 0 || n != components)
    fail(doc, what + ": componentType " + std::to_string(type) + " type '" + a.value("type", "") +
                  "' where " + std::to_string(components) + " components are read");
  if (!a.contains("bufferView")) fail(doc, what + " has no bufferView");
  const json& v = element(doc, "bufferViews", a["bufferView"]);
  const std::string_view view = buffer_view(doc, gltf_index(doc, a["bufferView"], what));
  const uint64_t count = unsigned_field(doc, a, "count", what, 0);
  const uint64_t offset = unsigned_field(doc, a, "byteOffset", what, 0);
  const uint64_t element_bytes = n * size;
  const uint64_t stride = unsigned_field(doc, v, "byteStride", what, element_bytes);
  // glTF: a stride is 4..252 and a multiple of 4; the bounds are compared without overflow.
  if (v.contains("byteStride") && (stride < 4 || stride > 252 || stride % 4 != 0))
    fail(doc, what + ": its bufferView's byteStride " + std::to_string(stride) +
                  " is not a multiple of 4 in 4..252");
  if (count > 0 &&
      (stride < element_bytes || offset > view.size() || element_bytes > view.size() - offset ||
       count - 1 > (view.size() - offset - element_bytes) / stride))
    fail(doc, what + ": " + std::to_string(count) + " elements of " +
                  std::to_string(element_bytes) + " bytes from byte " + std::to_string(offset) +
                  " (stride " + std::to_string(stride) + ") are out of its bufferView of " +
                  std::to_string(view.size()) + " bytes");
  const bool normalized = a.value("normalized", false);
  std::vector<double> out(count * n);
  for (size_t e = 0; e < count; ++e)
    for (size_t c = 0; c < n; ++c) {
      const char* p = view.data() + offset + e * stride + c * size;
      out[e * n + c] = component(p, type, normalized);
    }
  return out;
}

template <class T>
std::vector<T> cast(const std::vector<double>& values) {
  return std::vector<T>(values.begin(), values.end());
}

// Vertex indices or feature ids: each value finite, integral and in [0, 2^32) before the cast.
std::vector<uint32_t> integers(const GltfDocument& doc, const std::vector<double>& values,
                               const std::string& what) {
  std::vector<uint32_t> out(values.size());
  for (size_t i = 0; i < values.size(); ++i) {
    const double v = values[i];
    if (!(v >= 0 && v < 4294967296.0) || v != std::floor(v))
      fail(doc, what + " holds " + std::to_string(v) + ", not an integer in [0, 2^32)");
    out[i] = uint32_t(v);
  }
  return out;
}

// The named attributes of a Draco-compressed primitive, decoded.
void decode_draco(const GltfDocument& doc, const json& draco, const std::string& what,
                  GltfPrimitive& out) {
  const std::string_view data = buffer_view(doc, draco.value("bufferView", -1));
  draco::DecoderBuffer buffer;
  buffer.Init(data.data(), data.size());
  auto decoded = draco::Decoder().DecodeMeshFromBuffer(&buffer);
  if (!decoded.ok())
    fail(doc, what + ": Draco cannot decode it: " + decoded.status().error_msg_string());
  const draco::Mesh& mesh = *decoded.value();
  const json& ids = draco.value("attributes", json::object());
  const auto values = [&](const char* name, size_t components, auto& into) {
    if (!ids.contains(name)) return;
    const draco::PointAttribute* att = ids[name].is_number_unsigned()
                                           ? mesh.GetAttributeByUniqueId(ids[name].get<uint32_t>())
                                           : nullptr;
    if (!att || size_t(att->num_components()) != components)
      fail(doc, what + ": Draco attribute " + ids[name].dump() + " of " + name +
                    " is missing or has the wrong number of components");
    into.resize(mesh.num_points() * components);
    std::vector<float> value(components);
    for (uint32_t p = 0; p < mesh.num_points(); ++p) {
      att->ConvertValue<float>(att->mapped_index(draco::PointIndex(p)), int8_t(components),
                               value.data());
      for (size_t c = 0; c < components; ++c)
        into[p * components + c] = typename std::decay_t<decltype(into)>::value_type(value[c]);
    }
  };
  values("POSITION", 3, out.positions);
  values("NORMAL", 3, out.normals);
  values("TEXCOORD_0", 2, out.uvs);
  std::vector<double> feature_ids;
  values("_FEATURE_ID_0", 1, feature_ids);
  out.feature_ids = integers(doc, feature_ids, what + ": _FEATURE_ID_0");
  out.indices.reserve(mesh.num_faces() * 3);
  for (draco::FaceIndex f(0); f < mesh.num_faces(); ++f)
    for (int c = 0; c < 3; ++c) out.indices.push_back(mesh.face(f)[c].value());
}

std::string sniff_mime(std::string_view bytes) {
  if (bytes.starts_with("\x89PNG")) return "image/png";
  if (bytes.starts_with("\xFF\xD8")) return "image/jpeg";
  if (bytes.size() >= 12 && bytes.starts_with("RIFF") && bytes.substr(8, 4) == "WEBP")
    return "image/webp";
  return "";
}

}  // namespace

int gltf_index(const GltfDocument& doc, const json& value, const std::string& what) {
  if (!value.is_number_integer() || value.get<int64_t>() < 0 ||
      value.get<int64_t>() > std::numeric_limits<int32_t>::max())
    fail(doc, what + " is " + value.dump() + ", not an index");
  return value.get<int>();
}

std::string_view buffer_view(const GltfDocument& doc, int view) {
  const json& v = element(doc, "bufferViews", view);
  const std::string what = "bufferViews[" + std::to_string(view) + "]";
  const json& b = v.value("buffer", json());
  if (!b.is_number_unsigned() || b.get<uint64_t>() >= doc.buffers.size())
    fail(doc, what + ".buffer " + b.dump() + " is not a buffer");
  const std::string& buffer = doc.buffers[b.get<size_t>()];
  const uint64_t offset = unsigned_field(doc, v, "byteOffset", what, 0);
  const uint64_t length = unsigned_field(doc, v, "byteLength", what, 0);
  if (length > buffer.size() || offset > buffer.size() - length)
    fail(doc, what + ": " + std::to_string(length) + " bytes from byte " + std::to_string(offset) +
                  " are out of its buffer of " + std::to_string(buffer.size()) + " bytes");
  return std::string_view(buffer).substr(offset, length);
}

GltfDocument parse_gltf(std::string_view bytes, const std::string& where,
                        const std::filesystem::path& base_dir) {
  GltfDocument doc{where, base_dir, {}, {}};
  std::string_view text = bytes, bin;
  if (bytes.size() >= 4 && u32(bytes, 0) == kGlbMagic) {
    if (bytes.size() < 20 || u32(bytes, 4) != 2 || u32(bytes, 8) > bytes.size() ||
        u32(bytes, 16) != kJsonChunk || 20 + uint64_t(u32(bytes, 12)) > u32(bytes, 8))
      fail(doc,
           "a GLB whose header or JSON chunk is broken (version 2 and chunk lengths within "
           "the file are read)");
    const size_t end = u32(bytes, 8);
    text = bytes.substr(20, u32(bytes, 12));
    const size_t at = 20 + text.size();
    if (at + 8 <= end && u32(bytes, at + 4) == kBinChunk) {
      if (at + 8 + uint64_t(u32(bytes, at)) > end) fail(doc, "a GLB whose BIN chunk is cut short");
      bin = bytes.substr(at + 8, u32(bytes, at));
    }
  }
  // Nesting deeper than kMaxJsonDepth is refused: quoting such a value overflowed the stack.
  try {
    doc.json = parse_json(text, "JSON");
  } catch (const Error& e) {
    fail(doc, std::string("not glTF: ") + e.what());
  }
  if (!doc.json.is_object())
    fail(doc, "not glTF: neither a GLB (magic 'glTF') nor a glTF JSON object");
  const json& asset = doc.json.value("asset", json::object());
  if (!asset.value("version", std::string()).starts_with("2."))
    fail(doc, "not glTF 2.0: asset.version is " + asset.value("version", json()).dump());
  for (const json& e : doc.json.value("extensionsRequired", json::array()))
    if (e != "KHR_draco_mesh_compression" && e != "KHR_mesh_quantization" &&
        e != "EXT_texture_webp")
      fail(doc, "requires the extension " + e.dump() + ", which is not read");
  read_buffers(doc, bin);
  return doc;
}

GltfPrimitive read_primitive(const GltfDocument& doc, int mesh, int primitive) {
  const std::string what =
      "meshes[" + std::to_string(mesh) + "].primitives[" + std::to_string(primitive) + "]";
  const json& m = element(doc, "meshes", mesh);
  if (!m.contains("primitives") || !m["primitives"].is_array() ||
      size_t(primitive) >= m["primitives"].size())
    fail(doc, "no " + what);
  const json& p = m["primitives"][size_t(primitive)];
  const int mode = p.value("mode", 4);
  if (mode != 4)
    fail(doc, what + " has mode " + std::to_string(mode) +
                  ": only triangles (mode 4) are read, not points, lines, strips or fans");
  const json& atts = p.value("attributes", json::object());
  if (!atts.contains("POSITION")) fail(doc, what + " has no POSITION");
  GltfPrimitive out;
  out.material = p.contains("material") ? gltf_index(doc, p["material"], what + ".material") : -1;
  const json* draco = p.contains("extensions") && p["extensions"].is_object() &&
                              p["extensions"].contains("KHR_draco_mesh_compression")
                          ? &p["extensions"]["KHR_draco_mesh_compression"]
                          : nullptr;
  if (draco) {
    decode_draco(doc, *draco, what, out);
  } else {
    out.positions = cast<float>(read_accessor(doc, atts["POSITION"], 3));
    if (atts.contains("NORMAL")) out.normals = cast<float>(read_accessor(doc, atts["NORMAL"], 3));
    if (atts.contains("TEXCOORD_0"))
      out.uvs = cast<float>(read_accessor(doc, atts["TEXCOORD_0"], 2));
    if (atts.contains("_FEATURE_ID_0"))
      out.feature_ids =
          integers(doc, read_accessor(doc, atts["_FEATURE_ID_0"], 1), what + ": _FEATURE_ID_0");
    if (p.contains("indices")) {
      const json& a = element(doc, "accessors", p["indices"]);
      const int type = a.value("componentType", 0);
      if (type != 5121 && type != 5123 && type != 5125)
        fail(doc, what + ": indices of componentType " + std::to_string(type) +
                      " (glTF: unsigned byte, short or int)");
      out.indices = integers(doc, read_accessor(doc, p["indices"], 1), what + ": indices");
    } else {
      out.indices.resize(out.positions.size() / 3);
      for (size_t i = 0; i < out.indices.size(); ++i) out.indices[i] = uint32_t(i);
    }
  }
  const size_t n = out.positions.size() / 3;
  if ((!out.normals.empty() && out.normals.size() != n * 3) ||
      (!out.uvs.empty() && out.uvs.size() != n * 2) ||
      (!out.feature_ids.empty() && out.feature_ids.size() != n))
    fail(doc, what + ": its attributes have different counts");
  if (out.indices.size() % 3) fail(doc, what + ": indices are not a whole number of triangles");
  for (uint32_t i : out.indices)
    if (i >= n)
      fail(doc, what + ": index " + std::to_string(i) + " is out of its " + std::to_string(n) +
                    " vertices");
  for (float x : out.positions)
    if (!std::isfinite(x)) fail(doc, what + ": a position is not finite");
  return out;
}

std::vector<Material> read_materials(const GltfDocument& doc) {
  std::vector<Material> out;
  const json& materials = doc.json.value("materials", json::array());
  for (size_t i = 0; i < materials.size(); ++i) {
    const json& m = materials[i];
    const json& pbr = m.value("pbrMetallicRoughness", json::object());
    Material mat;
    mat.name = m.value("name", "");
    if (pbr.contains("baseColorFactor"))
      for (size_t c = 0; c < 4; ++c) mat.base_colour[c] = pbr["baseColorFactor"].at(c).get<float>();
    mat.metallic = pbr.value("metallicFactor", 1.0f);  // glTF's defaults
    mat.roughness = pbr.value("roughnessFactor", 1.0f);
    mat.double_sided = m.value("doubleSided", false);
    if (pbr.contains("baseColorTexture")) {
      const json& texture =
          element(doc, "textures", pbr["baseColorTexture"].value("index", json()));
      const json& webp =
          texture.value("extensions", json::object()).value("EXT_texture_webp", json());
      const json& source =
          webp.is_object() ? webp.value("source", json()) : texture.value("source", json());
      const json& image = element(doc, "images", source);
      const std::string what = "images[" + source.dump() + "]";
      mat.image = image.contains("bufferView")
                      ? std::string(buffer_view(doc, gltf_index(doc, image["bufferView"], what)))
                      : read_uri(doc, image.value("uri", ""), what, kMaxGltfBufferBytes);
      mat.image_mime = image.value("mimeType", sniff_mime(mat.image));
      if (mat.image_mime.empty())
        fail(doc, what + " is neither PNG, JPEG nor WebP (and has no mimeType)");
    }
    out.push_back(std::move(mat));
  }
  return out;
}

}  // namespace maquette
