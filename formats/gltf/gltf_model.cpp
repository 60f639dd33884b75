#include "gltf/gltf_model.h"

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "core/error.h"
#include "core/file_access.h"
#include "gltf/enu_axes.h"
#include "gltf/gltf_document.h"

namespace maquette {
namespace {

using nlohmann::json;
using Matrix = std::array<double, 16>;  // column-major, as glTF's node.matrix

constexpr Matrix kIdentity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

Matrix multiply(const Matrix& a, const Matrix& b) {
  Matrix m{};
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      for (int k = 0; k < 4; ++k) m[c * 4 + r] += a[k * 4 + r] * b[c * 4 + k];
  return m;
}

std::array<double, 3> numbers3(const json& node, const char* key, double fallback) {
  std::array<double, 3> v{fallback, fallback, fallback};
  if (node.contains(key))
    for (size_t i = 0; i < 3; ++i) v[i] = node[key].at(i).get<double>();
  return v;
}

// The node's local transform: its matrix, or T * R * S.
Matrix local_transform(const json& node) {
  Matrix m = kIdentity;
  if (node.contains("matrix")) {
    for (size_t i = 0; i < 16; ++i) m[i] = node["matrix"].at(i).get<double>();
    return m;
  }
  const auto t = numbers3(node, "translation", 0), s = numbers3(node, "scale", 1);
  double x = 0, y = 0, z = 0, w = 1;
  if (node.contains("rotation")) {
    const json& r = node["rotation"];
    x = r.at(0).get<double>(), y = r.at(1).get<double>(), z = r.at(2).get<double>(),
    w = r.at(3).get<double>();
  }
  const Matrix rotation = {1 - 2 * (y * y + z * z),
                           2 * (x * y + z * w),
                           2 * (x * z - y * w),
                           0,
                           2 * (x * y - z * w),
                           1 - 2 * (x * x + z * z),
                           2 * (y * z + x * w),
                           0,
                           2 * (x * z + y * w),
                           2 * (y * z - x * w),
                           1 - 2 * (x * x + y * y),
                           0,
                           0,
                           0,
                           0,
                           1};
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) m[c * 4 + r] = rotation[c * 4 + r] * s[c];
  m[12] = t[0], m[13] = t[1], m[14] = t[2];
  return m;
}

class ModelReader {
 public:
  explicit ModelReader(const GltfDocument& doc) : doc_(doc) {
    content_.materials = read_materials(doc);
  }

  void visit(size_t node, const Matrix& parent, size_t depth) {
    const json& nodes = doc_.json.value("nodes", json::array());
    if (node >= nodes.size() || depth > nodes.size())
      throw Error(doc_.where + ": nodes[" + std::to_string(node) +
                  "] does not exist or is its own ancestor");
    const json& n = nodes[node];
    const Matrix world = multiply(parent, local_transform(n));
    if (n.contains("mesh")) add_mesh(node, n["mesh"].get<int>(), world);
    for (const json& child : n.value("children", json::array()))
      visit(child.get<size_t>(), world, depth + 1);
  }

  MeshContent take() { return std::move(content_); }

 private:
  void add_mesh(size_t node, int mesh, const Matrix& m) {
    const json& meshes = doc_.json.value("meshes", json::array());
    if (mesh < 0 || size_t(mesh) >= meshes.size())
      throw Error(doc_.where + ": nodes[" + std::to_string(node) + "] draws mesh " +
                  std::to_string(mesh) + ", which does not exist");
    // Normals go through the inverse transpose of the linear part: its cofactors (the
    // determinant's scale goes when they are normalized; its sign flips the winding).
    const auto a = [&](int r, int c) { return m[c * 4 + r]; };
    std::array<double, 9> cof;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c)
        cof[r * 3 + c] = a((r + 1) % 3, (c + 1) % 3) * a((r + 2) % 3, (c + 2) % 3) -
                         a((r + 1) % 3, (c + 2) % 3) * a((r + 2) % 3, (c + 1) % 3);
    const double det = a(0, 0) * cof[0] + a(0, 1) * cof[1] + a(0, 2) * cof[2];
    const size_t count = meshes[size_t(mesh)].value("primitives", json::array()).size();
    for (size_t i = 0; i < count; ++i) {
      const GltfPrimitive p = read_primitive(doc_, mesh, int(i));
      if (p.material >= int(content_.materials.size()))
        throw Error(doc_.where + ": meshes[" + std::to_string(mesh) + "].primitives[" +
                    std::to_string(i) + "] has material " + std::to_string(p.material) + " of " +
                    std::to_string(content_.materials.size()));
      MeshObject o;
      o.material = p.material;
      o.provenance.object_id = content_.objects.size();
      o.provenance.tool = "model";
      o.provenance.attributes = {{"node", node}, {"mesh", mesh}, {"primitive", i}};
      for (size_t v = 0; v < p.positions.size(); v += 3) {
        float moved[3], normal[3];
        for (int r = 0; r < 3; ++r)
          moved[r] = float(a(r, 0) * p.positions[v] + a(r, 1) * p.positions[v + 1] +
                           a(r, 2) * p.positions[v + 2] + a(r, 3));
        append_enu_axes(moved, o.positions);
        if (p.normals.empty()) continue;
        double x[3], length = 0;
        for (int r = 0; r < 3; ++r) {
          x[r] = cof[r * 3] * p.normals[v] + cof[r * 3 + 1] * p.normals[v + 1] +
                 cof[r * 3 + 2] * p.normals[v + 2];
          length += x[r] * x[r];
        }
        length = std::sqrt(length) * (det < 0 ? -1 : 1);
        for (int r = 0; r < 3; ++r) normal[r] = length != 0 ? float(x[r] / length) : 0.f;
        append_enu_axes(normal, o.normals);
      }
      o.uvs = p.uvs;
      o.indices = p.indices;
      if (det < 0)  // a mirroring transform: keep triangles counter-clockwise seen from outside
        for (size_t t = 0; t < o.indices.size(); t += 3)
          std::swap(o.indices[t + 1], o.indices[t + 2]);
      content_.objects.push_back(std::move(o));
    }
  }

  const GltfDocument& doc_;
  MeshContent content_;
};

MeshContent read_model(const GltfDocument& doc) {
  if (doc.json.value("meshes", json::array()).empty())
    throw Error(doc.where + ": no mesh (a glTF without geometry)");
  ModelReader reader(doc);
  const json& scenes = doc.json.value("scenes", json::array());
  if (!scenes.empty()) {
    const size_t scene = doc.json.value("scene", size_t(0));
    if (scene >= scenes.size())
      throw Error(doc.where + ": scene " + std::to_string(scene) + " does not exist");
    for (const json& node : scenes[scene].value("nodes", json::array()))
      reader.visit(node.get<size_t>(), kIdentity, 0);
  } else {  // no scene: every root node
    const json& nodes = doc.json.value("nodes", json::array());
    std::vector<bool> child(nodes.size(), false);
    for (const json& n : nodes)
      for (const json& c : n.value("children", json::array()))
        if (c.get<size_t>() < child.size()) child[c.get<size_t>()] = true;
    for (size_t i = 0; i < nodes.size(); ++i)
      if (!child[i]) reader.visit(i, kIdentity, 0);
  }
  MeshContent content = reader.take();
  if (content.objects.empty()) throw Error(doc.where + ": no mesh drawn by a node of its scene");
  return content;
}

}  // namespace

MeshContent read_gltf_model(const std::string& path) {
  if (const auto problem = file_access_problem(path))
    throw Error("model file " + path + ": " + *problem);
  const uint64_t size = std::filesystem::file_size(path);
  if (size > kMaxGltfBufferBytes)
    throw Error("model file " + path + ": " + std::to_string(size) +
                " bytes, more than the 1 GiB read");
  std::string bytes(size, '\0');
  std::ifstream in(path, std::ios::binary);
  if (!in.read(bytes.data(), std::streamsize(size)))
    throw Error("model file " + path + ": cannot be read");
  try {
    return read_model(
        parse_gltf(bytes, "model file " + path, std::filesystem::path(path).parent_path()));
  } catch (const json::exception& e) {
    throw Error("model file " + path + ": malformed glTF: " + e.what());
  }
}

}  // namespace maquette
