// structures.buildings through the real program, as a user runs it: London Soho's 158 OSM
// footprints and a synthetic DEM (a lon/lat GeoTIFF: a slope and waves) ingested, the pipeline
// run by `maquette run`. Every footprint is stored once, in the cell owning its first point, as a
// mesh CGAL finds closed, outward and free of self-intersection after the GLB round trip, of
// volume footprint area x height (within the GLB's 1 mm quantization; every fifth footprint
// tagged with a pitched roof: between its walls' and its top's), roofs, pitched or flat, draping
// the orthophoto (each vertex's texel has the orthophoto's colour there); no stored DEM pixel whose
// centre lies in a footprint is below its base, and the base is a stored DEM value; 1 and 2
// threads store the same bits, another tiling of the same pixels the same buildings; a footprint
// that gives no valid solid fails the run naming its feature, or is left out and named with
// skip_invalid.
#include <gdal_priv.h>
#include <gtest/gtest.h>

#include <GeographicLib/LocalCartesian.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "core/grid.h"
#include "core/halo.h"
#include "egm96_oracle.h"
#include "run_cli.h"
#include "store/store.h"
#include "stored_content.h"
#include "stored_layers.h"
#include "synthetic_raster.h"
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

// The synthetic DEM (m) and orthophoto (RGB) in the local tangent plane at (kLon0, kLat0): x, y
// metres east and north.
double terrain(double x, double y) {
  return 25 + 0.01 * x + 2 * std::sin(x / 40) * std::cos(y / 30);
}
std::array<double, 3> colour(double x, double y) {
  return {128 + 100 * std::sin(x / 50), 128 + 100 * std::cos(y / 50), 128};
}

// A lon/lat GeoTIFF over the scene of `bands` bands of GDAL type `type`, band b of each pixel
// `value(x, y)[b - 1]` at its centre.
template <class Value>
void write_raster(const std::string& path, int bands, const std::string& type, const Value& value) {
  test::RasterSpec spec = test::lonlat_raster(
      kWest, kNorth, int(std::lround((kEast - kWest) / kSourcePixelDeg)), kSourcePixelDeg, type);
  spec.height = int(std::lround((kNorth - kSouth) / kSourcePixelDeg));
  spec.bands = bands;
  const GeographicLib::LocalCartesian frame(kLat0, kLon0, 0);
  test::write_raster(path, spec, [&](int band, double lon, double lat) {
    double x = 0, y = 0, up = 0;
    frame.Forward(lat, lon, 0, x, y, up);
    return value(x, y)[size_t(band - 1)];
  });
}

json soho() {
  std::ifstream in(kSoho);
  return json::parse(in);
}

// A store with the DEM and `footprints`, and the pipeline running structures.buildings on them.
struct Scene {
  std::string dir = test::temp_dir();
  std::string store = dir + "/soho.mqt";

  // Layers at `level` in tiles of `tile_size` pixels.
  // `datum`: the DEM's vertical datum (maquette ingest --vertical-datum).
  Scene(const json& footprints, const json& params, int level = kLevel, int tile_size = kTileSize,
        const std::string& datum = "ellipsoid") {
    write_raster(dir + "/dem.tif", 1, "Float32",
                 [](double x, double y) { return std::array<double, 1>{terrain(x, y)}; });
    write_raster(dir + "/orthophoto.tif", 3, "Byte", colour);
    std::ofstream(dir + "/footprints.geojson") << footprints.dump();
    const json pipeline = {
        {"store", store},
        {"region", {{"bbox", {kWest, kSouth, kEast, kNorth}}}},
        {"level", level},
        {"steps",
         {{{"op", "structures.buildings"},
           {"params", params},
           {"inputs", {{"dem", "dem"}, {"orthophoto", "orthophoto"}, {"footprints", "footprints"}}},
           {"outputs", {{"mesh", "buildings"}}}}}}};
    std::ofstream(dir + "/pipeline.json") << pipeline.dump(2);
    for (const std::string& args :
         {"ingest " + store + " " + dir + "/dem.tif --layer dem --as dem --vertical-datum " +
              datum + " --level " + std::to_string(level) + " --tile-size " +
              std::to_string(tile_size),
          "ingest " + store + " " + dir + "/orthophoto.tif --layer orthophoto --as imagery " +
              "--level " + std::to_string(level) + " --tile-size " + std::to_string(tile_size),
          "ingest " + store + " " + dir + "/footprints.geojson --layer footprints --as features"}) {
      const CliResult r = run_maquette("-q " + args);
      EXPECT_EQ(r.exit_code, 0) << args << "\n" << r.err;
    }
  }
  CliResult run(const std::string& options = "") const {
    return run_maquette("-q run " + options + " " + dir + "/pipeline.json");
  }
};

// An encoded image's pixels (GDAL reads it from memory), band after band.
struct Image {
  int width = 0, height = 0, bands = 0;
  std::vector<uint8_t> pixels;
  explicit Image(const std::string& bytes) {
    const std::string path = "/vsimem/buildings_texture";
    VSIFCloseL(VSIFileFromMemBuffer(path.c_str(),
                                    reinterpret_cast<GByte*>(const_cast<char*>(bytes.data())),
                                    vsi_l_offset(bytes.size()), FALSE));
    const std::unique_ptr<GDALDataset> ds(GDALDataset::Open(path.c_str(), GDAL_OF_RASTER));
    EXPECT_TRUE(ds);
    if (ds) {
      width = ds->GetRasterXSize(), height = ds->GetRasterYSize(), bands = ds->GetRasterCount();
      pixels.resize(size_t(width) * size_t(height) * size_t(bands));
      EXPECT_EQ(ds->RasterIO(GF_Read, 0, 0, width, height, pixels.data(), width, height, GDT_Byte,
                             bands, nullptr, 0, 0, 0, nullptr),
                CE_None);
    }
    VSIUnlink(path.c_str());
  }
  // The nearest pixel's band `b` at texture coordinates (u, v), glTF's: v down from the top.
  double at(float u, float v, int b) const {
    const int c = std::clamp(int(u * float(width)), 0, width - 1);
    const int r = std::clamp(int(v * float(height)), 0, height - 1);
    return pixels[(size_t(b) * size_t(height) + size_t(r)) * size_t(width) + size_t(c)];
  }
};

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

// Every test reads the Soho footprints of ../shared/data: skipped without them.
class BuildingsPipeline : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!std::filesystem::exists(kSoho)) GTEST_SKIP() << kSoho << " is absent (../shared/data)";
  }
};

TEST_F(BuildingsPipeline, SohoStandsOnTheDemAsValidSolids) {
  // Every fifth footprint with a pitched roof 3 m high on its 10 m walls (default), the shapes
  // in turn.
  json footprints = soho();
  const std::array<std::string, 4> kShapes = {"gabled", "hipped", "pyramidal", "skillion"};
  for (size_t i = 0; i < footprints["features"].size(); i += 5)
    footprints["features"][i]["properties"].update(
        {{"roof:shape", kShapes[i / 5 % 4]}, {"roof:height", 3}});
  const Scene scene(footprints, json::object());
  const CliResult r = scene.run();
  ASSERT_EQ(r.exit_code, 0) << r.err;

  const auto st = Store::open(scene.store, Store::Mode::ReadOnly);
  EXPECT_EQ(st->content_stats("buildings").content.objects, 158u);
  // The stored DEM's pixels: centre and height.
  std::vector<std::pair<LonLat, float>> pixels;
  for (const CellId cell : st->tile_cells("dem")) {
    const Tile<float> dem = test::float_tile(*st, "dem", cell);
    for (int row = 0; row < kTileSize; ++row)
      for (int col = 0; col < kTileSize; ++col)
        if (!std::isnan(dem.at(col, row)))
          pixels.emplace_back(
              pixel_centre(default_grid(), *pixel_source(default_grid(), cell, kTileSize, col, row),
                           kLevel + 8),
              dem.at(col, row));
  }
  std::set<int64_t> features;
  const GeographicLib::LocalCartesian local(kLat0, kLon0, 0);
  for (const auto& [origin, mesh] : test::stored_meshes(*st, "buildings")) {
    // The roofs drape the cell's orthophoto tile with its halo: 256 + 2 x 128 pixels, JPEG.
    ASSERT_EQ(mesh.materials.size(), 1u);
    EXPECT_EQ(mesh.materials[0].image_mime, "image/jpeg");
    const Image image(mesh.materials[0].image);
    EXPECT_EQ(image.width, 512);
    const GeographicLib::LocalCartesian frame(origin.lat, origin.lon, origin.height);
    for (const MeshObject& o : mesh.objects) {
      const int64_t id = o.provenance.feature_id;
      EXPECT_TRUE(features.insert(id).second) << "feature " << id << " stored twice";
      EXPECT_EQ(o.provenance.tool, "structures.buildings");
      const double height = o.provenance.attributes.at("height_m").get<double>();
      const double base = o.provenance.attributes.at("base_m").get<double>();
      const double area = o.provenance.attributes.at("area_m2").get<double>();
      const CgalVerdict v =
          cgal_verdict(std::vector<double>(o.positions.begin(), o.positions.end()), o.indices);
      EXPECT_TRUE(v.polygon_mesh && v.closed && !v.self_intersects && v.outward)
          << "feature " << id;
      // The top above the base: the highest vertex's height (the tangent plane rises d^2 / 2R
      // above the ellipsoid d from the anchor: 3.8 mm at Soho's largest blocks, ~220 m; the
      // GLB's quantization 1 mm: within 5 mm).
      double top = -INFINITY;
      for (size_t k = 0; k < o.positions.size(); k += 3) {
        double lat = 0, lon = 0, h = 0;
        frame.Reverse(o.positions[k], o.positions[k + 1], o.positions[k + 2], lat, lon, h);
        top = std::max(top, h - base);
      }
      if ((id - 1) % 5 == 0) {
        // Pitched: 10 m walls, the roof's top 3 m above them, a volume between the walls' and
        // the top's prisms.
        EXPECT_EQ(o.provenance.attributes.at("roof_shape"), kShapes[size_t(id - 1) / 5 % 4]);
        EXPECT_EQ(height, 13);
        EXPECT_GT(v.volume, area * 10 * (1 + 1e-3)) << "feature " << id;
        EXPECT_LT(v.volume, area * 13 * (1 - 1e-3)) << "feature " << id;
      } else {
        EXPECT_EQ(o.provenance.attributes.at("roof_shape"), "flat");
        EXPECT_EQ(height, 10);
        EXPECT_NEAR(v.volume, area * height, 1e-3 * area * height) << "feature " << id;
      }
      EXPECT_NEAR(top, height, 5e-3) << "feature " << id;
      // Each vertex's texel has the orthophoto's colour at the vertex (within the JPEG's loss
      // and a pixel's change of colour: 2 levels a metre, pixels of ~2.2 m).
      ASSERT_EQ(o.uvs.size(), 2 * o.positions.size() / 3);
      EXPECT_EQ(o.material, 0);
      for (size_t k = 0; k < o.positions.size() / 3; ++k) {
        double lat = 0, lon = 0, h = 0, x = 0, y = 0, z = 0;
        frame.Reverse(o.positions[3 * k], o.positions[3 * k + 1], o.positions[3 * k + 2], lat, lon,
                      h);
        local.Forward(lat, lon, 0, x, y, z);
        for (int b = 0; b < 3; ++b)
          EXPECT_NEAR(image.at(o.uvs[2 * k], o.uvs[2 * k + 1], b), colour(x, y)[size_t(b)], 12)
              << "feature " << id << " vertex " << k << " band " << b;
      }

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

// On a DEM of EGM96 heights (SRTM's datum, the ingest's default) each building stands at its base
// plus the geoid height there, as the exported terrain does: its lowest vertex's height above the
// ellipsoid is base_m + N, N from PROJ (EGM96 height -> WGS 84 ellipsoidal; ~46 m in London).
TEST_F(BuildingsPipeline, OnAnEgm96DemBuildingsStandOnTheEllipsoidalTerrain) {
  const Scene scene(soho(), json::object(), kLevel, kTileSize, "egm96");
  const CliResult r = scene.run();
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const test::Egm96ToEllipsoid to_ellipsoid;
  const auto st = Store::open(scene.store, Store::Mode::ReadOnly);
  int checked = 0;
  for (const auto& [origin, mesh] : test::stored_meshes(*st, "buildings")) {
    const GeographicLib::LocalCartesian frame(origin.lat, origin.lon, origin.height);
    for (const MeshObject& o : mesh.objects) {
      // The lowest vertex: the base.
      double lat = 0, lon = 0, h = INFINITY;
      for (size_t k = 0; k < o.positions.size(); k += 3) {
        double vlat = 0, vlon = 0, vh = 0;
        frame.Reverse(o.positions[k], o.positions[k + 1], o.positions[k + 2], vlat, vlon, vh);
        if (vh < h) std::tie(lat, lon, h) = std::tuple(vlat, vlon, vh);
      }
      const double z = to_ellipsoid(lon, lat, o.provenance.attributes.at("base_m").get<double>());
      EXPECT_GT(z - o.provenance.attributes.at("base_m").get<double>(), 40);
      EXPECT_NEAR(h, z, 0.01) << "feature " << o.provenance.feature_id;
      ++checked;
    }
  }
  EXPECT_EQ(checked, 158);
}

TEST_F(BuildingsPipeline, SameBitsForOneAndTwoThreads) {
  const Scene one(soho(), json::object()), two(soho(), json::object());
  ASSERT_EQ(one.run("-t 1").exit_code, 0);
  ASSERT_EQ(two.run("-t 2").exit_code, 0);
  const auto a = Store::open(one.store, Store::Mode::ReadOnly);
  const auto b = Store::open(two.store, Store::Mode::ReadOnly);
  // The buildings spread over several cells.
  EXPECT_GT(test::expect_same_content(*a, *b, "buildings"), 1u);
}

// Each building's provenance attributes (height, base, area) by feature id.
std::map<int64_t, json> buildings(const std::string& store) {
  const auto st = Store::open(store, Store::Mode::ReadOnly);
  std::map<int64_t, json> out;
  for (const auto& stored : test::stored_meshes(*st, "buildings"))
    for (const MeshObject& o : stored.mesh.objects)
      out[o.provenance.feature_id] = o.provenance.attributes;
  return out;
}

// The same pixels in cells of half the side (level 15, tiles of 128): other owning cells and
// frames, the same buildings (their base from the same pixels, their area in the same plane).
TEST_F(BuildingsPipeline, SameBuildingsForAnotherTiling) {
  const Scene coarse(soho(), json::object()),
      fine(soho(), json::object(), kLevel + 1, kTileSize / 2);
  ASSERT_EQ(coarse.run().exit_code, 0);
  ASSERT_EQ(fine.run().exit_code, 0);
  EXPECT_LT(Store::open(coarse.store, Store::Mode::ReadOnly)->content_cells("buildings").size(),
            Store::open(fine.store, Store::Mode::ReadOnly)->content_cells("buildings").size());
  const std::map<int64_t, json> a = buildings(coarse.store), b = buildings(fine.store);
  ASSERT_EQ(a.size(), 158u);
  ASSERT_EQ(b.size(), 158u);
  // The ingest gives some of the same pixels in the two tilings up to 2 float ulps apart (3.8e-6
  // m at ~25 m, seen): measured here, the bases are compared within it.
  const auto pixels = [](const std::string& store, int tile_size) {
    const auto st = Store::open(store, Store::Mode::ReadOnly);
    std::map<std::tuple<int, int64_t, int64_t>, float> out;
    for (const CellId cell : st->tile_cells("dem")) {
      const Tile<float> dem = to_tile<float>(*st->get_tile("dem", cell), nullptr);
      for (int r = 0; r < tile_size; ++r)
        for (int c = 0; c < tile_size; ++c)
          out[{cell.face(), int64_t(cell.col()) * tile_size + c,
               int64_t(cell.row()) * tile_size + r}] = dem.at(c, r);
    }
    return out;
  };
  const auto coarse_pixels = pixels(coarse.store, kTileSize);
  const auto fine_pixels = pixels(fine.store, kTileSize / 2);
  double dem_difference = 0;
  for (const auto& [at, z] : coarse_pixels)
    if (const auto it = fine_pixels.find(at); it != fine_pixels.end() && !std::isnan(z))
      dem_difference = std::max(dem_difference, double(std::abs(z - it->second)));
  EXPECT_LE(dem_difference, 4e-6);
  for (const auto& [id, attributes] : a) {
    const json& other = b.at(id);
    EXPECT_EQ(attributes.at("height_m"), other.at("height_m")) << "feature " << id;
    EXPECT_NEAR(attributes.at("base_m").get<double>(), other.at("base_m").get<double>(),
                dem_difference)
        << "feature " << id;
    // Tangent planes at bases 4e-6 m apart: areas 6e-13 relative apart (1.6e-7 per metre).
    EXPECT_NEAR(attributes.at("area_m2").get<double>(), other.at("area_m2").get<double>(),
                1e-9 * attributes.at("area_m2").get<double>())
        << "feature " << id;
  }
}

TEST_F(BuildingsPipeline, FootprintGivingNoSolidIsNamedNotWritten) {
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
