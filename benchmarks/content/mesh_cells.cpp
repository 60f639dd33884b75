// Not a Google Benchmark: the city of content_benchmark (city_content.h) written once per cell as
// an uncompressed GLB, the input of compare_gltf_transform.sh's peer, then encoded by our mesh
// GLB writer (gltf/mesh_glb.h, Draco) and written per cell, timed.
//
// Usage: mesh_cells OUT_DIR
// Writes OUT_DIR/plain/CELL.glb: the cell's objects as one primitive (they share the building
// material), glTF axes as mesh_glb's, plain float32 POSITION, NORMAL and TEXCOORD_0, uint16
// _FEATURE_ID_0 (the object's row) and uint32 indices, the JPEG embedded: what mesh_glb's Draco
// stream holds, with the same per-object metadata (mesh_metadata's property table, which
// gltf-transform keeps). OUT_DIR/ours/CELL.glb: encode_mesh_glb of the same content (1 mm
// positions).
// OUT_DIR/cells.json: per cell, the Draco position bits mesh_glb chose (for the peer to use the
// same); and the totals and our times (encode + write, excluding making the content): wall and
// CPU seconds of this process. Files are written unsynced, as the peer writes them.
#include <sys/resource.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>

#include "city_content.h"
#include "core/error.h"
#include "gltf/enu_axes.h"
#include "gltf/glb_writer.h"
#include "gltf/mesh_glb.h"

namespace maquette::bench {
namespace {

using nlohmann::json;

constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;
constexpr int kUnsignedShort = 5123, kUnsignedInt = 5125, kFloat = 5126;

double cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

struct Vertices {
  std::vector<float> positions, normals, uvs;  // glTF axes
  std::vector<uint16_t> feature_ids;
  std::vector<uint32_t> indices;
};

Vertices gltf_vertices(const MeshContent& c) {
  if (c.objects.size() > 65536) throw Error("mesh_cells: more than 65536 objects in a cell");
  Vertices v;
  for (size_t i = 0; i < c.objects.size(); ++i) {
    const MeshObject& o = c.objects[i];
    if (o.material != 0 || o.normals.empty() || o.uvs.empty())
      throw Error("mesh_cells: objects must share material 0, normals and uvs");
    const auto base = uint32_t(v.positions.size() / 3);
    for (size_t k = 0; k < o.positions.size(); k += 3) {
      append_gltf_axes(&o.positions[k], v.positions);
      append_gltf_axes(&o.normals[k], v.normals);
      v.feature_ids.push_back(uint16_t(i));
    }
    v.uvs.insert(v.uvs.end(), o.uvs.begin(), o.uvs.end());
    for (uint32_t k : o.indices) v.indices.push_back(base + k);
  }
  return v;
}

struct Bounds {
  std::array<float, 3> lo, hi;
};
Bounds bounds(const std::vector<float>& positions) {
  Bounds b;
  b.lo.fill(std::numeric_limits<float>::max());
  b.hi.fill(std::numeric_limits<float>::lowest());
  for (size_t i = 0; i < positions.size(); ++i) {
    b.lo[i % 3] = std::min(b.lo[i % 3], positions[i]);
    b.hi[i % 3] = std::max(b.hi[i % 3], positions[i]);
  }
  return b;
}

// The widest axis of the positions, as mesh_glb measures a primitive for its position bits.
double extent(const std::vector<float>& positions) {
  const Bounds b = bounds(positions);
  double e = 0;
  for (int a = 0; a < 3; ++a) e = std::max(e, double(b.hi[a]) - b.lo[a]);
  return e;
}

std::vector<char> plain_glb(const MeshContent& c, const Vertices& v) {
  GlbBuffer buffer;
  const auto attribute = [&](const auto& values, int components, int type, const char* shape) {
    return buffer.accessor(
        {{"bufferView",
          buffer.view(values.data(), values.size() * sizeof(values[0]), kArrayBuffer)},
         {"componentType", type},
         {"count", values.size() / size_t(components)},
         {"type", shape}});
  };
  const Bounds b = bounds(v.positions);
  json prim = {{"mode", 4}, {"material", 0}};
  prim["extensions"]["EXT_mesh_features"] = mesh_feature_ids(c.objects.size());
  prim["attributes"]["POSITION"] = buffer.accessor(
      {{"bufferView", buffer.view(v.positions.data(), v.positions.size() * 4, kArrayBuffer)},
       {"componentType", kFloat},
       {"count", v.positions.size() / 3},
       {"type", "VEC3"},
       {"min", b.lo},
       {"max", b.hi}});
  prim["attributes"]["NORMAL"] = attribute(v.normals, 3, kFloat, "VEC3");
  prim["attributes"]["TEXCOORD_0"] = attribute(v.uvs, 2, kFloat, "VEC2");
  prim["attributes"]["_FEATURE_ID_0"] = attribute(v.feature_ids, 1, kUnsignedShort, "SCALAR");
  prim["indices"] = buffer.accessor(
      {{"bufferView", buffer.view(v.indices.data(), v.indices.size() * 4, kElementArrayBuffer)},
       {"componentType", kUnsignedInt},
       {"count", v.indices.size()},
       {"type", "SCALAR"}});
  const Material& m = c.materials.at(0);
  const int image = buffer.view(m.image.data(), m.image.size());
  json gltf = {{"asset", {{"version", "2.0"}, {"generator", "maquette mesh_cells"}}},
               {"scene", 0},
               {"scenes", {{{"nodes", {0}}}}},
               {"nodes", {{{"mesh", 0}}}},
               {"meshes", {{{"primitives", {prim}}}}},
               {"materials",
                {{{"name", m.name},
                  {"pbrMetallicRoughness",
                   {{"baseColorFactor", m.base_colour},
                    {"metallicFactor", m.metallic},
                    {"roughnessFactor", m.roughness},
                    {"baseColorTexture", {{"index", 0}}}}}}}},
               {"images", {{{"bufferView", image}, {"mimeType", m.image_mime}}}},
               {"textures", {{{"sampler", 0}, {"source", 0}}}},
               {"samplers", {{{"magFilter", 9729}, {"minFilter", 9987}}}},
               {"extensionsUsed", {"EXT_mesh_features", "EXT_structural_metadata"}}};
  gltf["extensions"]["EXT_structural_metadata"] = mesh_metadata(c, buffer);
  return buffer.finish(std::move(gltf));
}

// Written as node's fs.writeFile writes the peer's (not synced: core/output_file.h's whole-file
// writes sync each file, which would time the disk rather than the encoder).
void write_bytes(const std::filesystem::path& path, const char* data, size_t size) {
  std::ofstream f(path, std::ios::binary);
  if (!f.write(data, std::streamsize(size))) throw Error("cannot write " + path.string());
}

int run(const std::filesystem::path& out) {
  const std::map<CellId, MeshContent> cells = city_buildings(soho_footprints_path());
  const ContentStats stats = mesh_stats(cells);
  std::filesystem::create_directories(out / "plain");
  std::filesystem::create_directories(out / "ours");
  json manifest = {{"cells", json::array()}};
  for (const auto& [cell, content] : cells) {
    const Vertices v = gltf_vertices(content);
    const std::vector<char> plain = plain_glb(content, v);
    write_bytes(out / "plain" / (cell.ToText() + ".glb"), plain.data(), plain.size());
    manifest["cells"].push_back(
        {{"cell", cell.ToText()}, {"position_bits", position_bits(extent(v.positions), {})}});
  }
  const auto start = std::chrono::steady_clock::now();
  const double cpu = cpu_seconds();
  for (const auto& [cell, content] : cells) {
    const std::string glb = encode_mesh_glb(content);
    write_bytes(out / "ours" / (cell.ToText() + ".glb"), glb.data(), glb.size());
  }
  manifest["ours_cpu_s"] = cpu_seconds() - cpu;
  manifest["ours_wall_s"] =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  manifest["objects"] = stats.objects;
  manifest["triangles"] = stats.triangles;
  std::ofstream(out / "cells.json") << manifest.dump(1) << "\n";
  return 0;
}

}  // namespace
}  // namespace maquette::bench

int main(int argc, char** argv) try {
  if (argc != 2) {
    std::cerr << "usage: mesh_cells OUT_DIR\n";
    return 2;
  }
  return maquette::bench::run(argv[1]);
} catch (const std::exception& e) {
  std::cerr << "mesh_cells: " << e.what() << "\n";
  return 1;
}
