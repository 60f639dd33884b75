// structures.vegetation through the real program, as a user runs it: a tilted plane written as a
// lon/lat GeoTIFF and ingested as a DEM, an RGB orthophoto of linear gradients ingested as
// imagery, an annulus stroke (tool "vegetation") ingested as features, the pipeline run by
// `maquette run`. Checked on the stored instances, against the analytic DEM and orthophoto and
// the stroke's own geometry: every pair of plants at least the minimum distance apart (all
// pairs), none outside the annulus, one plant per spacing^2, base heights on the terrain, colours
// of the orthophoto; the same plants (ids, positions to 1 cm, looks) for two tilings, the same
// bits for 1 and 2 threads; the paper's placement beside it; the spacing estimated from an
// orthophoto of crowns (structures.vegetation_spacing); bad or missing spacing_m refused.
#include <gtest/gtest.h>

#include <GeographicLib/LocalCartesian.hpp>
#include <array>
#include <cmath>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>
#include <vector>

#include "../poisson_disk.h"
#include "circle_ring.h"
#include "content/instances_codec.h"
#include "run_cli.h"
#include "store/store.h"
#include "synthetic_raster.h"

namespace maquette::structures {
namespace {

using nlohmann::json;
using test::CliResult;
using test::run_maquette;

constexpr double kLon = -112.0, kLat = 37.0;  // the annulus' centre
constexpr double kHalfDeg = 0.025;            // the rasters: +-0.025 degrees (~2.2 x 2.8 km)
constexpr double kOuterM = 1000, kInnerM = 300, kSpacingM = 20;

const GeographicLib::LocalCartesian kCentre(kLat, kLon, 0);

std::array<double, 2> local(double lon, double lat) {
  double x = 0, y = 0, z = 0;
  kCentre.Forward(lat, lon, 0, x, y, z);
  return {x, y};
}
double terrain(double lon, double lat) {
  const auto [x, y] = local(lon, lat);
  return 1000 + 0.02 * x + 0.01 * y;
}
std::array<double, 3> colour(double lon, double lat) {
  return {40 + 160 * (lon - kLon + kHalfDeg) / (2 * kHalfDeg),
          40 + 160 * (lat - kLat + kHalfDeg) / (2 * kHalfDeg), 90};
}

// The scene: rasters over +-half_deg around the centre at pixel_deg, the orthophoto's colour by
// lon, lat and band, the stroke an annulus, the step's region +-region_deg.
struct Layout {
  double half_deg, pixel_deg, outer_m, inner_m, region_deg;
  std::function<double(double, double, int)> orthophoto;
};

const Layout kGradients = {
    kHalfDeg, 1e-4, kOuterM, kInnerM, 0.013, [](double lon, double lat, int band) {
      return std::round(colour(lon, lat)[size_t(band)]);
    }};

// Crowns: discs of radius 3.5 m on a square lattice of kCrownSpacingM (in the centre's tangent
// plane), dark green on light ground, under a disc stroke of 150 m, pixels of ~1 m.
constexpr double kCrownSpacingM = 10;
const Layout kCrowns = {0.0025, 1e-5, 150, 0, 0.0018, [](double lon, double lat, int band) {
                          const auto [x, y] = local(lon, lat);
                          const double u = x / kCrownSpacingM - std::round(x / kCrownSpacingM);
                          const double v = y / kCrownSpacingM - std::round(y / kCrownSpacingM);
                          const bool crown = std::hypot(u, v) * kCrownSpacingM < 3.5;
                          return crown ? std::array{40.0, 90.0, 40.0}[size_t(band)]
                                       : std::array{200.0, 190.0, 160.0}[size_t(band)];
                        }};

// A lon/lat GeoTIFF over the layout of `bands` bands of GDAL type `type`, band b of each pixel
// `value(lon, lat, b - 1)` at its centre.
void write_raster(const std::string& path, const Layout& layout, int bands, const std::string& type,
                  const std::function<double(double, double, int)>& value) {
  const double half = layout.half_deg, pixel = layout.pixel_deg;
  test::RasterSpec spec = test::lonlat_raster(kLon - half, kLat + half,
                                              int(std::lround(2 * half / pixel)), pixel, type);
  spec.bands = bands;
  test::write_raster(path, spec,
                     [&](int band, double lon, double lat) { return value(lon, lat, band - 1); });
}

json ring(double radius_m) { return test::circle_ring(kLon, kLat, radius_m, 90); }

// The stroke's plane (vegetation_stroke.h): the tangent plane at its first vertex.
GeographicLib::LocalCartesian stroke_plane() {
  const json first = ring(kOuterM)[0];
  return GeographicLib::LocalCartesian(first[1].get<double>(), first[0].get<double>(), 0);
}

struct Plant {
  double lon, lat, h;
  uint16_t prototype;
  std::string prototype_name;
  float scale;
  uint32_t colour;
};

// A store with the rasters at `level` (tiles of `tile_size`) and the stroke, the pipeline
// running structures.vegetation with `params`; a null `spacing` leaves spacing_m out, and
// structures.vegetation_spacing estimates it first (unless params name spacings of their own).
struct Scene {
  std::string dir = test::temp_dir();
  std::string store = dir + "/scene.mqt";

  Scene(int level, int tile_size, const json& spacing, json params,
        const Layout& layout = kGradients, const json& stroke_properties = json::object()) {
    write_raster(dir + "/dem.tif", layout, 1, "Float32",
                 [](double lon, double lat, int) { return terrain(lon, lat); });
    write_raster(dir + "/ortho.tif", layout, 3, "Byte", layout.orthophoto);
    json properties = {{"tool", "vegetation"}};
    if (!spacing.is_null()) properties["spacing_m"] = spacing;
    properties.update(stroke_properties);
    json rings = {ring(layout.outer_m)};
    if (layout.inner_m > 0) rings.push_back(ring(layout.inner_m));
    const json strokes = {{"type", "FeatureCollection"},
                          {"features",
                           {{{"type", "Feature"},
                             {"properties", properties},
                             {"geometry", {{"type", "Polygon"}, {"coordinates", rings}}}}}}};
    std::ofstream(dir + "/strokes.geojson") << strokes.dump();
    json steps = json::array();
    if (spacing.is_null() && !params.contains("spacings")) {
      steps.push_back({{"op", "structures.vegetation_spacing"},
                       {"inputs", {{"orthophoto", "ortho"}, {"strokes", "strokes"}}},
                       {"outputs", {{"spacings", "spacings"}}}});
      params["spacings"] = "spacings";
    }
    steps.push_back({{"op", "structures.vegetation"},
                     {"inputs", {{"dem", "dem"}, {"orthophoto", "ortho"}, {"strokes", "strokes"}}},
                     {"outputs", {{"plants", "plants"}}},
                     {"params", params}});
    const double d = layout.region_deg;
    const json pipeline = {{"store", store},
                           {"region", {{"bbox", {kLon - d, kLat - d, kLon + d, kLat + d}}}},
                           {"level", level},
                           {"tile_size", tile_size},
                           {"steps", steps}};
    std::ofstream(dir + "/pipeline.json") << pipeline.dump(2);
    const std::string grid =
        " --level " + std::to_string(level) + " --tile-size " + std::to_string(tile_size);
    for (const std::string& args :
         {"ingest " + store + " " + dir + "/dem.tif --layer dem --as dem --vertical-datum " +
              "ellipsoid" + grid,
          "ingest " + store + " " + dir + "/ortho.tif --layer ortho --as imagery" + grid,
          "ingest " + store + " " + dir + "/strokes.geojson --layer strokes --as features"}) {
      const CliResult r = run_maquette("-q " + args);
      EXPECT_EQ(r.exit_code, 0) << args << "\n" << r.err;
    }
  }
  CliResult run(const std::string& options = "") const {
    return run_maquette("-q run " + options + " " + dir + "/pipeline.json");
  }
  // The stored plants by id.
  std::map<uint64_t, Plant> plants() const {
    const auto st = Store::open(store, Store::Mode::ReadOnly);
    std::map<uint64_t, Plant> out;
    for (const CellId cell : st->content_cells("plants")) {
      const InstancesContent c = unwrap_instances(*st->get_content("plants", cell), "test");
      const GeographicLib::LocalCartesian frame(c.origin.lat, c.origin.lon, c.origin.height);
      for (size_t k = 0; k < c.size(); ++k) {
        Plant p{};
        frame.Reverse(c.position[3 * k], c.position[3 * k + 1], c.position[3 * k + 2], p.lat, p.lon,
                      p.h);
        p.prototype = c.prototype[k];
        p.prototype_name = c.prototypes.at(c.prototype[k]);
        p.scale = c.scale[3 * k];
        p.colour = c.colour[k];
        EXPECT_TRUE(out.emplace(c.provenance[k].object_id, p).second) << "id twice";
      }
    }
    return out;
  }
};

const json kParams = {{"seed", 3},
                      {"prototypes",
                       {{{"name", "builtin:conifer"}, {"weight", 3}},
                        {{"name", "builtin:broadleaf"}, {"weight", 1}}}}};

// Plants' positions in the stroke's plane.
std::vector<PlanePoint> in_plane(const std::map<uint64_t, Plant>& plants) {
  const GeographicLib::LocalCartesian plane = stroke_plane();
  std::vector<PlanePoint> out;
  for (const auto& [id, p] : plants) {
    double x = 0, y = 0, z = 0;
    plane.Forward(p.lat, p.lon, 0, x, y, z);
    out.push_back({x, y});
  }
  return out;
}

// The fraction of points with another closer than d, and the smallest distance (all pairs).
std::pair<double, double> closeness(const std::vector<PlanePoint>& points, double d) {
  std::vector<bool> close(points.size());
  double closest = 1e300;
  for (size_t a = 0; a < points.size(); ++a)
    for (size_t b = a + 1; b < points.size(); ++b) {
      const double dist = std::hypot(points[a].x - points[b].x, points[a].y - points[b].y);
      closest = std::min(closest, dist);
      if (dist < d) close[a] = close[b] = true;
    }
  return {double(std::count(close.begin(), close.end(), true)) / double(points.size()), closest};
}

const double kArea = [] {  // of the 90-gon annulus, in the plane
  const double polygon = 90 / 2.0 * std::sin(2 * std::numbers::pi / 90);
  return polygon * (kOuterM * kOuterM - kInnerM * kInnerM);
}();

TEST(VegetationPipeline, BlueNoiseOnTheTerrainInTheOrthophotosColours) {
  const Scene scene(12, 64, kSpacingM, kParams);
  const CliResult r = scene.run();
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto plants = scene.plants();
  EXPECT_NEAR(double(plants.size()) / (kArea / (kSpacingM * kSpacingM)), 1, 0.05) << plants.size();
  const auto [close, closest] = closeness(in_plane(plants), kSpacingM / 2);
  EXPECT_EQ(close, 0.0);
  EXPECT_GE(closest, poisson_min_distance(kSpacingM) - 0.01);  // float32 positions
  size_t conifers = 0;
  for (const auto& [id, p] : plants) {
    const auto [x, y] = local(p.lon, p.lat);
    const double radius = std::hypot(x, y);
    EXPECT_TRUE(radius < kOuterM && radius > kInnerM * std::cos(std::numbers::pi / 90)) << radius;
    EXPECT_NEAR(p.h, terrain(p.lon, p.lat), 0.1);
    const auto rgb = colour(p.lon, p.lat);
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(double((p.colour >> (8 * k)) & 0xff), rgb[size_t(k)], 4) << "band " << k;
    EXPECT_TRUE(p.scale >= 8 && p.scale <= 15) << p.scale;  // the default range
    conifers += p.prototype == 0;
  }
  // Weights 3 : 1, binomial within 3 standard deviations.
  const double n = double(plants.size());
  EXPECT_NEAR(double(conifers), 0.75 * n, 3 * std::sqrt(n * 0.75 * 0.25));
}

// A stroke's own prototypes ({name: weight}) and scale (DESIGN.md's stroke convention) in place
// of the step's: the same places, every plant of its prototypes and in its scale range; a weight
// that is not a number refused, naming the feature and field.
TEST(VegetationPipeline, StrokesOwnPrototypesAndScale) {
  const Scene step(12, 64, kSpacingM, kParams);
  ASSERT_EQ(step.run().exit_code, 0);
  const json own = {{"prototypes", {{"builtin:shrub", 1}}}, {"scale", {2, 3}}};
  const Scene scene(12, 64, kSpacingM, kParams, kGradients, own);
  const CliResult r = scene.run();
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto plants = scene.plants(), step_plants = step.plants();
  ASSERT_EQ(plants.size(), step_plants.size());
  for (const auto& [id, p] : plants) {
    ASSERT_EQ(step_plants.count(id), 1u);
    EXPECT_EQ(p.lon, step_plants.at(id).lon);
    EXPECT_EQ(p.prototype_name, "builtin:shrub");
    EXPECT_TRUE(p.scale >= 2 && p.scale <= 3) << p.scale;
  }
  const Scene bad(12, 64, kSpacingM, kParams, kGradients,
                  {{"prototypes", {{"builtin:shrub", "many"}}}});
  const CliResult e = bad.run();
  EXPECT_NE(e.exit_code, 0);
  EXPECT_NE(e.err.find("feature 1 (tool vegetation): field 'prototypes': the weight of "
                       "'builtin:shrub' is \"many\""),
            std::string::npos)
      << e.err;
}

TEST(VegetationPipeline, SamePlantsForTwoTilingsAndThreadCounts) {
  // At 5 m the operator cuts its cells into windows of 256 buckets (3 x 3 of a level-12 cell,
  // 2 x 2 of a level-13 one), each with its own halo: 114,000 plants.
  const double spacing = 5;
  const Scene coarse(12, 64, spacing, kParams), fine(13, 32, spacing, kParams),
      two(12, 64, spacing, kParams);
  ASSERT_EQ(coarse.run("-t 1").exit_code, 0);
  ASSERT_EQ(fine.run("-t 1").exit_code, 0);
  ASSERT_EQ(two.run("-t 2").exit_code, 0);
  const auto a = coarse.plants(), b = fine.plants();
  ASSERT_GT(a.size(), 100000u);
  ASSERT_EQ(a.size(), b.size());
  for (const auto& [id, p] : a) {
    const auto it = b.find(id);
    ASSERT_NE(it, b.end()) << "plant " << id << " only in one tiling";
    const auto [x0, y0] = local(p.lon, p.lat);
    const auto [x1, y1] = local(it->second.lon, it->second.lat);
    EXPECT_LT(std::hypot(x1 - x0, y1 - y0), 0.01);
    EXPECT_NEAR(p.h, it->second.h, 0.01);
    EXPECT_EQ(p.prototype, it->second.prototype);
    EXPECT_EQ(p.scale, it->second.scale);
    EXPECT_EQ(p.colour, it->second.colour);
  }
  const auto st1 = Store::open(coarse.store, Store::Mode::ReadOnly);
  const auto st2 = Store::open(two.store, Store::Mode::ReadOnly);
  const std::vector<CellId> cells = st1->content_cells("plants");
  ASSERT_EQ(cells, st2->content_cells("plants"));
  for (const CellId cell : cells)
    EXPECT_EQ(st1->get_content("plants", cell), st2->get_content("plants", cell));
}

TEST(VegetationPipeline, ThePapersRandomPlacementBeside) {
  json params = kParams;
  params["placement"] = "random";
  const Scene scene(12, 64, kSpacingM, params);
  ASSERT_EQ(scene.run().exit_code, 0);
  const auto plants = scene.plants();
  EXPECT_NEAR(double(plants.size()), kArea / (kSpacingM * kSpacingM), 1.0);
  const double close = closeness(in_plane(plants), kSpacingM / 2).first;
  // A Poisson process' share, a little less for the plants near the rims (fewer neighbours).
  EXPECT_NEAR(close, 1 - std::exp(-std::numbers::pi / 4), 0.04);
  std::printf("random placement: %.1f %% of %zu plants closer than half the spacing\n", 100 * close,
              plants.size());
}

TEST(VegetationPipeline, SpacingFromTheOrthophotosCrowns) {
  const Scene scene(16, 128, nullptr, kParams, kCrowns);  // pixels of ~1.1 m
  const CliResult r = scene.run();
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto st = Store::open(scene.store, Store::Mode::ReadOnly);
  const json spacings = json::parse(st->get_artifact("spacings")->text());
  const double estimate = spacings.at("1").get<double>();
  EXPECT_NEAR(estimate / kCrownSpacingM, 1, 0.1) << estimate;
  // The plants at the estimated spacing: one per estimate^2 over the disc.
  const double area = 90 / 2.0 * std::sin(2 * std::numbers::pi / 90) * 150 * 150;
  EXPECT_NEAR(double(scene.plants().size()) / (area / (estimate * estimate)), 1, 0.06);
  std::printf("spacing estimated from the orthophoto: %.2f m (crowns at %.0f m)\n", estimate,
              kCrownSpacingM);
}

TEST(VegetationPipeline, BadSpacingNamesTheFeatureFieldAndValue) {
  const Scene scene(12, 64, -3, kParams);
  const CliResult r = scene.run();
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("feature 1 (tool vegetation): field 'spacing_m' is -3"), std::string::npos)
      << r.err;
  const auto st = Store::open(scene.store, Store::Mode::ReadOnly);
  EXPECT_TRUE(!st->layer("plants") || st->content_cells("plants").empty());
  // No spacing_m: an artifact of spacings is needed, and must be there (told when planned).
  for (const auto& [spacings, message] :
       {std::pair("", "feature 1 (tool vegetation): field 'spacing_m' is missing"),
        std::pair("nowhere",
                  "step 1 (structures.vegetation): params.spacings: unknown artifact 'nowhere'")}) {
    json params = kParams;
    params["spacings"] = spacings;
    const CliResult missing = Scene(12, 64, nullptr, params).run();
    EXPECT_NE(missing.exit_code, 0);
    EXPECT_NE(missing.err.find(message), std::string::npos) << missing.err;
  }
}

}  // namespace
}  // namespace maquette::structures
