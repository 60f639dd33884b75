// synthesis.clone run by the real program. The oracle: a checkerboard draped on a
// two-slope terrain (flat, then 30 degrees rising east; GeoTIFFs written with GDAL), seen from
// above (the imagery layer), cloned from the flat part onto the slope by an offset in metres: the
// cloned squares' ground area, measured through the DEM's heights and GeographicLib's distances,
// within 2 % of the source squares'. The same tile bytes on one thread and two; a destination
// missing or given twice, and a source that is no polygon, are refused naming them.
#include <gtest/gtest.h>
#include <unistd.h>

#include <GeographicLib/Geodesic.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>

#include "core/halo.h"
#include "core/mosaic_geometry.h"
#include "core/tile.h"
#include "ring_feature.h"
#include "run_cli.h"
#include "store/store.h"
#include "synthetic_raster.h"

namespace maquette::synthesis {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// At the equator in the middle of an rHEALPix face: samples of ~35 m at level 10, east along
// columns, south along rows.
constexpr double kWest = 45.0, kCrease = 45.05, kSquareDeg = 0.004, kSlopeDeg = 30;
constexpr double kRasterPixelDeg = 0.0001;
constexpr int kRasterSize = 1200;                          // 45.0..45.12, -0.06..0.06
const double kDegreeM = 6378137 * std::numbers::pi / 180;  // along the equator

// The terrain: flat west of the crease, rising east at 30 degrees beyond it.
double terrain_height(double lon) {
  return lon <= kCrease ? 0
                        : (lon - kCrease) * kDegreeM * std::tan(kSlopeDeg * std::numbers::pi / 180);
}

// The source: 2.2 km square on the flat part, moved 6 km east onto the slope.
constexpr double kSourceWest = 45.008, kSourceEast = 45.028, kSourceHalf = 0.01;
constexpr double kOffsetEastM = 6000;

std::string polygon(const std::string& type) {
  const json ring = {{kSourceWest, -kSourceHalf},
                     {kSourceEast, -kSourceHalf},
                     {kSourceEast, kSourceHalf},
                     {kSourceWest, kSourceHalf},
                     {kSourceWest, -kSourceHalf}};
  return test::ring_feature(ring, type);
}

// The imagery: squares of grey 200 and 40.
double checker(double lon, double lat) {
  const long i = std::lround(std::floor((lon - kWest) / kSquareDeg)) +
                 std::lround(std::floor(lat / kSquareDeg));
  return i % 2 != 0 ? 200.0 : 40.0;
}

// The land cover: on the flat part the checkerboard's squares as classes 90 (its bright squares)
// and 11, on the slope class 41.
double land_cover(double lon, double lat) {
  return lon > kCrease ? 41 : checker(lon, lat) > 120 ? 90 : 11;
}

struct CloneRun {
  fs::path dir;
  std::string store;
  test::CliResult result;
};

// `clone_inputs` and `clone_params` complete the clone step.
CloneRun run_clone(const std::string& name, int threads, const json& clone_inputs,
                   const json& clone_params, const std::string& type = "Polygon",
                   const json& clone_outputs = {{"rgb", "cloned"}}) {
  CloneRun run{
      fs::temp_directory_path() / ("maquette-clone-" + std::to_string(getpid()) + name), "", {}};
  fs::remove_all(run.dir);
  fs::create_directories(run.dir);
  run.store = (run.dir / "slopes.mqt").string();
  const auto raster = [](const char* type, int bands) {
    test::RasterSpec spec = test::lonlat_raster(kWest, kRasterSize * kRasterPixelDeg / 2,
                                                kRasterSize, kRasterPixelDeg, type);
    spec.bands = bands;
    return spec;
  };
  test::write_raster((run.dir / "dem.tif").string(), raster("Float32", 1),
                     [](int, double lon, double) { return terrain_height(lon); });
  test::write_raster((run.dir / "checker.tif").string(), raster("Byte", 3),
                     [](int, double lon, double lat) { return checker(lon, lat); });
  test::write_raster((run.dir / "classes.tif").string(), raster("Byte", 1),
                     [](int, double lon, double lat) { return land_cover(lon, lat); });
  std::ofstream(run.dir / "source.geojson") << polygon(type);
  json inputs = {{"image", "checker"}, {"source", "source"}};
  inputs.update(clone_inputs);
  const auto ingest = [&](const char* file, const char* layer, const char* as) {
    return json{{"op", "ingest"},
                {"outputs", {{"layer", layer}}},
                {"params", {{"sources", {(run.dir / file).string()}}, {"as", as}, {"level", 10}}}};
  };
  const json pipeline = {{"store", run.store},
                         {"region", {{"bbox", {kWest, -0.03, 45.12, 0.03}}}},
                         {"level", 10},
                         {"steps",
                          {ingest("dem.tif", "dem", "dem"),
                           ingest("checker.tif", "checker", "imagery"),
                           ingest("classes.tif", "landcover", "landcover"),
                           ingest("source.geojson", "source", "features"),
                           {{"op", "synthesis.clone"},
                            {"inputs", inputs},
                            {"params", clone_params},
                            {"outputs", clone_outputs}}}}};
  std::ofstream(run.dir / "pipeline.json") << pipeline.dump(1);
  run.result = test::run_maquette("run " + (run.dir / "pipeline.json").string() +
                                  " --quiet --threads " + std::to_string(threads));
  return run;
}

// A layer's first channel by global face pixel (col, row).
std::map<std::pair<int64_t, int64_t>, float> first_channel(const Store& store,
                                                           const std::string& layer, int& face,
                                                           int& pixel_level) {
  std::map<std::pair<int64_t, int64_t>, float> out;
  for (const CellId cell : store.tile_cells(layer)) {
    const RawTile tile = *store.get_tile(layer, cell);
    const int n = tile.size;
    face = cell.face(), pixel_level = cell.level() + log2_tile_size(n);
    for (int row = 0; row < n; ++row) {
      for (int col = 0; col < n; ++col) {
        out[{global_col(cell, n, col), global_row(cell, n, row)}] =
            float(std::to_integer<uint8_t>(tile.bytes[(size_t(row) * n + col) * 3]));
      }
    }
  }
  return out;
}

// A float32 layer's first channel by global face pixel (col, row).
std::map<std::pair<int64_t, int64_t>, float> first_channel_f32(const Store& store,
                                                               const std::string& layer, int& face,
                                                               int& pixel_level) {
  std::map<std::pair<int64_t, int64_t>, float> out;
  for (const CellId cell : store.tile_cells(layer)) {
    const Tile<float> tile = to_tile<float>(*store.get_tile(layer, cell));
    const int n = tile.size();
    face = cell.face(), pixel_level = cell.level() + log2_tile_size(n);
    for (int row = 0; row < n; ++row) {
      for (int col = 0; col < n; ++col) {
        out[{global_col(cell, n, col), global_row(cell, n, row)}] = tile.at(col, row, 0);
      }
    }
  }
  return out;
}

// The mean side of the squares along a line of samples through `centre` (fractional global
// pixel), `reach` samples either way, along columns (east) or rows: between the first and last
// crossings of 120, linearly interpolated, in ground metres (GeographicLib's distance on WGS84
// and the terrain's rise).
double square_side_m(const std::map<std::pair<int64_t, int64_t>, float>& values, int face,
                     int level, std::array<double, 2> centre, bool east, int reach) {
  const int64_t c = std::lround(centre[0]), r = std::lround(centre[1]);
  std::vector<LonLat> crossings;
  for (int i = -reach; i < reach; ++i) {
    const auto at = [&](int k) {
      return double(values.at(east ? std::pair{c + k, r} : std::pair{c, r + k})) - 120;
    };
    const double a = at(i), b = at(i + 1);
    if ((a < 0) == (b < 0)) continue;
    const double t = i + a / (a - b);
    crossings.push_back(face_point_lonlat(default_grid(), face, east ? c + t : double(c),
                                          east ? double(r) : r + t, level));
  }
  if (crossings.size() < 3) return NAN;
  const LonLat p = crossings.front(), q = crossings.back();
  double horizontal = 0;
  GeographicLib::Geodesic::WGS84().Inverse(p.lat, p.lon, q.lat, q.lon, horizontal);
  return std::hypot(horizontal, terrain_height(q.lon) - terrain_height(p.lon)) /
         double(crossings.size() - 1);
}

// The source's centre moved `east_m` east (in degrees at the equator), as a fractional global
// pixel of `face` at `level`.
std::array<double, 2> source_centre(int face, int level, double east_m) {
  const MosaicGeometry samples(default_grid(), face, level, 0, 0);
  return *samples.sample({(kSourceWest + kSourceEast) / 2 + east_m / kDegreeM, 0});
}

// The sample nearest the centre of the copy `offset_m` [kOffsetEastM, 0] puts on the slope.
std::pair<int64_t, int64_t> copy_centre(int face, int level) {
  const auto to = source_centre(face, level, kOffsetEastM);
  return {std::lround(to[0]), std::lround(to[1])};
}

TEST(CloneOperator, ACheckerboardClonedOntoA30DegreeSlopeKeepsItsGroundAreaSameBitsOnTwoThreads) {
  const json params = {{"offset_m", {kOffsetEastM, 0}}};
  const CloneRun one = run_clone("-1", 1, {{"dem", "dem"}}, params);
  const CloneRun two = run_clone("-2", 2, {{"dem", "dem"}}, params);
  ASSERT_EQ(one.result.exit_code, 0) << one.result.err;
  ASSERT_EQ(two.result.exit_code, 0) << two.result.err;
  const auto a = Store::open(one.store, Store::Mode::ReadOnly);
  const auto b = Store::open(two.store, Store::Mode::ReadOnly);
  const auto cells = a->tile_cells("cloned");
  ASSERT_GE(cells.size(), 2u);
  for (const CellId cell : cells) {
    EXPECT_EQ(a->get_tile("cloned", cell)->bytes, b->get_tile("cloned", cell)->bytes)
        << cell.ToText();
  }
  int face = 0, level = 0;
  const auto before = first_channel(*a, "checker", face, level);
  const auto after = first_channel(*a, "cloned", face, level);
  const auto source = source_centre(face, level, 0);
  const auto destination = source_centre(face, level, kOffsetEastM);
  // The source is ~63 samples a side; its copy ~55 wide on the slope: measured inside the band.
  const double source_area = square_side_m(before, face, level, source, true, 26) *
                             square_side_m(before, face, level, source, false, 26);
  const double width = square_side_m(after, face, level, destination, true, 22);
  const double height = square_side_m(after, face, level, destination, false, 26);
  EXPECT_NEAR(width * height / source_area, 1, 0.02)
      << width << " x " << height << " m, the source's squares " << std::sqrt(source_area);
  fs::remove_all(one.dir);
  fs::remove_all(two.dir);
}

TEST(CloneOperator, ADestinationMissingOrGivenTwiceAndASourceThatIsNoPolygonAreNamed) {
  const auto error = [](const CloneRun& run) {
    EXPECT_NE(run.result.exit_code, 0);
    fs::remove_all(run.dir);
    return run.result.err;
  };
  // The place told when the pipeline is read, before the ingest steps run (no store is made).
  const auto refused_when_read = [&](const CloneRun& run) {
    EXPECT_FALSE(fs::exists(run.store));
    return error(run);
  };
  const std::string both =
      "step 5 (synthesis.clone): inputs.destination, params.offset_m: give one of them";
  EXPECT_NE(refused_when_read(run_clone("-none", 1, json::object(), json::object())).find(both),
            std::string::npos);
  EXPECT_NE(refused_when_read(
                run_clone("-twice", 1, {{"destination", "source"}}, {{"offset_m", {100, 0}}}))
                .find(both),
            std::string::npos);
  EXPECT_NE(refused_when_read(
                run_clone("-even", 1, json::object(), {{"offset_m", {100, 0}}, {"patch", 8}}))
                .find("step 5 (synthesis.clone): params.patch: 8 is even; give an odd side"),
            std::string::npos);
  EXPECT_NE(error(run_clone("-line", 1, json::object(), {{"offset_m", {100, 0}}}, "LineString"))
                .find("inputs.source: feature 1 is a LineString, not a Polygon or MultiPolygon"),
            std::string::npos);
}

// Review K-S1: the runner keeps only the region's cells, so a copy reaching the context around
// them is refused naming the offset, not cut silently; a heights output without its DEM is named.
TEST(CloneOperator, ACopyLandingBeyondTheRegionsCellsOrAnOutputWithoutItsInputIsNamed) {
  const CloneRun plain = run_clone("-plain", 1, json::object(), {{"offset_m", {3000, 0}}});
  ASSERT_EQ(plain.result.exit_code, 0) << plain.result.err;
  const auto store = Store::open(plain.store, Store::Mode::ReadOnly);
  int64_t east = 0;  // the first global column east of the region's cells
  int face = 0, level = 0;
  for (const CellId cell : store->tile_cells("cloned")) {
    const int n = store->get_tile("cloned", cell)->size;
    face = cell.face(), level = cell.level() + log2_tile_size(n);
    east = std::max(east, global_col(cell, n, n - 1) + 1);
  }
  const double centre_lon = (kSourceWest + kSourceEast) / 2;
  const auto source = source_centre(face, level, 0);
  // The copy's centre 10 samples west of that edge: its eastern ~20 samples in the context.
  const LonLat edge = face_point_lonlat(default_grid(), face, double(east - 10), source[1], level);
  const json params = {{"offset_m", {(edge.lon - centre_lon) * kDegreeM, 0}}};
  const CloneRun ring = run_clone("-ring", 1, json::object(), params);
  EXPECT_NE(ring.result.exit_code, 0);
  EXPECT_NE(ring.result.err.find("params.offset_m: "), std::string::npos) << ring.result.err;
  EXPECT_NE(ring.result.err.find("samples land outside the region's cells"), std::string::npos)
      << ring.result.err;
  // 10 samples further west it lands inside them: accepted.
  const LonLat inside =
      face_point_lonlat(default_grid(), face, double(east - 45), source[1], level);
  const CloneRun fits = run_clone("-fits", 1, json::object(),
                                  {{"offset_m", {(inside.lon - centre_lon) * kDegreeM, 0}}});
  EXPECT_EQ(fits.result.exit_code, 0) << fits.result.err;
  const CloneRun no_dem = run_clone("-nodem", 1, json::object(), {{"offset_m", {3000, 0}}},
                                    "Polygon", {{"heights", "cloned_dem"}});
  EXPECT_NE(no_dem.result.exit_code, 0);
  EXPECT_NE(no_dem.result.err.find(
                "outputs.heights: synthesis.clone makes it from inputs.dem, which the step does "
                "not map"),
            std::string::npos)
      << no_dem.result.err;
  for (const auto* run : {&plain, &ring, &fits, &no_dem}) fs::remove_all(run->dir);
}

// A DEM cloned by the real program: the flat source's heights (0 m) land on the 30 degree slope
// as one block moved to the mean height of the slope under the copy's edge, the imagery cloned
// beside it the same.
TEST(CloneOperator, AFlatTerrainPatchClonedOntoTheSlopeMeetsItsMeanHeight) {
  const CloneRun run = run_clone("-heights", 1, {{"dem", "dem"}}, {{"offset_m", {kOffsetEastM, 0}}},
                                 "Polygon", {{"rgb", "cloned"}, {"heights", "cloned_dem"}});
  ASSERT_EQ(run.result.exit_code, 0) << run.result.err;
  const auto store = Store::open(run.store, Store::Mode::ReadOnly);
  int face = 0, level = 0;
  const auto dem = first_channel_f32(*store, "dem", face, level);
  const auto cloned = first_channel_f32(*store, "cloned_dem", face, level);
  const auto [c, r] = copy_centre(face, level);
  // The copy's middle (its band is 3 samples wide at the edge, ~27 samples away): one height.
  const float middle = cloned.at({c, r});
  double low = 1e30, high = -1e30;
  for (int64_t dr = -15; dr <= 15; ++dr) {
    for (int64_t dc = -15; dc <= 15; ++dc) {
      low = std::min(low, double(cloned.at({c + dc, r + dr})));
      high = std::max(high, double(cloned.at({c + dc, r + dr})));
    }
  }
  std::cout << "cloned heights: " << low << ".." << high << " m, the slope under the centre "
            << dem.at({c, r}) << " m\n";
  EXPECT_LE(high - low, 1e-3);
  // The slope under the copy's centre (the mean under its symmetric edge on a plane): measured
  // 1409.17 m against 1408.99 m.
  EXPECT_NEAR(middle, dem.at({c, r}), 1) << "the slope there " << dem.at({c, r});
  // Beyond the copy and its band, the DEM as it was.
  EXPECT_EQ(cloned.at({c + 60, r}), dem.at({c + 60, r}));
  fs::remove_all(run.dir);
}

// Land cover cloned by the real program beside the imagery (review C-R-S2), onto the slope with
// the DEM: a uint16 categorical layer; inside the copy every sample is the class of the cloned
// imagery's square there (both layers copied through the same resize: 90 where the imagery is
// bright, 11 where dark); only the classes 11, 41 and 90 where there was land cover (an average
// of codes would be neither); beyond the copy and its band the land cover as it was.
TEST(CloneOperator, LandCoverIsClonedAsClassesThroughTheImagerysMap) {
  const CloneRun run = run_clone("-classes", 2, {{"dem", "dem"}, {"landcover", "landcover"}},
                                 {{"offset_m", {kOffsetEastM, 0}}}, "Polygon",
                                 {{"rgb", "cloned"}, {"classes", "cloned_classes"}});
  ASSERT_EQ(run.result.exit_code, 0) << run.result.err;
  const auto store = Store::open(run.store, Store::Mode::ReadOnly);
  const LayerInfo info = store->require_layer("cloned_classes");
  EXPECT_EQ(info.dtype, DType::U16);
  EXPECT_EQ(info.semantics, Semantics::Categorical);
  int face = 0, level = 0;
  const auto imagery = first_channel(*store, "cloned", face, level);
  const auto before = first_channel_f32(*store, "landcover", face, level);
  const auto classes = first_channel_f32(*store, "cloned_classes", face, level);
  const auto [c, r] = copy_centre(face, level);
  size_t inside = 0, agree = 0, other = 0, changed_beyond = 0;
  const auto is_class = [](float k) { return k == 11 || k == 41 || k == 90; };
  for (const auto& [at, k] : classes) {
    if (!is_class(before.at(at))) continue;  // beyond the GeoTIFF: no land cover
    other += !is_class(k);
    const int64_t dc = std::abs(at.first - c), dr = std::abs(at.second - r);
    if (dc <= 20 && dr <= 25) {  // inside the copy (~55 x 63 samples), clear of its band
      ++inside;
      agree += k == (imagery.at(at) > 120 ? 90 : 11);
    } else if (dc > 45 || dr > 45) {
      changed_beyond += k != before.at(at);
    }
  }
  std::cout << "cloned land cover: " << agree << " of " << inside
            << " samples in the copy the class of the cloned imagery's square\n";
  EXPECT_GT(inside, 1500u);
  EXPECT_GE(double(agree), 0.95 * double(inside));
  EXPECT_EQ(other, 0u);
  EXPECT_EQ(changed_beyond, 0u);
  fs::remove_all(run.dir);
}

}  // namespace
}  // namespace maquette::synthesis
