// structures.buildings through the real program, as a user runs it: London Soho's 158 OSM
// footprints and a synthetic DEM (a lon/lat GeoTIFF: a slope and waves) ingested, the pipeline
// run by `maquette run`. Every footprint is stored once, in the cell owning its first point, as a
// mesh CGAL finds closed, outward and free of self-intersection after the GLB round trip, of
// volume footprint area x height (within the GLB's 1 mm quantization); no stored DEM pixel whose
// centre lies in a footprint is below its base, and the base is a stored DEM value; 1 and 2
// threads store the same bits; a footprint that gives no valid solid fails the run naming its
// feature, or is left out and named with skip_invalid.
#include <gdal_priv.h>
#include <gtest/gtest.h>
#include <ogr_spatialref.h>

#include <GeographicLib/LocalCartesian.hpp>
#include <cmath>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "content/content_blob.h"
#include "core/grid.h"
#include "core/halo.h"
#include "gltf/mesh_glb.h"
#include "run_cli.h"
#include "store/store.h"
#include "tests/cgal_oracle.h"

namespace maquette {
namespace {

using nlohmann::json;
using structures::cgal_verdict;
using structures::CgalVerdict;
using test::CliResult;
using test::run_maquette;

const std::string kSoho =
    std::string(MAQUETTE_SHARED_DIR) + "/data/buildings/london_soho_buildings_wgs84.geojson";
constexpr double kWest = -0.146, kEast = -0.128, kSouth = 51.507, kNorth = 51.519;
constexpr double kLon0 = -0.137, kLat0 = 51.513;
constexpr double kSourcePixelDeg = 2e-5;     // ~1.4 x 2.2 m
constexpr int kLevel = 14, kTileSize = 256;  // pixels of ~2.2 m

void write_dem(const std::string& path) {
  const int w = int(std::lround((kEast - kWest) / kSourcePixelDeg));
  const int h = int(std::lround((kNorth - kSouth) / kSourcePixelDeg));
  const GeographicLib::LocalCartesian frame(kLat0, kLon0, 0);
  std::vector<float> z;
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) {
      double x = 0, y = 0, up = 0;
      frame.Forward(kNorth - (r + 0.5) * kSourcePixelDeg, kWest + (c + 0.5) * kSourcePixelDeg, 0, x,
                    y, up);
      z.push_back(float(25 + 0.01 * x + 2 * std::sin(x / 40) * std::cos(y / 30)));
    }
  GDALAllRegister();
  const std::unique_ptr<GDALDataset> ds(GetGDALDriverManager()->GetDriverByName("GTiff")->Create(
      path.c_str(), w, h, 1, GDT_Float32, nullptr));
  double transform[6] = {kWest, kSourcePixelDeg, 0, kNorth, 0, -kSourcePixelDeg};
  ds->SetGeoTransform(transform);
  OGRSpatialReference srs;
  srs.importFromEPSG(4326);
  ds->SetSpatialRef(&srs);
  ASSERT_EQ(ds->GetRasterBand(1)->RasterIO(GF_Write, 0, 0, w, h, z.data(), w, h, GDT_Float32, 0, 0),
            CE_None);
}

json soho() {
  std::ifstream in(kSoho);
  return json::parse(in);
}

// A store with the DEM and `footprints`, and the pipeline running structures.buildings on them.
struct Scene {
  std::string dir = test::temp_dir();
  std::string store = dir + "/soho.mqt";

  Scene(const json& footprints, const json& params) {
    write_dem(dir + "/dem.tif");
    std::ofstream(dir + "/footprints.geojson") << footprints.dump();
    const json pipeline = {{"store", store},
                           {"region", {{"bbox", {kWest, kSouth, kEast, kNorth}}}},
                           {"level", kLevel},
                           {"steps",
                            {{{"op", "structures.buildings"},
                              {"params", params},
                              {"inputs", {{"dem", "dem"}, {"footprints", "footprints"}}},
                              {"outputs", {{"mesh", "buildings"}}}}}}};
    std::ofstream(dir + "/pipeline.json") << pipeline.dump(2);
    for (const std::string& args :
         {"ingest " + store + " " + dir + "/dem.tif --layer dem --as dem --vertical-datum " +
              "ellipsoid --level " + std::to_string(kLevel) + " --tile-size " +
              std::to_string(kTileSize),
          "ingest " + store + " " + dir + "/footprints.geojson --layer footprints --as features"}) {
      const CliResult r = run_maquette("-q " + args);
      EXPECT_EQ(r.exit_code, 0) << args << "\n" << r.err;
    }
  }
  CliResult run(const std::string& options = "") const {
    return run_maquette("-q run " + options + " " + dir + "/pipeline.json");
  }
};

Tile<float> tile(const Store& st, CellId cell) {
  const auto info = st.require_layer("dem");
  const auto raw = st.get_tile("dem", cell);
  return raw ? to_tile<float>(*raw, info.nodata ? &*info.nodata : nullptr)
             : Tile<float>(kTileSize, 1, 0, NAN);
}

bool inside(const json& rings, LonLat p) {
  bool in = false;
  for (const json& ring : rings)
    for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
      const double xi = ring[i][0], yi = ring[i][1], xj = ring[j][0], yj = ring[j][1];
      if ((yi > p.lat) != (yj > p.lat) && p.lon < xj + (p.lat - yj) / (yi - yj) * (xi - xj))
        in = !in;
    }
  return in;
}

TEST(BuildingsPipeline, SohoStandsOnTheDemAsValidSolids) {
  const json footprints = soho();
  const Scene scene(footprints, json::object());
  const CliResult r = scene.run();
  ASSERT_EQ(r.exit_code, 0) << r.err;

  const auto st = Store::open(scene.store, Store::Mode::ReadOnly);
  EXPECT_EQ(st->content_stats("buildings").content.objects, 158u);
  // The stored DEM's pixels: centre and height.
  std::vector<std::pair<LonLat, float>> pixels;
  for (const CellId cell : st->tile_cells("dem")) {
    const Tile<float> dem = tile(*st, cell);
    for (int row = 0; row < kTileSize; ++row)
      for (int col = 0; col < kTileSize; ++col)
        if (!std::isnan(dem.at(col, row)))
          pixels.emplace_back(
              pixel_centre(default_grid(), *pixel_source(default_grid(), cell, kTileSize, col, row),
                           kLevel + 8),
              dem.at(col, row));
  }
  std::set<int64_t> features;
  for (const CellId cell : st->content_cells("buildings")) {
    const std::string blob = *st->get_content("buildings", cell);
    const ContentEnvelope envelope = read_content_envelope(blob, "test");
    const MeshContent mesh = decode_mesh_glb(content_payload(blob), envelope.origin, "test");
    for (const MeshObject& o : mesh.objects) {
      const int64_t id = o.provenance.feature_id;
      EXPECT_TRUE(features.insert(id).second) << "feature " << id << " stored twice";
      EXPECT_EQ(o.provenance.tool, "structures.buildings");
      const double height = o.provenance.attributes.at("height_m").get<double>();
      const double base = o.provenance.attributes.at("base_m").get<double>();
      const double area = o.provenance.attributes.at("area_m2").get<double>();
      EXPECT_EQ(height, 10);
      const CgalVerdict v =
          cgal_verdict(std::vector<double>(o.positions.begin(), o.positions.end()), o.indices);
      EXPECT_TRUE(v.polygon_mesh && v.closed && !v.self_intersects && v.outward)
          << "feature " << id;
      EXPECT_NEAR(v.volume, area * height, 1e-3 * area * height) << "feature " << id;
      ASSERT_EQ(o.uvs.size(), 2 * o.positions.size() / 3);

      // The footprint: features are stored in file order with ids from 1.
      const json& rings = footprints["features"][size_t(id - 1)]["geometry"]["coordinates"];
      size_t under = 0;
      bool base_is_a_sample = false;
      for (const auto& [centre, z] : pixels) {
        base_is_a_sample |= z == float(base);
        if (!inside(rings, centre)) continue;
        ++under;
        EXPECT_GE(z, base) << "feature " << id << " floats above the pixel at " << centre.lon
                           << ", " << centre.lat;
      }
      EXPECT_TRUE(base_is_a_sample) << "feature " << id;
      EXPECT_GT(under, 0u) << "feature " << id;
    }
  }
  EXPECT_EQ(features.size(), 158u);
}

TEST(BuildingsPipeline, SameBitsForOneAndTwoThreads) {
  const Scene one(soho(), json::object()), two(soho(), json::object());
  ASSERT_EQ(one.run("-t 1").exit_code, 0);
  ASSERT_EQ(two.run("-t 2").exit_code, 0);
  const auto a = Store::open(one.store, Store::Mode::ReadOnly);
  const auto b = Store::open(two.store, Store::Mode::ReadOnly);
  const std::vector<CellId> cells = a->content_cells("buildings");
  EXPECT_GT(cells.size(), 1u);  // the buildings spread over several cells
  ASSERT_EQ(cells, b->content_cells("buildings"));
  for (const CellId cell : cells)
    EXPECT_EQ(a->get_content("buildings", cell), b->get_content("buildings", cell));
}

TEST(BuildingsPipeline, FootprintGivingNoSolidIsNamedNotWritten) {
  // A courtyard touching the outer wall at a corner: a valid polygon (OGC; the ingest takes it),
  // but its solid would have an edge shared by four faces.
  json footprints = soho();
  json touching = footprints["features"][0];
  touching["geometry"]["coordinates"] = {
      {{-0.1370, 51.5130},
       {-0.1360, 51.5130},
       {-0.1360, 51.5136},
       {-0.1370, 51.5136},
       {-0.1370, 51.5130}},
      {{-0.1370, 51.5130}, {-0.1365, 51.5132}, {-0.1366, 51.5134}, {-0.1370, 51.5130}}};
  footprints["features"].push_back(touching);  // feature 159
  const Scene failing(footprints, json::object());
  const CliResult r = failing.run();
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("inputs.footprints: feature 159: the outer ring's edge from"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("meets hole 1's edge"), std::string::npos) << r.err;

  const Scene skipping(footprints, {{"skip_invalid", true}});
  const CliResult s = skipping.run();
  ASSERT_EQ(s.exit_code, 0) << s.err;
  EXPECT_NE(s.err.find("feature 159: the outer ring's edge"), std::string::npos) << s.err;
  const auto st = Store::open(skipping.store, Store::Mode::ReadOnly);
  EXPECT_EQ(st->content_stats("buildings").content.objects, 158u);
}

}  // namespace
}  // namespace maquette
