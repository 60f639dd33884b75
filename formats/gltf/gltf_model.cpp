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

  // Draws the tree under the root `root` (a node without a parent: check_node_tree), with an
  // explicit stack so that a deep chain of nodes cannot overflow the call stack.
  void visit_tree(int root) {
    const json& nodes = doc_.json.value("nodes", json::array());
    std::vector<std::pair<int, Matrix>> stack{{root, kIdentity}};
    while (!stack.empty()) {
      const auto [node, parent] = stack.back();
      stack.pop_back();
      const json& n = nodes[size_t(node)];
      const Matrix world = multiply(parent, local_transform(n));
      const std::string what = "nodes[" + std::to_string(node) + "]";
      if (n.contains("mesh")) add_mesh(node, gltf_index(doc_, n["mesh"], what + ".mesh"), world);
      const json& children = n.value("children", json::array());
      for (auto child = children.rbegin(); child != children.rend(); ++child)  // first on top
        stack.emplace_back(gltf_index(doc_, *child, what + ".children"), world);
    }
  }

  MeshContent take() { return std::move(content_); }

 private:
  void add_mesh(int node, int mesh, const Matrix& m) {
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

// Whether each node is a child of another: throws unless the nodes form a forest as glTF
// requires (every node at most one parent, children that exist), which also rules out cycles
// reachable from the roots (a node of a cycle always has a parent).
std::vector<bool> check_node_tree(const GltfDocument& doc) {
  const json& nodes = doc.json.value("nodes", json::array());
  std::vector<bool> has_parent(nodes.size(), false);
  for (size_t i = 0; i < nodes.size(); ++i)
    for (const json& c : nodes[i].value("children", json::array())) {
      const std::string what = "nodes[" + std::to_string(i) + "].children";
      const int child = gltf_index(doc, c, what);
      if (size_t(child) >= nodes.size())
        throw Error(doc.where + ": " + what + " lists node " + std::to_string(child) +
                    ", which does not exist");
      if (has_parent[size_t(child)])
        throw Error(doc.where + ": nodes[" + std::to_string(child) +
                    "] has more than one parent (glTF's nodes form trees)");
      has_parent[size_t(child)] = true;
    }
  return has_parent;
}

MeshContent read_model(const GltfDocument& doc) {
  if (doc.json.value("meshes", json::array()).empty())
    throw Error(doc.where + ": no mesh (a glTF without geometry)");
  ModelReader reader(doc);
  const std::vector<bool> has_parent = check_node_tree(doc);
  const json& scenes = doc.json.value("scenes", json::array());
  if (!scenes.empty()) {
    const int scene = doc.json.contains("scene") ? gltf_index(doc, doc.json["scene"], "scene") : 0;
    if (size_t(scene) >= scenes.size())
      throw Error(doc.where + ": scene " + std::to_string(scene) + " does not exist");
    const std::string what = "scenes[" + std::to_string(scene) + "].nodes";
    for (const json& n : scenes[size_t(scene)].value("nodes", json::array())) {
      const int node = gltf_index(doc, n, what);
      if (size_t(node) >= has_parent.size() || has_parent[size_t(node)])
        throw Error(doc.where + ": " + what + " lists node " + std::to_string(node) +
                    ", which does not exist or is not a root");
      reader.visit_tree(node);
    }
  } else {  // no scene: every root node
    for (size_t i = 0; i < has_parent.size(); ++i)
      if (!has_parent[i]) reader.visit_tree(int(i));
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
        parse_gltf(bytes, "model file " + path, std::filesystem::absolute(path).parent_path()));
  } catch (const json::exception& e) {
    throw Error("model file " + path + ": malformed glTF: " + e.what());
  }
}

}  // namespace maquette
