// Vertical datums: recorded at ingest (option, source CRS, default), shown by `info`, inherited
// by terrain.fill_voids, and converted to ellipsoidal heights by the 3D exports. Oracle: PROJ's
// cs2cs run as a separate process with the EGM96 grid Debian's proj-data ships (egm96_15.gtx),
// on the real SRTM tiles of Mount Rainier and Mount Everest.
#include <gtest/gtest.h>

#include <GeographicLib/LocalCartesian.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "glb_reader.h"
#include "run_cli.h"

namespace maquette::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const std::string kSrtm = std::string(MAQUETTE_SHARED_DIR) + "/data/srtm3/";

struct Vertex {
  double lon, lat, h;  // WGS84, height above the ellipsoid
};

// The vertices of a plain GLB `maquette export glb --no-draco` wrote, as geodetic points.
std::vector<Vertex> glb_vertices(const std::string& path) {
  const Glb glb = read_glb(path);
  const json& origin = glb.json["asset"]["extras"]["maquette_frame"]["origin"];
  const GeographicLib::LocalCartesian enu(origin["lat"].get<double>(), origin["lon"].get<double>(),
                                          0);
  std::vector<Vertex> out;
  for (size_t n = 0; n < glb.json["nodes"].size(); ++n) {
    const auto t = glb.translation(int(n));  // positions are measured from it
    for (const auto& prim :
         glb.json["meshes"][glb.json["nodes"][n]["mesh"].get<int>()]["primitives"]) {
      const std::vector<float> p = glb.floats(prim["attributes"]["POSITION"].get<int>());
      for (size_t i = 0; i + 2 < p.size(); i += 3) {
        Vertex v{};
        // x east, y up, z south
        enu.Reverse(t[0] + p[i], -(t[2] + p[i + 2]), t[1] + p[i + 1], v.lat, v.lon, v.h);
        out.push_back(v);
      }
    }
  }
  return out;
}

// EGM96 geoid heights N at `points` from PROJ's cs2cs (EGM96 height -> WGS 84 ellipsoidal).
std::vector<double> cs2cs_undulations(const std::vector<Vertex>& points) {
  const std::string in = temp_dir() + "/points.txt";
  {
    std::ofstream f(in);
    f.precision(12);
    for (const Vertex& v : points) f << v.lat << " " << v.lon << " 0\n";  // EPSG:4326: lat, lon
  }
  std::istringstream lines(shell_output("cs2cs -f %.6f EPSG:4326+5773 EPSG:4979 < " + in));
  std::vector<double> n;
  double lat, lon, h;
  while (lines >> lat >> lon >> h) n.push_back(h);
  return n;
}

// The same cells exported from a DEM ingested as EGM96 heights and as ellipsoidal heights: the
// vertices differ by the geoid height N of cs2cs, within a few centimetres.
void expect_geoid_shift(const std::string& tile, double lon, double lat, double n_lo, double n_hi) {
  if (!fs::exists(kSrtm + tile)) GTEST_SKIP() << kSrtm + tile << " absent";
  const std::string dir = temp_dir();
  const std::string bbox = " --bbox " + std::to_string(lon - 0.02) + " " +
                           std::to_string(lat - 0.02) + " " + std::to_string(lon + 0.02) + " " +
                           std::to_string(lat + 0.02);
  for (const char* datum : {"egm96", "ellipsoid"}) {
    const auto r =
        run_maquette("ingest " + dir + "/s.mqt --as dem --layer " + datum + " --vertical-datum " +
                     datum + " --level 10" + bbox + " " + kSrtm + tile);
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  const std::string cell = run_maquette("cells from-point " + std::to_string(lon) + " " +
                                        std::to_string(lat) + " --level 10")
                               .out;
  std::vector<Vertex> v[2];
  int k = 0;
  for (const char* datum : {"egm96", "ellipsoid"}) {
    const std::string glb = dir + "/" + datum + ".glb";
    // Plain float positions on a fine lattice (23 bits: under a millimetre over the cell).
    const auto r = run_maquette("export glb " + dir + "/s.mqt " + glb +
                                " --no-draco --position-bits 23 --dem " + datum + " --cells " +
                                cell.substr(0, cell.find('\n')));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    v[k++] = glb_vertices(glb);
  }
  ASSERT_EQ(v[0].size(), v[1].size());
  ASSERT_GT(v[0].size(), 1000u);
  const std::vector<double> n = cs2cs_undulations(v[1]);
  ASSERT_EQ(n.size(), v[1].size()) << "cs2cs failed";
  double worst = 0;
  for (size_t i = 0; i < n.size(); ++i) {
    EXPECT_NEAR(v[0][i].lon, v[1][i].lon, 1e-7);
    EXPECT_NEAR(v[0][i].lat, v[1][i].lat, 1e-7);
    EXPECT_GT(n[i], n_lo);
    EXPECT_LT(n[i], n_hi);
    worst = std::max(worst, std::abs(v[0][i].h - (v[1][i].h + n[i])));
  }
  EXPECT_LT(worst, 0.03) << "EGM96 export height - (ellipsoidal export height + N)";
}

TEST(VerticalDatum, RainierGlbHeightsAreOrthometricPlusGeoid) {
  expect_geoid_shift("mt_rainier_90m.tif", -121.7603, 46.8523, -20, -18);
}

TEST(VerticalDatum, EverestGlbHeightsAreOrthometricPlusGeoid) {
  expect_geoid_shift("mt_everest_90m.tif", 86.9250, 27.9881, -31, -27);
}

json info_layer(const std::string& store, const std::string& layer) {
  const auto r = run_maquette("info --json " + store);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  const json report = json::parse(r.out);
  for (const json& l : report["layers"])
    if (l["name"] == layer) return l;
  ADD_FAILURE() << "no layer " << layer;
  return {};
}

// A small DEM GeoTIFF `out` with `srs` (gdal_translate -a_srs) cut from the Rainier tile.
std::string rainier_with_crs(const std::string& out, const std::string& srs) {
  shell_output("gdal_translate -q -srcwin 600 600 40 40 -a_srs " + srs + " " + kSrtm +
               "mt_rainier_90m.tif " + out);
  return out;
}

TEST(VerticalDatum, RecordedFromOptionSourceOrDefault) {
  if (!fs::exists(kSrtm + "mt_rainier_90m.tif")) GTEST_SKIP() << kSrtm << " absent";
  const std::string dir = temp_dir(), store = dir + "/s.mqt";
  const std::string plain = rainier_with_crs(dir + "/dem.tif", "EPSG:4326");
  ASSERT_EQ(run_maquette("ingest " + store + " --as dem --layer d " + plain).exit_code, 0);
  const json d = info_layer(store, "d");
  EXPECT_EQ(d["provenance"]["vertical_datum"]["crs"], "EPSG:5773");
  EXPECT_NE(d["vertical_datum"].get<std::string>().find("default for --as dem"), std::string::npos);
  const auto text = run_maquette("info " + store);
  EXPECT_NE(text.out.find("heights above EGM96 height (EPSG:5773)"), std::string::npos) << text.out;

  ASSERT_EQ(
      run_maquette("ingest " + store + " --as dem --layer v --vertical-datum EPSG:5703 " + plain)
          .exit_code,
      0);
  EXPECT_EQ(info_layer(store, "v")["provenance"]["vertical_datum"]["name"], "NAVD88 height");

  const std::string compound = rainier_with_crs(dir + "/compound.tif", "EPSG:4326+3855");
  ASSERT_EQ(run_maquette("ingest " + store + " --as dem --layer c " + compound).exit_code, 0);
  const json c = info_layer(store, "c")["provenance"]["vertical_datum"];
  EXPECT_EQ(c["crs"], "EPSG:3855");
  EXPECT_NE(c["from"].get<std::string>().find("the CRS of"), std::string::npos);

  // Imagery has no heights; an unknown datum is named.
  auto r =
      run_maquette("ingest " + store + " --as imagery --layer i --vertical-datum egm96 " + plain);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("--vertical-datum is for height layers (--as dem)"), std::string::npos)
      << r.err;
  r = run_maquette("ingest " + store + " --as dem --layer b --vertical-datum notadatum " + plain);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("--vertical-datum 'notadatum': not egm96, egm2008, ellipsoid or a vertical"),
            std::string::npos)
      << r.err;
  r = run_maquette("ingest " + store + " --as dem --layer b --vertical-datum EPSG:32610 " + plain);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("UTM zone 10N, not a vertical CRS"), std::string::npos) << r.err;
}

// No grid for the datum: the export fails naming the grid it looked for, never leaving heights
// unconverted. EGM2008's grid is not in Debian's proj-data; EGM96's is hidden by pointing PROJ at
// a directory holding only its database.
TEST(VerticalDatum, MissingGeoidGridIsAnError) {
  if (!fs::exists(kSrtm + "mt_rainier_90m.tif")) GTEST_SKIP() << kSrtm << " absent";
  const std::string dir = temp_dir(), store = dir + "/s.mqt";
  const std::string dem = rainier_with_crs(dir + "/dem.tif", "EPSG:4326");
  ASSERT_EQ(run_maquette("ingest " + store + " --as dem --layer e8 --vertical-datum egm2008 " + dem)
                .exit_code,
            0);
  ASSERT_EQ(run_maquette("ingest " + store + " --as dem --layer e9 " + dem).exit_code, 0);
  const std::string cell = run_maquette("cells from-point -121.483 46.483 --level 9").out;
  const std::string cells = " --cells " + cell.substr(0, cell.find('\n'));
  auto r = run_maquette("export glb " + store + " " + dir + "/a.glb --dem e8" + cells);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("us_nga_egm08_25.tif"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir + "/a.glb"));

  const std::string proj_data = dir + "/proj";
  fs::create_directories(proj_data);
  std::istringstream paths(shell_output("projinfo --searchpaths"));
  for (std::string path; std::getline(paths, path);)
    if (fs::exists(path + "/proj.db")) {
      fs::copy_file(path + "/proj.db", proj_data + "/proj.db");
      break;
    }
  ASSERT_TRUE(fs::exists(proj_data + "/proj.db")) << "PROJ's database not found";
  r = run_maquette("export glb " + store + " " + dir + "/b.glb --dem e9" + cells,
                   "PROJ_DATA=" + proj_data + " PROJ_LIB=" + proj_data);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("us_nga_egm96_15.tif"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(proj_data), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir + "/b.glb"));
  // With the grid: the same export works.
  r = run_maquette("export glb " + store + " " + dir + "/b.glb --dem e9" + cells);
  EXPECT_EQ(r.exit_code, 0) << r.err;
}

// A pipeline's ingest takes "vertical_datum"; terrain.fill_voids' filled DEM keeps it.
TEST(VerticalDatum, PipelineIngestAndFilledDemKeepTheDatum) {
  if (!fs::exists(kSrtm + "mt_rainier_90m.tif")) GTEST_SKIP() << kSrtm << " absent";
  const std::string dir = temp_dir();
  const std::string dem = rainier_with_crs(dir + "/dem.tif", "EPSG:4326");
  std::ofstream(dir + "/p.json") << json{
      {"store", "p.mqt"},
      {"region", {{"bbox", {-121.75, 46.3, -121.3, 46.5}}}},
      {"level", 9},
      {"tile_size", 256},
      {"steps",
       {{{"op", "ingest"},
         {"outputs", {{"layer", "dem"}}},
         {"params", {{"sources", {dem}}, {"as", "dem"}, {"vertical_datum", "ellipsoid"}}}},
        {{"op", "terrain.fill_voids"},
         {"inputs", {{"dem", "dem"}}},
         {"outputs", {{"dem", "filled"}}},
         {"params", {{"pyramid", "dem"}}}}}}};
  const auto r = run_maquette("run " + dir + "/p.json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(info_layer(dir + "/p.mqt", "dem")["provenance"]["vertical_datum"]["crs"], "ellipsoid");
  EXPECT_EQ(info_layer(dir + "/p.mqt", "filled")["provenance"]["vertical_datum"]["crs"],
            "ellipsoid");
}

}  // namespace
}  // namespace maquette::test
