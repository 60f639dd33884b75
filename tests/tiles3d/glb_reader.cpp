#include "glb_reader.h"

#include <draco/compression/decode.h>
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <set>

namespace maquette::test {
namespace {

uint32_t u32(const std::vector<char>& b, size_t at) {
  uint32_t v;
  std::memcpy(&v, b.data() + at, 4);
  return v;
}

DecodedPrimitive decode(const nlohmann::json& j, const std::vector<char>& bin,
                        const nlohmann::json& prim, const Glb& glb, int node) {
  DecodedPrimitive out;
  const auto& ext = prim["extensions"]["KHR_draco_mesh_compression"];
  const auto& view = j["bufferViews"][ext["bufferView"].get<int>()];
  draco::DecoderBuffer buffer;
  buffer.Init(bin.data() + view["byteOffset"].get<size_t>(), view["byteLength"].get<size_t>());
  auto decoded = draco::Decoder().DecodeMeshFromBuffer(&buffer);
  EXPECT_TRUE(decoded.ok());
  if (!decoded.ok()) return out;
  const draco::Mesh& mesh = *decoded.value();
  const auto& acc = j["accessors"];
  const auto& pos_acc = acc[prim["attributes"]["POSITION"].get<int>()];
  EXPECT_EQ(mesh.num_points(), pos_acc["count"].get<uint32_t>());
  EXPECT_EQ(size_t(mesh.num_faces()) * 3, acc[prim["indices"].get<int>()]["count"].get<size_t>());
  out.index_count = size_t(mesh.num_faces()) * 3;
  for (draco::FaceIndex f(0); f < mesh.num_faces(); ++f)
    out.faces.push_back(
        {mesh.face(f)[0].value(), mesh.face(f)[1].value(), mesh.face(f)[2].value()});
  EXPECT_EQ(ext["attributes"].size(), prim["attributes"].size());
  for (const auto& [name, id] : ext["attributes"].items()) {
    const draco::PointAttribute* att = mesh.GetAttributeByUniqueId(id.get<uint32_t>());
    EXPECT_NE(att, nullptr) << name;
    if (!att) return out;
    EXPECT_EQ(mesh.num_points(), acc[prim["attributes"][name].get<int>()]["count"].get<uint32_t>());
  }
  const draco::PointAttribute* pos =
      mesh.GetAttributeByUniqueId(ext["attributes"]["POSITION"].get<uint32_t>());
  std::array<float, 3> lo, hi;
  lo.fill(1e30f);
  hi.fill(-1e30f);
  for (draco::PointIndex i(0); i < mesh.num_points(); ++i) {
    std::array<float, 3> p;
    pos->GetMappedValue(i, p.data());
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
    out.positions.push_back(glb.place(node, {p[0], p[1], p[2]}));
  }
  if (ext["attributes"].contains("NORMAL")) {
    const draco::PointAttribute* nrm =
        mesh.GetAttributeByUniqueId(ext["attributes"]["NORMAL"].get<uint32_t>());
    for (draco::PointIndex i(0); i < mesh.num_points(); ++i) {
      std::array<float, 3> n;
      nrm->GetMappedValue(i, n.data());
      out.normals.push_back(n);
    }
  }
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(lo[k], pos_acc["min"][k].get<float>());
    EXPECT_EQ(hi[k], pos_acc["max"][k].get<float>());
  }
  return out;
}

}  // namespace

Glb read_glb(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  const std::vector<char> b((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  Glb glb;
  EXPECT_GE(b.size(), 28u) << path;
  if (b.size() < 28) return glb;
  EXPECT_EQ(u32(b, 0), 0x46546C67u);
  EXPECT_EQ(u32(b, 8), b.size());
  const uint32_t json_len = u32(b, 12);
  glb.json = nlohmann::json::parse(b.begin() + 20, b.begin() + 20 + json_len);
  const size_t bin_at = 20 + json_len + 8;
  glb.bin.assign(b.begin() + long(bin_at), b.end());
  std::map<int, int> mesh_node;
  for (size_t n = 0; n < glb.json["nodes"].size(); ++n)
    if (glb.json["nodes"][n].contains("mesh"))
      mesh_node[glb.json["nodes"][n]["mesh"].get<int>()] = int(n);
  for (size_t m = 0; m < glb.json["meshes"].size(); ++m)
    for (const auto& prim : glb.json["meshes"][m]["primitives"])
      if (prim.contains("extensions"))  // Draco: plain primitives are read through floats()
        glb.primitives.push_back(decode(glb.json, glb.bin, prim, glb, mesh_node.at(int(m))));
  return glb;
}

std::array<double, 3> Glb::translation(int node) const {
  return json["nodes"][node].value("translation", std::array<double, 3>{0, 0, 0});
}

std::array<double, 3> Glb::place(int node, const std::array<double, 3>& p) const {
  const auto& n = json["nodes"][node];
  std::array<double, 3> q = p;
  if (n.contains("matrix")) {
    const auto m = n["matrix"].get<std::array<double, 16>>();
    for (int r = 0; r < 3; ++r) q[r] = m[r] * p[0] + m[4 + r] * p[1] + m[8 + r] * p[2] + m[12 + r];
  } else {
    const auto t = translation(node);
    for (int r = 0; r < 3; ++r) q[r] += t[r];
  }
  for (size_t parent = 0; parent < json["nodes"].size(); ++parent)
    for (const auto& child : json["nodes"][parent].value("children", nlohmann::json::array()))
      if (child.get<int>() == node) return place(int(parent), q);
  return q;
}

std::vector<float> Glb::floats(int accessor) const {
  const auto& a = json["accessors"][accessor];
  const auto& view = json["bufferViews"][a["bufferView"].get<int>()];
  const std::map<std::string, size_t> components = {
      {"SCALAR", 1}, {"VEC2", 2}, {"VEC3", 3}, {"VEC4", 4}};
  std::vector<float> v(a["count"].get<size_t>() * components.at(a["type"]));
  EXPECT_EQ(v.size() * 4, view["byteLength"].get<size_t>());
  std::memcpy(v.data(), bin.data() + view["byteOffset"].get<size_t>(), v.size() * 4);
  return v;
}

std::vector<char> Glb::image(int index) const {
  const auto& view = json["bufferViews"][json["images"][index]["bufferView"].get<int>()];
  const auto begin = bin.begin() + view["byteOffset"].get<std::ptrdiff_t>();
  return {begin, begin + view["byteLength"].get<std::ptrdiff_t>()};
}

size_t shared_vertices(const Glb& a, const Glb& b) {
  using Pos = std::array<double, 3>;
  const auto& pa = a.primitives.at(0).positions;
  const auto& pb = b.primitives.at(0).positions;
  const std::set<Pos> sa(pa.begin(), pa.end());
  size_t n = 0;
  for (const Pos& p : std::set<Pos>(pb.begin(), pb.end())) n += sa.count(p);
  return n;
}

}  // namespace maquette::test
