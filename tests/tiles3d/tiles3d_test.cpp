// maquette export tiles3d|glb|drc on a small generated store: Draco primitives decoded and checked
// against their accessors and the DEM, shared edges identical (also across a face seam), the
// tileset's tree, the Khronos glTF validator, and bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <optional>
#include <set>

#include "run_cli.h"
#include "tiles3d_fixture.h"
#include "tileset_reader.h"

namespace maquette::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const Export& tiles3d_export() {
  static const Export e = [] {
    const std::string dir = temp_dir() + "/tiles";
    const auto r = run_maquette("export tiles3d " + tiles3d_fixture().store_path + " " + dir +
                                " --dem dem --texture rgb --levels 4..6");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return read_export(dir);
  }();
  return e;
}

const Glb& glb_of(CellId c) {
  return tiles3d_export().glbs.at("tiles/" + std::to_string(c.level()) + "/" + c.ToText() + ".glb");
}

TEST(Tiles3d, TilesetTreeAndContents) {
  const Export& e = tiles3d_export();
  EXPECT_EQ(e.tileset["asset"]["version"], "1.1");
  // 6 cells at level 6, their parents at 5 and 4 (the seam cells have distinct ancestors).
  EXPECT_GE(e.glbs.size(), 6u + 3u + 3u);
  for (const auto& [uri, glb] : e.glbs) {
    ASSERT_EQ(glb.primitives.size(), 1u) << uri;
    EXPECT_GT(glb.primitives[0].index_count, 0u);
    EXPECT_EQ(glb.json["extensionsRequired"][0], "KHR_draco_mesh_compression");
    EXPECT_EQ(glb.json["images"][0]["mimeType"], "image/jpeg");
  }
}

TEST(Tiles3d, PositionsFollowTheDem) {
  const Export& e = tiles3d_export();
  const auto m = e.tileset["root"]["transform"].get<std::vector<double>>();
  const Grid& grid = default_grid();
  for (CellId c : tiles3d_fixture().block) {
    const auto& prim = glb_of(c).primitives[0];
    // Lattice step of 14 bits over the cell's extent; skirts hang 2 vertex spacings down.
    const double step = 2 * grid.level_info(kLevel, 1).cell_side_m / 16382;
    const double skirt = 2 * grid.level_info(kLevel, kTileSize).pixel_m;
    size_t top = 0;
    for (const Pos& p : prim.positions) {
      const auto g = geodetic(m, p);
      const double want = dem_field({g[0], g[1]});
      const bool on_top = std::abs(g[2] - want) < step;
      top += on_top;
      EXPECT_TRUE(on_top || std::abs(g[2] - (want - skirt)) < step)
          << c.ToText() << " h " << g[2] << " dem " << want;
    }
    EXPECT_EQ(top, size_t((kTileSize + 1) * (kTileSize + 1)));
  }
}

TEST(Tiles3d, SharedEdgesDecodeIdentically) {
  const auto& f = tiles3d_fixture();
  // Cells 0 | 1 side by side, 0 over 2; an edge has kTileSize + 1 vertices (and as many skirt
  // vertices hanging from them).
  EXPECT_GE(shared_vertices(glb_of(f.block[0]), glb_of(f.block[1])), size_t(kTileSize + 1));
  EXPECT_GE(shared_vertices(glb_of(f.block[0]), glb_of(f.block[2])), size_t(kTileSize + 1));
  EXPECT_GE(shared_vertices(glb_of(f.seam[0]), glb_of(f.seam[1])), size_t(kTileSize + 1));
}

// Where three faces meet (N's bottom-right corner = O's top-right = P's top-left) every pair of
// the three corner cells shares an edge, computed from a different face plane on each side: the
// decoded edge vertices must still coincide exactly.
TEST(Tiles3d, EdgesMatchAtACubeCorner) {
  const int n = 1 << kLevel;
  const CellId north = CellId::FromFaceColRow(0, kLevel, n - 1, n - 1);
  const CellId o = CellId::FromFaceColRow(1, kLevel, n - 1, 0);
  const CellId p = CellId::FromFaceColRow(2, kLevel, 0, 0);
  // The grid says they are edge neighbours (checked against geometry in tests/grid).
  const auto around = default_grid().edge_neighbours(o);
  ASSERT_NE(std::find(around.begin(), around.end(), north), around.end());
  ASSERT_NE(std::find(around.begin(), around.end(), p), around.end());
  const std::string store = corner_store({north, o, p});
  const std::string dir = temp_dir() + "/corner";
  const auto r = run_maquette("export tiles3d " + store + " " + dir + " --dem dem --levels " +
                              std::to_string(kLevel) + ".." + std::to_string(kLevel));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto glb = [&](CellId c) {
    return read_glb(dir + "/tiles/" + std::to_string(kLevel) + "/" + c.ToText() + ".glb");
  };
  const Glb gn = glb(north), go = glb(o), gp = glb(p);
  EXPECT_GE(shared_vertices(gn, go), size_t(kTileSize + 1)) << "N/O seam";
  EXPECT_GE(shared_vertices(gn, gp), size_t(kTileSize + 1)) << "N/P seam";
  EXPECT_GE(shared_vertices(go, gp), size_t(kTileSize + 1)) << "O/P seam";
}

TEST(Tiles3d, GltfValidator) {
  const std::string glb = temp_dir() + "/cells.glb";
  const auto& f = tiles3d_fixture();
  ASSERT_EQ(run_maquette("export glb " + f.store_path + " " + glb + " --dem dem --texture rgb " +
                         "--cells " + f.block[0].ToText() + " " + f.block[1].ToText())
                .exit_code,
            0);
  const auto tileset = gltf_validator_passes(tiles3d_export().dir);
  if (!tileset)
    GTEST_SKIP() << "gltf-validator not installed (npm ci in " MAQUETTE_NODE_DIR " failed)";
  EXPECT_TRUE(*tileset);
  EXPECT_EQ(gltf_validator_passes(fs::path(glb).parent_path().string()), true);
}

TEST(Tiles3d, DrcPerCell) {
  const auto& f = tiles3d_fixture();
  const std::string dir = temp_dir() + "/drc";
  const auto r = run_maquette("export drc " + f.store_path + " " + dir + " --dem dem --cells " +
                              f.block[0].ToText() + " " + f.seam[1].ToText());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir + "/" + f.block[0].ToText() + ".drc"));
  EXPECT_TRUE(fs::exists(dir + "/" + f.seam[1].ToText() + ".drc"));
  ASSERT_TRUE(fs::exists(dir + "/frame.json"));
  // Each cell's positions are measured from its offset in the frame.
  const json offsets = json::parse(std::ifstream(dir + "/frame.json"))["offsets"];
  for (CellId c : {f.block[0], f.seam[1]}) EXPECT_EQ(offsets[c.ToText()].size(), 3u) << c.ToText();
}

// Draco is in the mesh plug-in (framework/plugins): loaded by the mesh exports, not at every start.
TEST(Tiles3d, OnlyMeshExportsLoadDraco) {
  const std::string trace = start_trace();
  EXPECT_EQ(trace.find("libdraco"), std::string::npos) << trace;
  EXPECT_EQ(trace.find("libmaquette_mesh.so"), std::string::npos) << trace;

  const auto& f = tiles3d_fixture();
  const auto drc = run_maquette_traced("export drc " + f.store_path + " " + temp_dir() +
                                       "/drc --dem dem --cells " + f.block[0].ToText());
  ASSERT_EQ(drc.exit_code, 0) << drc.err;
  EXPECT_NE(drc.err.find("file=" + plugin_path("libmaquette_mesh.so")), std::string::npos)
      << drc.err;
  EXPECT_NE(drc.err.find("libdraco"), std::string::npos) << drc.err;
}

TEST(Tiles3d, BadInput) {
  const auto& f = tiles3d_fixture();
  auto fails = [&](const std::string& args, const std::string& message) {
    const auto r = run_maquette("export " + args);
    EXPECT_NE(r.exit_code, 0) << args;
    EXPECT_NE(r.err.find(message), std::string::npos) << args << ": " << r.err;
  };
  const std::string out = temp_dir() + "/bad";
  fails("tiles3d " + f.store_path + " " + out + " --dem nope",
        "--dem layer 'nope' is not in the store");
  fails("tiles3d " + f.store_path + " " + out + " --dem rgb", "expected one channel of heights");
  fails("tiles3d " + f.store_path + " " + out + " --dem dem --texture dem", "is not imagery");
  fails("tiles3d " + f.store_path + " " + out + " --dem dem --bbox 100 -40 101 -39", "no tiles");
  fails("tiles3d " + f.store_path + " " + out + " --dem dem --max-mib 0", "would write about");
  fails("tiles3d " + f.store_path + " " + out + " --dem dem --levels 7..8", "--levels");
  fails("tiles3d " + f.store_path + " " + out + " --dem dem --decimation 3", "--decimation");
  fails("tiles3d " + f.store_path + " " + out + " --dem dem --position-bits 24", "8..23");
  fails("glb " + f.store_path + " " + out + ".glb --dem dem --cells ../../etc", "../../etc");
  fs::create_directories(out);
  std::ofstream(out + "/keep.txt") << "x";
  fails("tiles3d " + f.store_path + " " + out + " --dem dem", "not empty");
  EXPECT_EQ(std::distance(fs::directory_iterator(out), fs::directory_iterator()), 1);
  EXPECT_EQ(run_maquette("export tiles3d " + f.store_path + " " + out +
                         " --dem dem --levels 6..6 "
                         "--force")
                .exit_code,
            0);
}

}  // namespace
}  // namespace maquette::test
