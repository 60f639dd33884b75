// structures.bridge through the real program, as a user runs it: a V valley z = 100 + 0.2 |x|
// (x: metres east of the valley's floor in the local tangent plane, GeographicLib) written as a
// lon/lat GeoTIFF and ingested as a DEM, bridge strokes (tool "bridge", a MultiLineString of the
// two edges) ingested as features, the pipeline run by `maquette run`. A straight deck 10 m wide
// from x = -150 m to x = 250 m: its ends' tops are the valley's analytic heights there (130 and
// 150 m) within 1 cm, its top along the edges has the analytic slope 0.05, its floor lies the
// thickness below (on a DEM of EGM96 heights, the ends at the terrain taken to the ellipsoid by
// PROJ); CGAL finds it closed, outward, free of self-intersection after the GLB round
// trip, of volume width x length x thickness; stored once; the mask's pixels are GDAL's
// rasterization of the deck's outline (GDALRasterizeGeometries in the rHEALPix plane); the same
// bits for 1 and 2 threads and the same mask pixels for two tilings, and without the mesh mapped;
// the same deck across the seam of two faces of the grid, its ends on both faces' DEM; bad
// strokes fail naming the feature and field.
#include <gdal_priv.h>
#include <gtest/gtest.h>
#include <ogr_spatialref.h>

#include <GeographicLib/LocalCartesian.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "burn_deck.h"
#include "content/content_blob.h"
#include "core/grid.h"
#include "egm96_oracle.h"
#include "gltf/mesh_glb.h"
#include "run_cli.h"
#include "store/store.h"
#include "synthetic_raster.h"
#include "tests/cgal_oracle.h"

namespace maquette {
namespace {

using nlohmann::json;
using structures::cgal_verdict;
using structures::CgalVerdict;
using test::CliResult;
using test::run_maquette;

constexpr double kHalfLon = 0.006, kHalfLat = 0.004;      // the DEM: ~+-460 m x +-440 m
constexpr double kRegionLon = 0.004, kRegionLat = 0.002;  // the region: ~+-310 m x +-220 m
constexpr double kSourcePixelDeg = 2e-5;                  // ~1.5 x 2.2 m
constexpr int kLevel = 14, kTileSize = 256;               // pixels of ~2.2 m
constexpr double kWest = -150, kEast = 250, kHalfWidth = 5, kThickness = 2;

double terrain(double x) { return 100 + 0.2 * std::abs(x); }

// Where the valley's floor is (it runs north-south), and the tangent plane there.
struct Site {
  double lon0, lat0;
  GeographicLib::LocalCartesian local{lat0, lon0, 0};

  std::array<double, 2> lonlat(double x, double y) const {
    double lat = 0, lon = 0, h = 0;
    local.Reverse(x, y, 0, lat, lon, h);
    return {lon, lat};
  }
};

// In the Alps, on face Q of the grid.
const Site& alps() {
  static const Site site{7.5, 46.0};
  return site;
}

// On the meridian 0, the seam between faces P (west) and Q (east): the deck's west ends are on P,
// its east ends on Q.
const Site& seam() {
  static const Site site{0.0, 20.0};
  return site;
}

std::array<double, 2> lonlat(double x, double y) { return alps().lonlat(x, y); }

// With `hole`, nodata (-9999) within 20 m of the bridge's east end.
void write_dem(const std::string& path, bool hole, const Site& site) {
  test::RasterSpec spec;
  spec.width = int(std::lround(2 * kHalfLon / kSourcePixelDeg));
  spec.height = int(std::lround(2 * kHalfLat / kSourcePixelDeg));
  spec.geotransform = {site.lon0 - kHalfLon, kSourcePixelDeg, 0, site.lat0 + kHalfLat, 0,
                       -kSourcePixelDeg};
  spec.crs = "EPSG:4326";
  spec.nodata = -9999;
  test::write_raster(path, spec, [&](int, double lon, double lat) {
    double x = 0, y = 0, up = 0;
    site.local.Forward(lat, lon, 0, x, y, up);
    return hole && std::hypot(x - kEast, y) < 20 ? -9999.0 : terrain(x);
  });
}

// An edge at y metres north of the valley's centre, from x = kWest to kEast every 100 m.
json edge(double y, const Site& site = alps()) {
  json line = json::array();
  for (double x = kWest; x <= kEast; x += 100) line.push_back(site.lonlat(x, y));
  return line;
}

json bridge_feature(const json& lines, const json& properties) {
  json props = {{"tool", "bridge"}};
  props.update(properties);
  return {{"type", "Feature"},
          {"properties", props},
          {"geometry", {{"type", "MultiLineString"}, {"coordinates", lines}}}};
}

json collection(const json& feature) {
  json out = {{"type", "FeatureCollection"}, {"features", json::array()}};
  out["features"].push_back(feature);
  return out;
}

json straight_bridge(const Site& site = alps()) {
  return collection(bridge_feature({edge(-kHalfWidth, site), edge(kHalfWidth, site)},
                                   {{"thickness_m", kThickness}}));
}

// A store with the valley's DEM and `strokes`, and the pipeline running structures.bridge.
struct Valley {
  std::string dir = test::temp_dir();
  std::string store = dir + "/valley.mqt";

  // `hole`: write_dem's; `datum`: the DEM's vertical datum (maquette ingest --vertical-datum).
  // `outputs`: the step's output ports mapped to layers.
  Valley(const json& strokes, int level = kLevel, int tile_size = kTileSize, bool hole = false,
         const std::string& datum = "ellipsoid",
         const json& outputs = {{"mesh", "bridge"}, {"mask", "bridge_mask"}},
         const Site& site = alps()) {
    write_dem(dir + "/dem.tif", hole, site);
    std::ofstream(dir + "/strokes.geojson") << strokes.dump();
    const json pipeline = {{"store", store},
                           {"region",
                            {{"bbox",
                              {site.lon0 - kRegionLon, site.lat0 - kRegionLat,
                               site.lon0 + kRegionLon, site.lat0 + kRegionLat}}}},
                           {"level", level},
                           {"steps",
                            {{{"op", "structures.bridge"},
                              {"inputs", {{"dem", "dem"}, {"strokes", "strokes"}}},
                              {"outputs", outputs}}}}};
    std::ofstream(dir + "/pipeline.json") << pipeline.dump(2);
    for (const std::string& args :
         {"ingest " + store + " " + dir + "/dem.tif --layer dem --as dem --vertical-datum " +
              datum + " --resampling bilinear --level " + std::to_string(level) + " --tile-size " +
              std::to_string(tile_size),
          "ingest " + store + " " + dir + "/strokes.geojson --layer strokes --as features"}) {
      const CliResult r = run_maquette("-q " + args);
      EXPECT_EQ(r.exit_code, 0) << args << "\n" << r.err;
    }
  }
  CliResult run(const std::string& options = "") const {
    return run_maquette("-q run " + options + " " + dir + "/pipeline.json");
  }
};

// The decoded meshes of the bridge layer, each vertex as (x, y) in the valley's local plane and
// its height above the ellipsoid.
struct Deck {
  MeshObject object;
  std::vector<std::array<double, 3>> local;  // x, y (at height 0), ellipsoidal height
};

std::vector<Deck> decks(const Store& st, const Site& site = alps()) {
  std::vector<Deck> out;
  for (const CellId cell : st.content_cells("bridge")) {
    const std::string blob = *st.get_content("bridge", cell);
    const ContentEnvelope envelope = read_content_envelope(blob, "test");
    const GeographicLib::LocalCartesian frame(envelope.origin.lat, envelope.origin.lon,
                                              envelope.origin.height);
    for (MeshObject& o : decode_mesh_glb(content_payload(blob), envelope.origin, "test").objects) {
      Deck& d = out.emplace_back();
      for (size_t k = 0; k < o.positions.size(); k += 3) {
        double lat = 0, lon = 0, h = 0, x = 0, y = 0, z = 0;
        frame.Reverse(o.positions[k], o.positions[k + 1], o.positions[k + 2], lat, lon, h);
        site.local.Forward(lat, lon, 0, x, y, z);
        d.local.push_back({x, y, h});
      }
      d.object = std::move(o);
    }
  }
  return out;
}

// The straight deck's shape: its corners on the slant from terrain(kWest) to terrain(kEast) and
// the thickness below, its ends on the terrain, valid and of its volume by CGAL.
void expect_straight_deck(const Deck& deck) {
  EXPECT_EQ(deck.object.provenance.feature_id, 1);
  EXPECT_EQ(deck.object.provenance.tool, "structures.bridge");

  // Every edge point has two corners: the top on the line from terrain(kWest) to
  // terrain(kEast), and the floor kThickness below (the GLB quantizes positions to 1 mm; each
  // corner is one vertex per face meeting there, for flat normals: counted once).
  const double slope = (terrain(kEast) - terrain(kWest)) / (kEast - kWest);
  EXPECT_NEAR(slope, 0.05, 1e-12);
  std::set<std::array<long, 3>> corners;
  std::vector<std::array<double, 3>> unique;
  for (const auto& [x, y, h] : deck.local)
    if (corners.insert({std::lround(x * 100), std::lround(y * 100), std::lround(h * 100)}).second)
      unique.push_back({x, y, h});
  size_t tops = 0, floors = 0;
  for (const auto& [x, y, h] : unique) {
    ASSERT_NEAR(std::abs(y), kHalfWidth, 0.01);
    const double top = terrain(kWest) + slope * (x - kWest);
    if (std::abs(h - top) < 0.01)
      ++tops;
    else if (std::abs(h - (top - kThickness)) < 0.01)
      ++floors;
    else
      ADD_FAILURE() << "vertex at x " << x << ", y " << y << ": height " << h
                    << " neither on the deck's top " << top << " nor its floor";
  }
  EXPECT_EQ(tops, 10u);
  EXPECT_EQ(floors, 10u);
  // The ends: the tops at the edges' ends are the DEM's heights there within 1 cm.
  for (const double end_x : {kWest, kEast})
    for (const double end_y : {-kHalfWidth, kHalfWidth}) {
      int at_end = 0;
      for (const auto& [x, y, h] : unique)
        if (std::hypot(x - end_x, y - end_y) < 0.01 && std::abs(h - terrain(end_x)) < 0.01)
          ++at_end;
      EXPECT_EQ(at_end, 1) << "end at x " << end_x << ", y " << end_y;
    }
  const json& ends = deck.object.provenance.attributes.at("end_heights_m");
  EXPECT_NEAR(ends[0].get<double>(), terrain(kWest), 1e-3);
  EXPECT_NEAR(ends[1].get<double>(), terrain(kEast), 1e-3);

  // CGAL: a valid solid of volume width x length x thickness, within the GLB's 1 mm quantization
  // (measured: 9e-5). The deck's points, given at height 0, stand 130-150 m up, where their
  // outline is about (1 + 140 m / R)^2 = 1 + 4.4e-5 larger: the volume the operator measured
  // (provenance) is that within 1e-5 (measured: 4.5e-5 over width x length x thickness).
  const CgalVerdict v =
      cgal_verdict(std::vector<double>(deck.object.positions.begin(), deck.object.positions.end()),
                   deck.object.indices);
  EXPECT_TRUE(v.polygon_mesh);
  EXPECT_TRUE(v.closed);
  EXPECT_TRUE(v.outward);
  EXPECT_FALSE(v.self_intersects);
  const double volume = 2 * kHalfWidth * (kEast - kWest) * kThickness;
  EXPECT_NEAR(v.volume, volume, 2e-4 * volume);
  const double raised = (1 + 140 / 6.38e6) * (1 + 140 / 6.38e6);
  EXPECT_NEAR(deck.object.provenance.attributes.at("volume_m3").get<double>(), volume * raised,
              1e-5 * volume);
}

TEST(BridgePipeline, StraightDeckAcrossAValley) {
  const Valley valley(straight_bridge());
  const CliResult r = valley.run();
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto st = Store::open(valley.store, Store::Mode::ReadOnly);
  EXPECT_EQ(st->content_stats("bridge").content.objects, 1u);
  const std::vector<Deck> found = decks(*st);
  ASSERT_EQ(found.size(), 1u);
  expect_straight_deck(found[0]);
}

// On a DEM of EGM96 heights (SRTM's datum, the ingest's default) the deck's ends stand on the
// terrain taken to the ellipsoid, as the exported terrain is: each end's top is terrain + N within
// 1 cm, N from PROJ (EGM96 height -> WGS 84 ellipsoidal, ~50 m in the Alps).
TEST(BridgePipeline, OnAnEgm96DemTheEndsStandOnTheEllipsoidalTerrain) {
  const Valley valley(straight_bridge(), kLevel, kTileSize, false, "egm96");
  const CliResult r = valley.run();
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const test::Egm96ToEllipsoid to_ellipsoid;
  const std::vector<Deck> found = decks(*Store::open(valley.store, Store::Mode::ReadOnly));
  ASSERT_EQ(found.size(), 1u);
  int ends = 0;
  for (const double end_x : {kWest, kEast})
    for (const double end_y : {-kHalfWidth, kHalfWidth}) {
      const auto [lon, lat] = lonlat(end_x, end_y);
      const double expected = to_ellipsoid(lon, lat, terrain(end_x));
      EXPECT_GT(expected - terrain(end_x), 40);
      double top = -INFINITY;
      for (const auto& [x, y, h] : found[0].local)
        if (std::hypot(x - end_x, y - end_y) < 0.01) top = std::max(top, h);
      EXPECT_NEAR(top, expected, 0.01) << "end at x " << end_x << ", y " << end_y;
      ++ends;
    }
  EXPECT_EQ(ends, 4);
}

// The rHEALPix plane of the grid (formats/geotiff/export_crs.h) as PROJ defines it.
OGRSpatialReference rhealpix() {
  OGRSpatialReference srs;
  srs.importFromProj4(
      "+proj=rhealpix +ellps=WGS84 +north_square=0 +south_square=0 +units=m +no_defs");
  return srs;
}

// GDAL's rasterization of the straight deck's outline (edges densified to 1e-6 degrees, so that
// they follow straight lines in degrees as the operator's) on `cell`'s tile in the rHEALPix
// plane: 1 for the pixels whose centre lies inside.
std::vector<uint8_t> rasterized_deck(CellId cell, int tile_size, const Site& site = alps()) {
  const std::unique_ptr<GDALDataset> ds(GetGDALDriverManager()->GetDriverByName("MEM")->Create(
      "", tile_size, tile_size, 1, GDT_Byte, nullptr));
  const PlaneSquare square = default_grid().plane_square(cell);
  const double pixel = square.side / tile_size;
  double transform[6] = {square.x_min, pixel, 0, square.y_max, 0, -pixel};
  ds->SetGeoTransform(transform);
  const OGRSpatialReference plane = rhealpix();
  ds->SetSpatialRef(&plane);
  EXPECT_TRUE(test::burn_deck(*ds, edge(-kHalfWidth, site), edge(kHalfWidth, site), {1}));
  std::vector<uint8_t> out(size_t(tile_size) * size_t(tile_size));
  EXPECT_EQ(ds->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, tile_size, tile_size, out.data(),
                                           tile_size, tile_size, GDT_Byte, 0, 0),
            CE_None);
  return out;
}

// The stored mask's pixels by global face pixel (face, col, row).
std::map<std::tuple<int, int64_t, int64_t>, uint8_t> mask_pixels(const Store& st, int tile_size) {
  std::map<std::tuple<int, int64_t, int64_t>, uint8_t> out;
  for (const CellId cell : st.tile_cells("bridge_mask")) {
    const auto raw = st.get_tile("bridge_mask", cell);
    EXPECT_EQ(raw->dtype, DType::U8);
    for (int r = 0; r < tile_size; ++r)
      for (int c = 0; c < tile_size; ++c)
        out[{cell.face(), int64_t(cell.col()) * tile_size + c,
             int64_t(cell.row()) * tile_size + r}] =
            uint8_t(raw->bytes[size_t(r) * size_t(tile_size) + size_t(c)]);
  }
  return out;
}

TEST(BridgePipeline, MaskIsGdalRasterizationOfTheDeck) {
  const Valley valley(straight_bridge());
  ASSERT_EQ(valley.run().exit_code, 0);
  const auto st = Store::open(valley.store, Store::Mode::ReadOnly);
  size_t under = 0, differ = 0;
  for (const CellId cell : st->tile_cells("bridge_mask")) {
    const auto raw = st->get_tile("bridge_mask", cell);
    const std::vector<uint8_t> expected = rasterized_deck(cell, kTileSize);
    for (size_t i = 0; i < expected.size(); ++i) {
      const uint8_t got = uint8_t(raw->bytes[i]);
      EXPECT_LE(got, 1);
      under += got;
      differ += got != expected[i];
    }
  }
  EXPECT_EQ(differ, 0u);
  // About the deck's area (4,000 m^2) over the pixel's area.
  const double pixel_area = default_grid().area(0) / std::ldexp(1.0, 2 * (kLevel + 8));
  EXPECT_NEAR(double(under) * pixel_area, 2 * kHalfWidth * (kEast - kWest), 0.1 * 4000);
}

// The DEM file's height at (lon, lat) as GDAL reads it: bilinear between its pixel centres.
double gdal_height(const std::string& path, double lon, double lat) {
  const std::unique_ptr<GDALDataset> ds(GDALDataset::Open(path.c_str(), GDAL_OF_RASTER));
  double t[6];
  EXPECT_EQ(ds->GetGeoTransform(t), CE_None);
  const double col = (lon - t[0]) / t[1] - 0.5, row = (lat - t[3]) / t[5] - 0.5;
  const int c = int(std::floor(col)), r = int(std::floor(row));
  float v[4];
  EXPECT_EQ(ds->GetRasterBand(1)->RasterIO(GF_Read, c, r, 2, 2, v, 2, 2, GDT_Float32, 0, 0),
            CE_None);
  const double fc = col - c, fr = row - r;
  return (1 - fr) * ((1 - fc) * v[0] + fc * v[1]) + fr * ((1 - fc) * v[2] + fc * v[3]);
}

// A bridge across the seam of faces P and Q (the meridian 0): built in the plane unfolded around
// one face, its west ends on P's DEM and its east ends on Q's within 1 cm of the DEM file as
// GDAL reads it, the same deck as on one face; its mask on both faces' tiles GDAL's
// rasterization of the outline.
TEST(BridgePipeline, AcrossTheSeamOfTwoFaces) {
  const Valley valley(straight_bridge(seam()), kLevel, kTileSize, false, "ellipsoid",
                      {{"mesh", "bridge"}, {"mask", "bridge_mask"}}, seam());
  const CliResult r = valley.run();
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto st = Store::open(valley.store, Store::Mode::ReadOnly);
  const std::vector<Deck> found = decks(*st, seam());
  ASSERT_EQ(found.size(), 1u);
  expect_straight_deck(found[0]);
  for (const double end_x : {kWest, kEast})
    for (const double end_y : {-kHalfWidth, kHalfWidth}) {
      const auto [lon, lat] = seam().lonlat(end_x, end_y);
      EXPECT_EQ(CellId::FromFace(default_grid().cell_from_point({lon, lat}, 0).face()).ToText(),
                end_x < 0 ? "P" : "Q");
      double top = -INFINITY;
      for (const auto& [x, y, h] : found[0].local)
        if (std::hypot(x - end_x, y - end_y) < 0.01) top = std::max(top, h);
      EXPECT_NEAR(top, gdal_height(valley.dir + "/dem.tif", lon, lat), 0.01)
          << "end at x " << end_x << ", y " << end_y;
    }
  std::map<int, size_t> under;  // mask pixels by face
  size_t differ = 0;
  for (const CellId cell : st->tile_cells("bridge_mask")) {
    const auto raw = st->get_tile("bridge_mask", cell);
    const std::vector<uint8_t> expected = rasterized_deck(cell, kTileSize, seam());
    for (size_t i = 0; i < expected.size(); ++i) {
      under[cell.face()] += uint8_t(raw->bytes[i]);
      differ += uint8_t(raw->bytes[i]) != expected[i];
    }
  }
  EXPECT_EQ(differ, 0u);
  EXPECT_EQ(under.size(), 2u);
  for (const auto& [face, pixels] : under) EXPECT_GT(pixels, 100u) << "face " << face;
}

TEST(BridgePipeline, SameBitsForOneAndTwoThreadsAndTwoTilings) {
  const Valley one(straight_bridge()), two(straight_bridge()),
      fine(straight_bridge(), kLevel + 1, kTileSize / 2);
  ASSERT_EQ(one.run("-t 1").exit_code, 0);
  ASSERT_EQ(two.run("-t 2").exit_code, 0);
  ASSERT_EQ(fine.run().exit_code, 0);
  const auto a = Store::open(one.store, Store::Mode::ReadOnly);
  const auto b = Store::open(two.store, Store::Mode::ReadOnly);
  const auto c = Store::open(fine.store, Store::Mode::ReadOnly);
  const std::vector<CellId> cells = a->content_cells("bridge");
  ASSERT_EQ(cells.size(), 1u);
  ASSERT_EQ(cells, b->content_cells("bridge"));
  EXPECT_EQ(a->get_content("bridge", cells[0]), b->get_content("bridge", cells[0]));
  const auto mask = mask_pixels(*a, kTileSize);
  EXPECT_EQ(mask, mask_pixels(*b, kTileSize));
  // The finer tiling covers the same pixels, or more of them beyond the coarse cells.
  const auto fine_mask = mask_pixels(*c, kTileSize / 2);
  size_t compared = 0;
  for (const auto& [at, v] : fine_mask)
    if (const auto it = mask.find(at); it != mask.end()) {
      ++compared;
      EXPECT_EQ(v, it->second);
    }
  EXPECT_GT(compared, 100000u);
  // The deck from the other tiling: the same vertices in lon/lat and height within 1 mm.
  const std::vector<Deck> coarse_deck = decks(*a), fine_deck = decks(*c);
  ASSERT_EQ(coarse_deck.size(), 1u);
  ASSERT_EQ(fine_deck.size(), 1u);
  ASSERT_EQ(coarse_deck[0].local.size(), fine_deck[0].local.size());
  for (size_t k = 0; k < coarse_deck[0].local.size(); ++k)
    for (size_t i = 0; i < 3; ++i)
      EXPECT_NEAR(coarse_deck[0].local[k][i], fine_deck[0].local[k][i], 1e-3) << k;
}

// A step mapping only the mask writes the same mask, and no mesh layer.
TEST(BridgePipeline, MaskAlone) {
  const Valley both(straight_bridge()),
      alone(straight_bridge(), kLevel, kTileSize, false, "ellipsoid", {{"mask", "bridge_mask"}});
  ASSERT_EQ(both.run().exit_code, 0);
  const CliResult r = alone.run();
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto a = Store::open(both.store, Store::Mode::ReadOnly);
  const auto b = Store::open(alone.store, Store::Mode::ReadOnly);
  EXPECT_FALSE(b->layer("bridge"));
  const auto mask = mask_pixels(*b, kTileSize);
  size_t under = 0;
  for (const auto& [at, v] : mask) under += v;
  EXPECT_GT(under, 500u);
  EXPECT_EQ(mask, mask_pixels(*a, kTileSize));
}

// A bad stroke fails the run naming the feature and the field, and writes no bridge.
void expect_refused(const json& feature, const std::string& message, bool hole = false) {
  const Valley valley(collection(feature), kLevel, kTileSize, hole);
  const CliResult r = valley.run();
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("structures.bridge: inputs.strokes: feature 1 (tool bridge): " + message),
            std::string::npos)
      << r.err;
  const auto st = Store::open(valley.store, Store::Mode::ReadOnly);
  EXPECT_TRUE(!st->layer("bridge") || st->content_cells("bridge").empty());
}

TEST(BridgePipeline, BadStrokesAreNamed) {
  expect_refused(bridge_feature({edge(-kHalfWidth), edge(kHalfWidth)}, {{"thickness_m", -1}}),
                 "thickness_m: -1 is not a positive number");
  expect_refused(bridge_feature({edge(-kHalfWidth), edge(kHalfWidth)}, {{"thickness_m", "thick"}}),
                 "thickness_m: \"thick\" is not a positive number");
  // Three edges (an edge of fewer than 2 points is refused by the ingest already, and by
  // bridge_stroke_test.cpp).
  expect_refused(bridge_feature({edge(-kHalfWidth), edge(0), edge(kHalfWidth)}, json::object()),
                 "geometry: a MultiLineString of 3 part(s), not a MultiLineString of the deck's "
                 "two edges");
  // Edges crossing: the second runs from the first's south side to its north side.
  json crossing = edge(kHalfWidth);
  crossing[2] = lonlat(50, -20);
  expect_refused(bridge_feature({edge(-kHalfWidth), crossing}, json::object()),
                 "geometry: the deck between the edges is not a simple polygon");
  // An end beyond the DEM (the stroke reaches 1 km east, the DEM ~460 m).
  json far_edge = edge(-kHalfWidth), far_other = edge(kHalfWidth);
  far_edge.push_back(lonlat(1000, -kHalfWidth));
  far_other.push_back(lonlat(1000, kHalfWidth));
  expect_refused(bridge_feature({far_edge, far_other}, json::object()),
                 "geometry: edge 1's last point is off the DEM, on its nodata");
  // An end on the DEM's nodata.
  expect_refused(bridge_feature({edge(-kHalfWidth), edge(kHalfWidth)}, json::object()),
                 "geometry: edge 1's last point is off the DEM, on its nodata", true);
}

}  // namespace
}  // namespace maquette
