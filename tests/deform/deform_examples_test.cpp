// The deform examples (examples/deform-virgin-river.json, examples/deform-rainier.json) run by the
// real program on ../shared/data, their pictures' steps left out. Checked on the layers exported
// as GeoTIFF and read with GDAL, positions through PROJ (OGR), not through the grid's code:
// - the Virgin River: the deformed surface (the solve's triangles, linear in each) along the
//   stroke's curve equals its Z; no sample raised by more than 3 m (the stroke asks for no raise:
//   its bed is 3 m below the lower envelope of the DEM along it, its banks at that envelope), and
//   the channel's bed lowered;
// - Rainier: the lake behind the road embankment holds water, its level is the spill level (the
//   lowest deformed height on the stroke's boundary, the pixels inside its polygon with an
//   8-neighbour outside, the polygon tested by OGR), near the embankment's crest; its depths are
//   level - terrain, and every wet pixel lies in the polygon.
// Skipped when the data is absent.
#include <gtest/gtest.h>
#include <ogr_geometry.h>
#include <ogr_spatialref.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/grid.h"
#include "example_pipeline.h"
#include "geotiff_raster.h"
#include "run_cli.h"
#include "store/store.h"

namespace maquette::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// Runs the example's steps of the given operators with its store in `dir` and its sources at
// their absolute paths (example_pipeline.h).
void run_example(const std::string& name, const std::string& dir,
                 const std::vector<std::string>& ops) {
  json p = example_pipeline(name);
  p["store"] = dir + "/example.mqt";
  json steps = json::array();
  for (const json& s : p["steps"])
    if (std::find(ops.begin(), ops.end(), s["op"].get<std::string>()) != ops.end())
      steps.push_back(s);
  p["steps"] = steps;
  std::ofstream(dir + "/pipeline.json") << p.dump(1);
  const CliResult r = run_maquette("-q run " + dir + "/pipeline.json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
}

// The layer exported on the grid's plane (its samples exactly) over the example's region, and
// read back.
Raster export_layer(const std::string& name, const std::string& dir, const std::string& layer) {
  const json bbox = read_json(kExamples + "/" + name + ".json")["region"]["bbox"];
  std::string box;
  for (const json& v : bbox) box += " " + std::to_string(v.get<double>());
  const std::string tif = dir + "/" + layer + ".tif";
  const CliResult r = run_maquette("-q export gtiff " + dir + "/example.mqt " + tif + " --layer " +
                                   layer + " --bbox" + box);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return read_raster(tif);
}

struct ExampleRun {
  std::string dir;       // holding example.mqt
  Raster first, second;  // two of its layers on the same grid
};

// Runs the example's steps of `ops` and exports its layers `first` and `second`.
ExampleRun run_and_export(const std::string& name, const std::vector<std::string>& ops,
                          const std::string& first, const std::string& second) {
  ExampleRun r{temp_dir(), {}, {}};
  run_example(name, r.dir, ops);
  r.first = export_layer(name, r.dir, first);
  r.second = export_layer(name, r.dir, second);
  EXPECT_GT(r.first.width, 0);
  EXPECT_EQ(r.second.width, r.first.width);
  EXPECT_EQ(r.second.height, r.first.height);
  return r;
}

// Lon/lat to the raster's CRS and back, through PROJ.
struct LonLatTransforms {
  OGRSpatialReference lonlat, plane;
  std::unique_ptr<OGRCoordinateTransformation> forward, inverse;
  explicit LonLatTransforms(const Raster& raster) {
    lonlat.importFromEPSG(4326);
    lonlat.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    plane.importFromWkt(raster.crs_wkt.c_str());
    plane.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    forward.reset(OGRCreateCoordinateTransformation(&lonlat, &plane));
    inverse.reset(OGRCreateCoordinateTransformation(&plane, &lonlat));
  }
};

// The height at a point given in pixel coordinates (x right, y down, sample centres at
// half-integers) on the solve's surface: each square of samples cut from its (col, row) corner to
// its (col + 1, row + 1) corner, heights linear in each triangle.
double surface_height(const Raster& r, double x, double y) {
  x -= 0.5;
  y -= 0.5;
  const int c = int(std::floor(x)), row = int(std::floor(y));
  const double fx = x - c, fy = y - row;
  const double h00 = r.at(c, row), h10 = r.at(c + 1, row), h01 = r.at(c, row + 1),
               h11 = r.at(c + 1, row + 1);
  return fx >= fy ? h00 + fx * (h10 - h00) + fy * (h11 - h10)
                  : h00 + fy * (h01 - h00) + fx * (h11 - h01);
}

TEST(DeformExamples, VirginRiverBedFollowsTheStroke) {
  if (!fs::exists(kShared + "/data/zion/srtm.tif")) GTEST_SKIP() << "no ../shared/data/zion";
  const ExampleRun run =
      run_and_export("deform-virgin-river", {"ingest", "deform.features"}, "dem", "river_dem");
  ASSERT_FALSE(HasFailure());
  const Raster &dem = run.first, &river = run.second;
  const LonLatTransforms t(river);

  // Along the curve every ~2 m: Z linear between the vertices.
  const json stroke = read_json(kExamples + "/deform-virgin-river/river.geojson");
  const json& vertices = stroke["features"][0]["geometry"]["coordinates"];
  double sum2 = 0, worst = 0;
  int points = 0;
  for (size_t v = 0; v + 1 < vertices.size(); ++v) {
    const json &a = vertices[v], &b = vertices[v + 1];
    for (int k = 0; k < 50; ++k) {
      const double f = k / 50.0;
      double x = a[0].get<double>() + f * (b[0].get<double>() - a[0].get<double>());
      double y = a[1].get<double>() + f * (b[1].get<double>() - a[1].get<double>());
      const double z = a[2].get<double>() + f * (b[2].get<double>() - a[2].get<double>());
      ASSERT_TRUE(t.forward->Transform(1, &x, &y));
      const double px = (x - river.transform[0]) / river.transform[1];
      const double py = (y - river.transform[3]) / river.transform[5];
      const double e = surface_height(river, px, py) - z;
      sum2 += e * e;
      worst = std::max(worst, std::abs(e));
      ++points;
    }
  }
  const double rms = std::sqrt(sum2 / points);

  double raised = 0;
  int lowered = 0;
  for (size_t i = 0; i < dem.values.size(); ++i) {
    if (!std::isfinite(dem.values[i])) continue;
    const double d = double(river.values[i]) - dem.values[i];
    raised = std::max(raised, d);
    lowered += d < -2.5;
  }
  std::printf(
      "%d points along the river: deformed surface - Z: RMS %.1f mm, largest %.1f mm; %d "
      "samples lowered by more than 2.5 m, largest raise %.2f m\n",
      points, rms * 1000, worst * 1000, lowered, raised);
  EXPECT_GT(points, 3000);
  EXPECT_LE(rms, 0.02);
  EXPECT_LE(worst, 0.16);  // at a bend of the curve
  // The bed (20 m wide, 7.3 km) covers ~1,900 samples of 77 m2.
  EXPECT_GT(lowered, 1500);
  EXPECT_LE(raised, 2.0);  // no spike: the vertices beyond the band are held
}

TEST(DeformExamples, RainierLakeFillsToTheSpillLevel) {
  if (!fs::exists(kShared + "/data/srtm3/mt_rainier_90m.tif"))
    GTEST_SKIP() << "no ../shared/data/srtm3";
  const ExampleRun run = run_and_export(
      "deform-rainier", {"ingest", "deform.features", "deform.water", "deform.water_bodies"},
      "dammed_dem", "lake_depth");
  ASSERT_FALSE(HasFailure());
  const Raster &dem = run.first, &depth = run.second;
  const LonLatTransforms t(dem);

  const json strokes = read_json(kExamples + "/deform-rainier/strokes.geojson");
  double crest = 0;
  OGRPolygon polygon;
  for (const json& f : strokes["features"]) {
    const json& g = f["geometry"];
    if (f["properties"]["tool"] == "feature") crest = g["coordinates"][0][2].get<double>();
    if (f["properties"]["tool"] != "water") continue;
    OGRLinearRing ring;
    for (const json& p : g["coordinates"][0]) ring.addPoint(p[0].get<double>(), p[1].get<double>());
    polygon.addRing(&ring);
  }
  ASSERT_FALSE(polygon.IsEmpty());
  ASSERT_GT(crest, 0);

  // The pixels whose centres lie in the polygon.
  const int w = dem.width, h = dem.height;
  std::vector<char> inside(size_t(w) * size_t(h), 0);
  for (int row = 0; row < h; ++row)
    for (int col = 0; col < w; ++col) {
      double x = dem.transform[0] + (col + 0.5) * dem.transform[1];
      double y = dem.transform[3] + (row + 0.5) * dem.transform[5];
      ASSERT_TRUE(t.inverse->Transform(1, &x, &y));
      const OGRPoint p(x, y);
      inside[size_t(row) * size_t(w) + size_t(col)] = polygon.Contains(&p);
    }
  const auto in = [&](int col, int row) {
    return col >= 0 && row >= 0 && col < w && row < h &&
           inside[size_t(row) * size_t(w) + size_t(col)];
  };
  double spill = INFINITY;
  std::array<double, 2> spill_at{};
  int boundary = 0, wet = 0, wet_outside = 0;
  double worst_depth = 0, volume = 0;
  for (int row = 0; row < h; ++row)
    for (int col = 0; col < w; ++col) {
      const double d = depth.at(col, row);
      if (d > 0) {
        ++wet;
        wet_outside += !in(col, row);
        volume += d;
      }
      if (!in(col, row)) continue;
      bool edge = false;
      for (int dr = -1; dr <= 1; ++dr)
        for (int dc = -1; dc <= 1; ++dc) edge = edge || !in(col + dc, row + dr);
      if (!edge) continue;
      ++boundary;
      if (dem.at(col, row) < spill) {
        spill = dem.at(col, row);
        spill_at = {dem.transform[0] + (col + 0.5) * dem.transform[1],
                    dem.transform[3] + (row + 0.5) * dem.transform[5]};
      }
    }
  for (int row = 0; row < h; ++row)
    for (int col = 0; col < w; ++col)
      if (depth.at(col, row) > 0)
        worst_depth =
            std::max(worst_depth, std::abs(spill - dem.at(col, row) - depth.at(col, row)));
  ASSERT_TRUE(t.inverse->Transform(1, &spill_at[0], &spill_at[1]));
  // rHEALPix cells are equal-area: a pixel of level 12's 256-sample tiles is the face's area over
  // its (2^20)^2 pixels.
  const double pixel_area = default_grid().area(0) / std::ldexp(1.0, 2 * 20);
  volume *= pixel_area;

  const auto store = Store::open(run.dir + "/example.mqt", Store::Mode::ReadOnly);
  const auto artifact = store->get_artifact("lakes");
  ASSERT_TRUE(artifact);
  const json bodies = json::parse(artifact->text());
  ASSERT_EQ(bodies.size(), 1u);
  const json& lake = bodies[0];
  std::printf(
      "spill level %.3f m at lon %.5f, lat %.5f (lowest of %d boundary pixels; the crest %.1f m), "
      "the lake's %.3f m; %d wet pixels, %.4g m2, %.5g m3; depth = level - terrain within %.2g m\n",
      spill, spill_at[0], spill_at[1], boundary, crest, lake["level"].get<double>(), wet,
      wet * pixel_area, volume, worst_depth);
  std::printf("the bodies' artifact: %.4g m2, %.5g m3\n", lake["area_m2"].get<double>(),
              lake["volume_m3"].get<double>());
  // Every tile's wet pixels counted, that of a cell the polygon's edge crosses with no vertex in
  // it included (the stroke delivered there too): area and volume as summed on the export.
  EXPECT_NEAR(lake["area_m2"].get<double>(), wet * pixel_area, 1e-6 * wet * pixel_area);
  EXPECT_NEAR(lake["volume_m3"].get<double>(), volume, 1e-4 * volume);
  EXPECT_GT(boundary, 1000);
  EXPECT_NEAR(lake["level"].get<double>(), spill, 1e-3);
  // The water spills over the embankment: the level is its crest within the fit's ringing.
  EXPECT_NEAR(spill, crest, 1.0);
  EXPECT_GT(wet, 10000);
  EXPECT_GT(volume, 1e6);
  EXPECT_EQ(wet_outside, 0);
  EXPECT_LE(worst_depth, 1e-3);
}

}  // namespace
}  // namespace maquette::test
