#include "gpu_instancing_check.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>

namespace maquette::test {
namespace {

using nlohmann::json;

constexpr int kByte = 5120, kUnsignedByte = 5121, kShort = 5122, kUnsignedShort = 5123,
              kUnsignedInt = 5125, kFloat = 5126;

uint32_t u32(std::string_view bytes, size_t at) {
  uint32_t v;
  std::memcpy(&v, bytes.data() + at, 4);
  return v;
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
  }
  return 0;
}

size_t components(const std::string& type) {
  if (type == "SCALAR") return 1;
  if (type == "VEC2") return 2;
  if (type == "VEC3") return 3;
  if (type == "VEC4") return 4;
  return 0;
}

// An accessor's values as doubles (normalized integers as glTF maps them), or a problem.
struct Values {
  std::vector<double> values;
  size_t count = 0, width = 0;
  std::string problem;
  double at(size_t i, size_t k) const { return values[i * width + k]; }
};

double component(const char* p, int type, bool normalized) {
  auto read = [p]<typename T>(T) {
    T v;
    std::memcpy(&v, p, sizeof v);
    return v;
  };
  switch (type) {
    case kFloat:
      return read(float{});
    case kByte:
      return normalized ? std::max(read(int8_t{}) / 127.0, -1.0) : read(int8_t{});
    case kUnsignedByte:
      return normalized ? read(uint8_t{}) / 255.0 : read(uint8_t{});
    case kShort:
      return normalized ? std::max(read(int16_t{}) / 32767.0, -1.0) : read(int16_t{});
    case kUnsignedShort:
      return normalized ? read(uint16_t{}) / 65535.0 : read(uint16_t{});
    default:
      return read(uint32_t{});
  }
}

Values read_accessor(const GlbChunks& glb, size_t index) {
  Values out;
  const json& accessors = glb.json.value("accessors", json::array());
  if (index >= accessors.size()) {
    out.problem = "accessor " + std::to_string(index) + " does not exist";
    return out;
  }
  const json& a = accessors[index];
  const int type = a.value("componentType", 0);
  out.count = a.value("count", size_t{0});
  out.width = components(a.value("type", ""));
  const size_t size = component_bytes(type) * out.width;
  if (size == 0 || out.count == 0) {
    out.problem =
        "accessor " + std::to_string(index) + " has no valid type, component type or count";
    return out;
  }
  out.values.assign(out.count * out.width, 0.0);
  if (a.contains("sparse")) out.problem = "accessor " + std::to_string(index) + " is sparse";
  if (!a.contains("bufferView")) return out;  // all zeros, as glTF says
  const size_t v = a["bufferView"];
  const json& views = glb.json.value("bufferViews", json::array());
  if (v >= views.size()) {
    out.problem = "accessor " + std::to_string(index) + " has bufferView " + std::to_string(v) +
                  " of " + std::to_string(views.size());
    return out;
  }
  const json& view = views[v];
  const size_t view_offset = view.value("byteOffset", size_t{0});
  const size_t view_length = view.value("byteLength", size_t{0});
  const size_t stride = view.value("byteStride", size);
  const size_t offset = a.value("byteOffset", size_t{0});
  const std::string where =
      "accessor " + std::to_string(index) + " (bufferView " + std::to_string(v) + ")";
  if (view.value("buffer", -1) != 0 || view_offset + view_length > glb.bin.size())
    out.problem = where + ": bufferView bytes " + std::to_string(view_offset) + " + " +
                  std::to_string(view_length) + " are not within the BIN chunk (" +
                  std::to_string(glb.bin.size()) + " bytes)";
  else if (offset % component_bytes(type) != 0)
    out.problem = where + ": byteOffset " + std::to_string(offset) + " is not aligned";
  else if (stride < size || offset + stride * (out.count - 1) + size > view_length)
    out.problem = where + ": " + std::to_string(out.count) + " elements of " +
                  std::to_string(size) + " bytes (stride " + std::to_string(stride) +
                  ") from byte " + std::to_string(offset) + " exceed its " +
                  std::to_string(view_length) + " bytes";
  if (!out.problem.empty()) return out;
  const bool normalized = a.value("normalized", false);
  for (size_t i = 0; i < out.count; ++i)
    for (size_t k = 0; k < out.width; ++k)
      out.values[i * out.width + k] =
          component(glb.bin.data() + view_offset + offset + i * stride + k * component_bytes(type),
                    type, normalized);
  return out;
}

// The problem with the attribute's accessor type, or "".
std::string type_problem(const std::string& name, const json& a) {
  const int type = a.value("componentType", 0);
  const std::string shape = a.value("type", "");
  if (name == "TRANSLATION" || name == "SCALE")
    return shape == "VEC3" && type == kFloat ? "" : "must be VEC3 of floats";
  if (name == "ROTATION")
    return shape == "VEC4" && (type == kFloat ||
                               ((type == kByte || type == kShort) && a.value("normalized", false)))
               ? ""
               : "must be VEC4 of floats or of normalized signed bytes or shorts";
  return name.starts_with("_") ? "" : "is neither TRANSLATION, ROTATION, SCALE nor named _*";
}

// The problem with instance `i`'s value of the attribute, or "".
std::string value_problem(const std::string& name, const Values& v, size_t i) {
  for (size_t k = 0; k < v.width; ++k) {
    const double x = v.at(i, k);
    if (!std::isfinite(x)) return "component " + std::to_string(k) + " is not finite";
    if (name == "SCALE" && x == 0) return "component " + std::to_string(k) + " is 0";
  }
  if (name == "ROTATION") {
    const double norm = std::sqrt(v.at(i, 0) * v.at(i, 0) + v.at(i, 1) * v.at(i, 1) +
                                  v.at(i, 2) * v.at(i, 2) + v.at(i, 3) * v.at(i, 3));
    if (std::abs(norm - 1) > 1e-3)
      return "quaternion (" + std::to_string(v.at(i, 0)) + ", " + std::to_string(v.at(i, 1)) +
             ", " + std::to_string(v.at(i, 2)) + ", " + std::to_string(v.at(i, 3)) + ") has norm " +
             std::to_string(norm);
  }
  return "";
}

}  // namespace

GlbChunks split_glb(std::string_view bytes) {
  if (bytes.size() < 20 || u32(bytes, 0) != 0x46546C67 || u32(bytes, 4) != 2 ||
      u32(bytes, 8) != bytes.size())
    throw std::runtime_error("not a GLB 2 file of its stated length");
  const size_t json_length = u32(bytes, 12);
  if (u32(bytes, 16) != 0x4E4F534A || 20 + json_length > bytes.size())
    throw std::runtime_error("GLB without a JSON chunk within the file");
  GlbChunks out;
  out.json = json::parse(bytes.substr(20, json_length));
  const size_t bin = 20 + json_length;
  if (bin + 8 <= bytes.size()) {
    const size_t length = u32(bytes, bin);
    if (u32(bytes, bin + 4) != 0x004E4942 || bin + 8 + length > bytes.size())
      throw std::runtime_error("GLB whose second chunk is not a BIN chunk within the file");
    out.bin = bytes.substr(bin + 8, length);
  }
  return out;
}

std::vector<double> accessor_values(const GlbChunks& glb, size_t index) {
  Values v = read_accessor(glb, index);
  if (!v.problem.empty()) throw std::runtime_error(v.problem);
  return std::move(v.values);
}

std::vector<std::string> gpu_instancing_problems(const GlbChunks& glb) {
  std::vector<std::string> problems;
  const json& nodes = glb.json.value("nodes", json::array());
  for (size_t n = 0; n < nodes.size(); ++n) {
    const json* ext = nodes[n].contains("extensions") &&
                              nodes[n]["extensions"].contains("EXT_mesh_gpu_instancing")
                          ? &nodes[n]["extensions"]["EXT_mesh_gpu_instancing"]
                          : nullptr;
    if (!ext) continue;
    const std::string node = "node " + std::to_string(n);
    if (!nodes[n].contains("mesh")) problems.push_back(node + ": instanced but has no mesh");
    const json attributes = ext->value("attributes", json::object());
    if (attributes.empty()) problems.push_back(node + ": no instance attributes");
    size_t count = 0;
    std::string first;
    for (const auto& [name, index] : attributes.items()) {
      const std::string where = node + " " + name + " (accessor " + index.dump() + ")";
      if (!index.is_number_integer() || index < 0) {
        problems.push_back(where + ": not an accessor index");
        continue;
      }
      const Values v = read_accessor(glb, index);
      if (!v.problem.empty()) {
        problems.push_back(node + " " + name + ": " + v.problem);
        continue;
      }
      if (const std::string p = type_problem(name, glb.json["accessors"][size_t(index)]);
          !p.empty()) {
        problems.push_back(where + ": " + p);
        continue;
      }
      if (first.empty()) {
        first = name;
        count = v.count;
      } else if (v.count != count) {
        problems.push_back(where + ": " + std::to_string(v.count) + " instances, " + first +
                           " has " + std::to_string(count));
      }
      for (size_t i = 0; i < v.count; ++i)
        if (const std::string p = value_problem(name, v, i); !p.empty()) {
          problems.push_back(where + ", instance " + std::to_string(i) + ": " + p);
          break;  // one per attribute is enough to tell
        }
    }
  }
  return problems;
}

}  // namespace maquette::test
