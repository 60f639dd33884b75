#include "tileset_reader.h"

#include <gtest/gtest.h>

#include <GeographicLib/Geocentric.hpp>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>

namespace maquette::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr double kPi = std::numbers::pi;

json read_json(const fs::path& p) { return json::parse(std::ifstream(p)); }

// A region as 3D Tiles defines it, with longitudes and latitudes in range and west <= east (the
// exports never cross the antimeridian: not every viewer reads west > east).
void expect_valid(const json& r, const fs::path& file) {
  ASSERT_EQ(r.size(), 6u) << file;
  const double w = r[0], s = r[1], e = r[2], n = r[3], lo = r[4], hi = r[5];
  EXPECT_TRUE(-kPi <= w && w <= e && e <= kPi) << file << " " << r;
  EXPECT_TRUE(-kPi / 2 <= s && s <= n && n <= kPi / 2) << file << " " << r;
  EXPECT_LE(lo, hi) << file << " " << r;
}

// A point (degrees, metres) `top` metres high inside region `r`. Longitudes +-180 are one;
// at a pole any longitude is.
void expect_inside(const json& r, const std::array<double, 3>& g, double top, const fs::path& uri) {
  EXPECT_GE(g[2], r[4].get<double>()) << uri;
  EXPECT_LE(g[2] + top, r[5].get<double>()) << uri;
  const double rad = kPi / 180, lat = g[1] * rad;
  EXPECT_GE(lat, r[1].get<double>()) << uri;
  EXPECT_LE(lat, r[3].get<double>()) << uri;
  if (std::abs(g[1]) > 90 - 1e-7) return;
  // A region ends at +-pi (3D Tiles' range), so vertices on the antimeridian, which
  // quantization moves by up to half a lattice step (~500 m for level 0's 14-bit lattice), may
  // stray across it.
  const double w = r[0], e = r[2], slack = 1e-4;
  bool in = false;
  for (const double shift : {-360.0, 0.0, 360.0}) {
    const double lon = (g[0] + shift) * rad;
    in = in || (lon >= (w == -kPi ? w - slack : w) && lon <= (e == kPi ? e + slack : e));
  }
  EXPECT_TRUE(in) << uri << " lon " << g[0] << " lat " << g[1] << " outside " << r;
}

void walk(const fs::path& file, const json& tile, const json* parent, Export& out) {
  const auto& r = tile["boundingVolume"]["region"];
  expect_valid(r, file);
  if (parent) {
    const auto& pr = (*parent)["boundingVolume"]["region"];
    for (int k : {0, 1, 4}) EXPECT_GE(r[k].get<double>(), pr[k].get<double>());
    for (int k : {2, 3, 5}) EXPECT_LE(r[k].get<double>(), pr[k].get<double>());
    EXPECT_LT(tile["geometricError"].get<double>(),
              (*parent)["geometricError"].get<double>() + 1e-9);
  }
  json contents = tile.value("contents", json::array());
  if (tile.contains("content")) contents.push_back(tile["content"]);
  const auto m = out.tileset["root"]["transform"].get<std::vector<double>>();
  for (const auto& content : contents) {
    const fs::path uri = file.parent_path() / content["uri"].get<std::string>();
    EXPECT_TRUE(fs::exists(uri)) << uri;
    if (uri.extension() == ".json") {
      walk(uri, read_json(uri)["root"], &tile, out);
      continue;
    }
    Glb glb = read_glb(uri.string());
    if (const auto inst = instancing(glb)) {  // the prototypes' bases and tops
      const auto t = glb.floats((*inst)["TRANSLATION"]), sc = glb.floats((*inst)["SCALE"]);
      for (size_t i = 0; i < sc.size() / 3; ++i)
        expect_inside(r, geodetic(m, glb.place(0, {t[3 * i], t[3 * i + 1], t[3 * i + 2]})),
                      sc[3 * i], uri);
    } else {
      for (const auto& prim : glb.primitives)
        for (const Pos& p : prim.positions) expect_inside(r, geodetic(m, p), 0, uri);
    }
    out.glbs[fs::relative(uri, out.dir).string()] = std::move(glb);
  }
  if (tile.contains("children"))
    for (const auto& c : tile["children"]) walk(file, c, &tile, out);
}

}  // namespace

Export read_export(const std::string& dir) {
  Export x;
  x.dir = dir;
  x.tileset = read_json(dir + "/tileset.json");
  walk(dir + "/tileset.json", x.tileset["root"], nullptr, x);
  return x;
}

std::array<double, 3> geodetic(const std::vector<double>& m, const Pos& p) {
  const double e = p[0], n = -p[2], u = p[1];
  double x[3];
  for (int r = 0; r < 3; ++r) x[r] = m[r] * e + m[4 + r] * n + m[8 + r] * u + m[12 + r];
  double lat, lon, h;
  GeographicLib::Geocentric::WGS84().Reverse(x[0], x[1], x[2], lat, lon, h);
  return {lon, lat, h};
}

std::optional<json> instancing(const Glb& glb) {
  const json& node = glb.json["nodes"][0];
  if (!node.contains("extensions")) return std::nullopt;
  return node["extensions"]["EXT_mesh_gpu_instancing"]["attributes"];
}

std::optional<bool> gltf_validator_passes(const std::string& dir) {
  const std::string node = MAQUETTE_NODE_DIR;
  if (!fs::exists(node + "/node_modules/gltf-validator")) return std::nullopt;
  const std::string cmd = "node " + node + "/validate.mjs " + dir + " > /dev/null";
  return std::system(cmd.c_str()) == 0;
}

}  // namespace maquette::test
