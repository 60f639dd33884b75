#include "gltf/glb_merge.h"

#include <algorithm>

#include "content/glb_chunks.h"
#include "core/error.h"
#include "gltf/glb_writer.h"

namespace maquette {
namespace {

using nlohmann::json;

// Where each array of the merged glTF stands before a part's entries are appended.
struct Offsets {
  size_t accessors = 0, views = 0, images = 0, samplers = 0, textures = 0, materials = 0,
         meshes = 0, nodes = 0, tables = 0;
};

size_t count(const json& gltf, const char* key) {
  return gltf.contains(key) ? gltf[key].size() : 0;
}

void shift(json& index, size_t by) { index = index.get<size_t>() + by; }

// The texture references of a material: every textureInfo's "index".
void shift_textures(json& material, size_t by) {
  for (const char* key : {"normalTexture", "occlusionTexture", "emissiveTexture"})
    if (material.contains(key)) shift(material[key]["index"], by);
  if (!material.contains("pbrMetallicRoughness")) return;
  for (const char* key : {"baseColorTexture", "metallicRoughnessTexture"})
    if (material["pbrMetallicRoughness"].contains(key))
      shift(material["pbrMetallicRoughness"][key]["index"], by);
}

// A part's objects with its indices shifted by `o`, appended to `out`.
void append_part(json part, const Offsets& o, json& out, const std::string& where) {
  for (json& v : part["bufferViews"]) v["buffer"] = 0;
  for (json& a : part["accessors"]) {
    if (a.contains("sparse")) throw Error(where + ": sparse accessors are not supported");
    if (a.contains("bufferView")) shift(a["bufferView"], o.views);
  }
  for (json& i : part["images"])
    if (i.contains("bufferView")) shift(i["bufferView"], o.views);
  for (json& t : part["textures"]) {
    if (t.contains("source")) shift(t["source"], o.images);
    if (t.contains("sampler")) shift(t["sampler"], o.samplers);
    if (t.contains("extensions") && t["extensions"].contains("EXT_texture_webp"))
      shift(t["extensions"]["EXT_texture_webp"]["source"], o.images);
  }
  for (json& m : part["materials"]) shift_textures(m, o.textures);
  for (json& mesh : part["meshes"])
    for (json& p : mesh["primitives"]) {
      if (p.contains("targets")) throw Error(where + ": morph targets are not supported");
      for (auto& [name, a] : p["attributes"].items()) shift(a, o.accessors);
      if (p.contains("indices")) shift(p["indices"], o.accessors);
      if (p.contains("material")) shift(p["material"], o.materials);
      json& ext = p["extensions"];
      if (ext.contains("KHR_draco_mesh_compression"))
        shift(ext["KHR_draco_mesh_compression"]["bufferView"], o.views);
      if (ext.contains("EXT_mesh_features"))
        for (json& f : ext["EXT_mesh_features"]["featureIds"])
          if (f.contains("propertyTable")) shift(f["propertyTable"], o.tables);
      if (ext.empty()) p.erase("extensions");
    }
  for (json& n : part["nodes"]) {
    if (n.contains("mesh")) shift(n["mesh"], o.meshes);
    if (n.contains("children"))
      for (json& c : n["children"]) shift(c, o.nodes);
    if (n.contains("extensions") && n["extensions"].contains("EXT_mesh_gpu_instancing"))
      for (auto& [name, a] : n["extensions"]["EXT_mesh_gpu_instancing"]["attributes"].items())
        shift(a, o.accessors);
  }
  for (const char* key : {"accessors", "bufferViews", "images", "samplers", "textures", "materials",
                          "meshes", "nodes"})
    for (json& x : part[key]) out[key].push_back(std::move(x));
}

}  // namespace

std::vector<char> merge_glbs(const std::vector<GlbPart>& parts, const json& extras,
                             const std::string& where) {
  json out = {{"asset", {{"version", "2.0"}, {"generator", "maquette"}}}};
  if (!extras.is_null()) out["asset"]["extras"] = extras;
  std::string bin;
  std::vector<json> part_nodes;  // the node of each part
  json metadata;                 // EXT_structural_metadata
  json used = json::array(), required = json::array();
  for (size_t i = 0; i < parts.size(); ++i) {
    const std::string part_where = where + ", part '" + parts[i].name + "'";
    json children = json::array();
    try {
      GlbChunks c = split_glb(parts[i].glb, part_where);
      json& g = c.gltf;
      if (!g.contains("scenes") || g["scenes"].size() != 1)
        throw Error(part_where + ": expected one scene");
      Offsets o;
      o.accessors = count(out, "accessors");
      o.views = count(out, "bufferViews");
      o.images = count(out, "images");
      o.samplers = count(out, "samplers");
      o.textures = count(out, "textures");
      o.materials = count(out, "materials");
      o.meshes = count(out, "meshes");
      o.nodes = count(out, "nodes");
      o.tables = metadata.is_null() ? 0 : metadata["propertyTables"].size();
      while (bin.size() % 8) bin.push_back(0);
      const size_t bin_at = bin.size();
      bin.append(c.bin);
      for (json& v : g["bufferViews"]) v["byteOffset"] = v.value("byteOffset", size_t(0)) + bin_at;
      if (g.contains("extensions") && g["extensions"].contains("EXT_structural_metadata")) {
        json m = g["extensions"]["EXT_structural_metadata"];
        for (json& t : m["propertyTables"])
          for (auto& [name, p] : t["properties"].items())
            for (const char* key : {"values", "arrayOffsets", "stringOffsets"})
              if (p.contains(key)) shift(p[key], o.views);
        if (metadata.is_null()) {
          metadata = m;
        } else if (m["schema"] != metadata["schema"]) {
          throw Error(part_where + ": its EXT_structural_metadata schema differs from the others'");
        } else {
          for (json& t : m["propertyTables"]) metadata["propertyTables"].push_back(std::move(t));
        }
      }
      for (const json& e : g.value("extensionsUsed", json::array()))
        if (std::find(used.begin(), used.end(), e) == used.end()) used.push_back(e);
      for (const json& e : g.value("extensionsRequired", json::array()))
        if (std::find(required.begin(), required.end(), e) == required.end()) required.push_back(e);
      for (const json& n : g["scenes"][0].value("nodes", json::array()))
        children.push_back(n.get<size_t>() + o.nodes);
      append_part(std::move(g), o, out, part_where);
    } catch (const json::exception& e) {
      throw Error(part_where + ": malformed glTF (" + e.what() + ")");
    }
    part_nodes.push_back(
        {{"name", parts[i].name}, {"matrix", parts[i].matrix}, {"children", children}});
  }
  json scene_nodes = json::array();
  for (json& n : part_nodes) {
    scene_nodes.push_back(out["nodes"].size());
    out["nodes"].push_back(std::move(n));
  }
  out["scene"] = 0;
  out["scenes"] = {{{"nodes", scene_nodes}}};
  if (!metadata.is_null()) out["extensions"]["EXT_structural_metadata"] = metadata;
  if (!used.empty()) out["extensionsUsed"] = used;
  if (!required.empty()) out["extensionsRequired"] = required;
  // Keys made empty by parts without them are left out (glTF requires arrays to be non-empty).
  for (auto it = out.begin(); it != out.end();)
    it = it->is_array() && it->empty() ? out.erase(it) : std::next(it);
  if (!bin.empty()) out["buffers"] = {{{"byteLength", (bin.size() + 3) / 4 * 4}}};
  return glb_file(out, bin);
}

}  // namespace maquette
