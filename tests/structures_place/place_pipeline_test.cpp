// structures.place through the real program, as a user runs it: a box model (2 m x 1 m, written
// as a glTF GLB by the test) ingested with `maquette ingest --as model`, a synthetic DEM of EGM96
// heights (a lon/lat GeoTIFF: a tilted plane) and closed strokes of tool 'place' drawn around the
// box's footprint turned, scaled and moved (128 points, each off by up to 2 % of the footprint's
// length), run by `maquette run`. Each stored instance gives back its stroke's transform: rotation
// within 1 degree, scale within 3 %, position within 1 % of the footprint's length; its base
// stands on the lowest terrain under its footprint (the DEM's plane at the footprint's lowest
// corner, taken to the ellipsoid by PROJ): not above it, and below it by no more than the
// pixels it stands on reach.
// An explicit heading is honoured; 1 and 2 threads store the same bits; a square stroke, or one
// naming no model of the store, fails the run naming its feature.
#include <gdal_priv.h>
#include <gtest/gtest.h>
#include <ogr_geometry.h>

#include <GeographicLib/LocalCartesian.hpp>
#include <array>
#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <numbers>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "egm96_oracle.h"
#include "model_files.h"
#include "model_oracle.h"
#include "run_cli.h"
#include "store/store.h"
#include "stored_content.h"
#include "stored_layers.h"
#include "synthetic_raster.h"

namespace maquette {
namespace {

using nlohmann::json;
using test::CliResult;
using test::run_maquette;

constexpr double kWest = 7.440, kEast = 7.448, kSouth = 46.946, kNorth = 46.952;
constexpr double kLon0 = 7.444, kLat0 = 46.949;
constexpr double kSourcePixelDeg = 2e-5;  // ~1.5 x 2.2 m
constexpr double kPi = std::numbers::pi;
// The box model's footprint (tests/models: 2 m east, 1 m north, centred on its origin).
constexpr double kBoxLength = 2, kBoxWidth = 1;

const GeographicLib::LocalCartesian& scene_frame() {
  static const GeographicLib::LocalCartesian frame(kLat0, kLon0, 0);
  return frame;
}

// The DEM (m above EGM96) at x, y metres east and north of the scene's centre: a tilted plane,
// which the ingest's bilinear resampling and the operator's bilinear sampling keep exactly.
double terrain(double x, double y) { return 540 + 0.03 * x - 0.02 * y; }

void write_dem(const std::string& path) {
  test::RasterSpec spec =
      test::lonlat_raster(kWest, kNorth, int(std::lround((kEast - kWest) / kSourcePixelDeg)),
                          kSourcePixelDeg, "Float32");
  spec.height = int(std::lround((kNorth - kSouth) / kSourcePixelDeg));
  test::write_raster(path, spec, [](int, double lon, double lat) {
    double x = 0, y = 0, up = 0;
    scene_frame().Forward(lat, lon, 0, x, y, up);
    return terrain(x, y);
  });
}

// The box's footprint turned by `rotation` (radians, counter-clockwise from east), scaled by
// `scale` (its width by `scale` x `stretch`) and centred at (x, y) metres in the scene's frame.
struct Placement {
  double rotation, scale, x, y, stretch = 1;
};

// A stroke around the placement's footprint: `n` points evenly spaced along its outline from a
// random start, each moved by a random vector of up to 2 % of the footprint's length; drawn again
// until the ring does not cross itself (GEOS, as the ingest checks strokes).

json drawn_stroke(const Placement& p, int n, std::mt19937& random) {
  const double a = kBoxLength / 2, b = kBoxWidth / 2 * p.stretch, perimeter = 4 * (a + b);
  const double noise = 0.02 * kBoxLength * p.scale;
  std::uniform_real_distribution<double> unit(0, 1);
  const double start = unit(random) * perimeter;
  json ring = json::array();
  for (int i = 0; i < n; ++i) {
    double s = std::fmod(start + perimeter * i / n, perimeter), u = 0, v = 0;
    if (s < 2 * a) {
      u = -a + s, v = -b;
    } else if ((s -= 2 * a) < 2 * b) {
      u = a, v = -b + s;
    } else if ((s -= 2 * b) < 2 * a) {
      u = a - s, v = b;
    } else {
      u = -a, v = b - (s - 2 * a);
    }
    const double radius = noise * std::sqrt(unit(random)), t = unit(random) * 2 * kPi;
    const double x = p.x + p.scale * (std::cos(p.rotation) * u - std::sin(p.rotation) * v) +
                     radius * std::cos(t);
    const double y = p.y + p.scale * (std::sin(p.rotation) * u + std::cos(p.rotation) * v) +
                     radius * std::sin(t);
    double lat = 0, lon = 0, h = 0;
    scene_frame().Reverse(x, y, 0, lat, lon, h);
    ring.push_back({lon, lat});
  }
  ring.push_back(ring[0]);
  return {{"type", "Polygon"}, {"coordinates", {ring}}};
}

json stroke(const Placement& p, int n, std::mt19937& random) {
  for (;;) {
    json geometry = drawn_stroke(p, n, random);
    const std::unique_ptr<OGRGeometry> g(
        OGRGeometryFactory::createFromGeoJson(geometry.dump().c_str()));
    CPLErrorHandlerPusher quiet(CPLQuietErrorHandler);
    if (g && g->IsValid()) return geometry;
  }
}

// A stroke of tool 'place'; the ingest numbers features from 1 in the file's order.
json feature(const json& geometry, json properties) {
  properties["tool"] = "place";
  return {{"type", "Feature"}, {"geometry", geometry}, {"properties", properties}};
}

// A store with the DEM, the box model and `strokes`, and the pipeline placing them.
struct Scene {
  std::string dir = test::temp_dir();
  std::string store = dir + "/place.mqt";

  explicit Scene(const json& strokes) {
    write_dem(dir + "/dem.tif");
    const std::string model = test::write_glb(test::box_model({0.8f, 0.6f, 0.3f, 1}), dir, "box");
    json collection = {{"type", "FeatureCollection"}, {"features", strokes}};
    std::ofstream(dir + "/strokes.geojson") << collection.dump();
    const json pipeline = {{"store", store},
                           {"region", {{"bbox", {kWest, kSouth, kEast, kNorth}}}},
                           {"level", 14},
                           {"steps",
                            {{{"op", "structures.place"},
                              {"inputs", {{"dem", "dem"}, {"strokes", "strokes"}}},
                              {"outputs", {{"instances", "placed"}}}}}}};
    std::ofstream(dir + "/pipeline.json") << pipeline.dump(2);
    for (const std::string& args :
         {"ingest " + store + " " + dir + "/dem.tif --layer dem --as dem --vertical-datum egm96 " +
              "--level 14 --tile-size 256",
          "ingest " + store + " " + model + " --layer box --as model",
          "ingest " + store + " " + dir + "/strokes.geojson --layer strokes --as features"}) {
      const CliResult r = run_maquette("-q " + args);
      EXPECT_EQ(r.exit_code, 0) << args << "\n" << r.err;
    }
  }
  CliResult run(const std::string& options = "") const {
    return run_maquette("-q run " + options + " " + dir + "/pipeline.json");
  }
};

// A stored instance as the test reads it back, in the scene's frame.
struct Placed {
  double rotation = 0;  // of the model's +x, counter-clockwise from east at its position
  double scale = 0;
  double x = 0, y = 0;                  // metres in the scene's frame
  double lon = 0, lat = 0, height = 0;  // the position (the model's base), above the ellipsoid
  std::string prototype;
  json attributes;
};

std::map<int64_t, Placed> placed(const std::string& store) {
  const auto st = Store::open(store, Store::Mode::ReadOnly);
  std::map<int64_t, Placed> out;
  for (const test::StoredInstance& s : test::stored_instances(*st, "placed")) {
    Placed p;
    p.lon = s.lon, p.lat = s.lat, p.height = s.height;
    EXPECT_NEAR(s.x_axis[2], 0, 1e-5) << "the model turns about the vertical only";
    p.rotation = std::atan2(s.x_axis[1], s.x_axis[0]);
    EXPECT_EQ(s.scale[0], s.scale[1]);
    EXPECT_EQ(s.scale[0], s.scale[2]);
    p.scale = s.scale[0];
    double z = 0;
    scene_frame().Forward(p.lat, p.lon, 0, p.x, p.y, z);
    p.prototype = s.prototype;
    EXPECT_EQ(s.provenance.tool, "structures.place");
    p.attributes = s.provenance.attributes;
    EXPECT_TRUE(out.emplace(s.provenance.feature_id, p).second) << "placed once";
  }
  return out;
}

// The lowest terrain under the box placed as `p` says (its footprint's corners: the terrain is a
// plane), above the ellipsoid at p's position: the DEM's EGM96 height taken to WGS 84 by PROJ.
double lowest_ellipsoidal_terrain(const Placed& p) {
  double lowest = 1e300;
  for (const double u : {-kBoxLength / 2, kBoxLength / 2})
    for (const double v : {-kBoxWidth / 2, kBoxWidth / 2})
      lowest = std::min(
          lowest, terrain(p.x + p.scale * (std::cos(p.rotation) * u - std::sin(p.rotation) * v),
                          p.y + p.scale * (std::sin(p.rotation) * u + std::cos(p.rotation) * v)));
  static const test::Egm96ToEllipsoid to_ellipsoid;
  const double z = to_ellipsoid(p.lon, p.lat, lowest);
  EXPECT_GT(z - lowest, 40);  // the geoid is ~49 m above the ellipsoid near Bern
  return z;
}

// How far below the lowest terrain under the footprint its base may be: the base is the lowest
// DEM sample among the pixels the footprint touches and their neighbours (terrain_base.h), whose
// centres lie up to 1.5 pixels beyond it along each axis; pixels here (level 14, tiles of 256)
// have 2.4 m equal-area sides but are not square, under 3 m along either axis; the slope is
// hypot(0.03, 0.02). A base taken from farther away (the tile's lowest: 22 m lower) fails.
constexpr double kBaseBelowM = 1.5 * 3 * 1.4143 * 0.0361;

// The base's height above the lowest terrain under the footprint: in [-kBaseBelowM, 1 mm] when
// nothing floats and the base is no deeper than the pixels it stands on.
double base_above_terrain(const Placed& p) {
  const double above = p.height - lowest_ellipsoidal_terrain(p);
  EXPECT_LE(above, 0.001) << "the model floats";
  EXPECT_GE(above, -kBaseBelowM) << "the model sinks";
  return above;
}

// The angle between two rotations, radians, modulo a half turn (the box is centrally symmetric:
// turned by a half turn it covers the same footprint).
double half_turn_difference(double a, double b) { return std::abs(std::remainder(a - b, kPi)); }

// Strokes around the box turned, scaled and spread over the scene (x, y metres from its centre),
// and one of them with a heading given (the last).
const std::vector<Placement> kPlacements = {{35 * kPi / 180, 10, -60, 40},
                                            {-120 * kPi / 180, 7, 80, -70},
                                            {170 * kPi / 180, 4.5, 20, 120},
                                            {5 * kPi / 180, 25, -120, -90}};
const Placement kHeaded{60 * kPi / 180, 8, 130, 20};
constexpr double kHeadingDeg = 100;

json placement_strokes() {
  std::mt19937 random(17);
  json strokes = json::array();
  for (const Placement& p : kPlacements)
    strokes.push_back(feature(stroke(p, 128, random), {{"model", "box"}}));
  // The third drawn as a LineString ending where it begins (as DESIGN.md's strokes are).
  json& line = strokes[2]["geometry"];
  line = {{"type", "LineString"}, {"coordinates", line["coordinates"][0]}};
  strokes.push_back(
      feature(stroke(kHeaded, 128, random), {{"model", "box"}, {"heading_deg", kHeadingDeg}}));
  return strokes;
}

TEST(PlacePipeline, StrokesPlaceTheModelTurnedScaledOnTheTerrain) {
  const std::vector<Placement>& placements = kPlacements;
  const Placement& headed = kHeaded;
  const Scene scene(placement_strokes());
  const CliResult r = scene.run();
  ASSERT_EQ(r.exit_code, 0) << r.err;

  const std::map<int64_t, Placed> out = placed(scene.store);
  ASSERT_EQ(out.size(), placements.size() + 1);
  double worst_rotation = 0, worst_scale = 0, worst_position = 0, worst_base = 0;
  for (size_t i = 0; i < placements.size(); ++i) {
    const Placement& want = placements[i];
    const Placed& got = out.at(int64_t(i) + 1);
    EXPECT_EQ(got.prototype, "box");
    const double length = kBoxLength * want.scale;
    worst_rotation = std::max(worst_rotation, half_turn_difference(got.rotation, want.rotation));
    worst_scale = std::max(worst_scale, std::abs(got.scale / want.scale - 1));
    worst_position = std::max(worst_position, std::hypot(got.x - want.x, got.y - want.y) / length);
    worst_base = std::max(worst_base, std::abs(base_above_terrain(got)));
    EXPECT_FALSE(got.attributes.at("half_turn_decided").get<bool>());  // a box: symmetric
    // The stroke's area variance ratio: the footprint's aspect squared (4), within the noise.
    EXPECT_NEAR(got.attributes.at("axis_ratio").get<double>(), 4, 0.2);
  }
  EXPECT_LE(worst_rotation, kPi / 180);
  EXPECT_LE(worst_scale, 0.03);
  EXPECT_LE(worst_position, 0.01);
  std::cout << "worst rotation " << worst_rotation * 180 / kPi << " deg, scale "
            << worst_scale * 100 << " %, position " << worst_position * 100
            << " % of the length, base at most " << worst_base * 1000
            << " mm below the lowest terrain under the footprint\n";

  // The heading: the model's +y 100 degrees clockwise from north, its +x at -100 degrees from
  // east, whatever the stroke's axes; the scale and position still the stroke's.
  const Placed& got = out.at(int64_t(placements.size()) + 1);
  EXPECT_NEAR(std::remainder(got.rotation + kHeadingDeg * kPi / 180, 2 * kPi), 0, 1e-5);
  EXPECT_NEAR(got.scale / headed.scale, 1, 0.03);
  EXPECT_LE(std::hypot(got.x - headed.x, got.y - headed.y), 0.01 * kBoxLength * headed.scale);
  base_above_terrain(got);
}

TEST(PlacePipeline, SameBitsForOneAndTwoThreads) {
  const Scene one(placement_strokes()), two(placement_strokes());
  ASSERT_EQ(one.run("-t 1").exit_code, 0);
  ASSERT_EQ(two.run("-t 2").exit_code, 0);
  const auto a = Store::open(one.store, Store::Mode::ReadOnly);
  const auto b = Store::open(two.store, Store::Mode::ReadOnly);
  // The strokes spread over several cells.
  EXPECT_GT(test::expect_same_content(*a, *b, "placed"), 1u);
}

TEST(PlacePipeline, SquareStrokeIsAmbiguousNamingItsFeature) {
  std::mt19937 random(5);
  // The box scaled 12 along and 24 across: a square of 24 m.
  const json square = stroke({0.3, 12, 0, 0, 2}, 128, random);
  const Scene ambiguous(json::array({feature(square, {{"model", "box"}})}));
  const CliResult r = ambiguous.run();
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("structures.place: feature 1"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("heading is ambiguous"), std::string::npos) << r.err;

  // The same square with a heading is placed.
  const Scene headed(json::array({feature(square, {{"model", "box"}, {"heading_deg", 30}})}));
  ASSERT_EQ(headed.run().exit_code, 0);
  const std::map<int64_t, Placed> out = placed(headed.store);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_NEAR(std::remainder(out.at(1).rotation + 30 * kPi / 180, 2 * kPi), 0, 1e-5);
}

// DESIGN.md's stroke convention names the properties `object` and `heading`: the same placement;
// both names with different values refused.
TEST(PlacePipeline, DesignNamesObjectAndHeadingAreTaken) {
  std::mt19937 random(5);
  const json square = stroke({0.3, 12, 0, 0, 2}, 128, random);
  const Scene named(json::array({feature(square, {{"object", "box"}, {"heading", 30}})}));
  ASSERT_EQ(named.run().exit_code, 0);
  const std::map<int64_t, Placed> out = placed(named.store);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_NEAR(std::remainder(out.at(1).rotation + 30 * kPi / 180, 2 * kPi), 0, 1e-5);

  const Scene both(
      json::array({feature(square, {{"model", "box"}, {"object", "crate"}, {"heading", 30}})}));
  const CliResult r = both.run();
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("structures.place: feature 1: properties 'model' (\"box\") and 'object' "
                       "(\"crate\") disagree"),
            std::string::npos)
      << r.err;

  // Errors name the field as the stroke spells it.
  const Scene bad_heading(
      json::array({feature(square, {{"object", "box"}, {"heading", "north"}})}));
  const CliResult h = bad_heading.run();
  EXPECT_NE(h.exit_code, 0);
  EXPECT_NE(h.err.find("property 'heading' is not a number of degrees: \"north\""),
            std::string::npos)
      << h.err;
  const Scene bad_object(json::array({feature(square, {{"object", 5}})}));
  const CliResult o = bad_object.run();
  EXPECT_NE(o.exit_code, 0);
  EXPECT_NE(o.err.find("property 'object' (the name of a model layer) is not a name: 5"),
            std::string::npos)
      << o.err;
}

TEST(PlacePipeline, UnknownModelIsNamed) {
  std::mt19937 random(3);
  const Scene scene(
      json::array({feature(stroke({0, 10, 0, 0}, 64, random), {{"model", "crate"}})}));
  const CliResult r = scene.run();
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("structures.place: feature 1: unknown prototype 'crate'"), std::string::npos)
      << r.err;
}

TEST(PlacePipeline, OpenStrokeIsRefusedNamingItsFeature) {
  std::mt19937 random(3);
  json line = stroke({0, 10, 0, 0}, 64, random)["coordinates"][0];
  line.erase(line.end() - 1);  // not back to its start
  const Scene scene(
      json::array({feature({{"type", "LineString"}, {"coordinates", line}}, {{"model", "box"}})}));
  const CliResult r = scene.run();
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("structures.place: feature 1: a stroke of tool 'place' is closed"),
            std::string::npos)
      << r.err;
}

}  // namespace
}  // namespace maquette
