// Features ports (runtime/operator.h: InputSpec::kind, reach_m) through the real program: strokes
// written by the test as GeoJSON, ingested with `maquette ingest --as features`, delivered by
// `maquette run` to the fixture operators (tests/modules_fixture/fixture_features.cpp), which
// write per cell the count, id sum and "w" sum of the features they were given. The oracle: GEOS
// distances (OGR's Distance) between the cells' outlines and the features on an azimuthal
// equidistant copy made by PROJ (edges cut in lon/lat first, as the runtime takes them
// straight in lon/lat). Same bits with 1 and 2 threads and with 1 and 2 MPI ranks.
#include <gdal_priv.h>
#include <gtest/gtest.h>
#include <ogr_geometry.h>
#include <ogr_spatialref.h>
#include <ogrsf_frmts.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "core/geo_distance.h"
#include "core/geometry.h"
#include "core/grid.h"
#include "core/polygon_set.h"
#include "run_cli.h"
#include "store/store.h"
#include "test_util.h"
#include "vector/ogr_source.h"

namespace maquette {
namespace {

using nlohmann::json;
using test::CliResult;
using test::run_maquette;

constexpr int kLevel = 12;       // cells of about 2.4 km
constexpr double kReach = 1000;  // fixture.near_features' reach_m (fixture_features.h)
const std::vector<double> kBox = {10.0, 45.0, 10.1, 45.1};
const LonLat kCentre{10.05, 45.05};
const std::string kEnv =
    std::string("MAQUETTE_MODULE_PATH=") + MAQUETTE_FIXTURE_MODULE_DIR + "/good";

// Lon/lat <-> an azimuthal equidistant plane centred on the region (metres), by PROJ.
class Plane {
 public:
  Plane() {
    wgs_.SetWellKnownGeogCS("WGS84");
    wgs_.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    aeqd_.importFromProj4(("+proj=aeqd +lat_0=" + std::to_string(kCentre.lat) +
                           " +lon_0=" + std::to_string(kCentre.lon) + " +datum=WGS84 +units=m")
                              .c_str());
    to_.reset(OGRCreateCoordinateTransformation(&wgs_, &aeqd_));
    from_.reset(OGRCreateCoordinateTransformation(&aeqd_, &wgs_));
  }
  // A lon/lat geometry cut into pieces of 0.001 degrees, then projected.
  std::unique_ptr<OGRGeometry> project(const OGRGeometry& lonlat) const {
    std::unique_ptr<OGRGeometry> g(lonlat.clone());
    g->segmentize(0.001);
    EXPECT_EQ(g->transform(to_.get()), OGRERR_NONE);
    return g;
  }
  LonLat lonlat(double x, double y) const {
    double lon = x, lat = y;
    EXPECT_TRUE(from_->Transform(1, &lon, &lat));
    return {lon, lat};
  }
  OGRPoint xy(LonLat p) const {
    double x = p.lon, y = p.lat;
    EXPECT_TRUE(to_->Transform(1, &x, &y));
    return OGRPoint(x, y);
  }

 private:
  OGRSpatialReference wgs_, aeqd_;
  std::unique_ptr<OGRCoordinateTransformation> to_, from_;
};

const Plane& plane() {
  static const Plane p;
  return p;
}

// The cell's outline (64 points an edge) on the plane.
std::unique_ptr<OGRGeometry> cell_polygon(CellId cell) {
  OGRLinearRing ring;
  for (const LonLat& p : default_grid().boundary(cell, 64)) ring.addPoint(p.lon, p.lat);
  OGRPolygon polygon;
  polygon.addRing(&ring);
  return plane().project(polygon);
}

std::vector<CellId> region_cells() {
  return default_grid().cover_bbox(kBox[0], kBox[1], kBox[2], kBox[3], kLevel,
                                   Containment::Overlap);
}

// Deterministic pseudo-random numbers in [0, 1).
struct Lcg {
  uint64_t state = 12345;
  double next() {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return double(state >> 11) / double(1ull << 53);
  }
};

json position(LonLat p) { return json::array({p.lon, p.lat}); }

// Points, lines (with Z), polygons (one with a hole) and Multi* around and beyond the region,
// with ids 1.. (the ingest's fids: positions in the file) and "w" attributes; then two points 1 m
// inside and 1 m beyond the reach of the cell at the region's centre (ids near_id, far_id).
struct Strokes {
  json collection;
  int64_t near_id = 0, far_id = 0;
};

Strokes make_strokes() {
  Lcg rng;
  auto random_point = [&] {
    return LonLat{kBox[0] - 0.1 + 0.3 * rng.next(), kBox[1] - 0.1 + 0.3 * rng.next()};
  };
  json features = json::array();
  auto add = [&](json geometry) {
    const int64_t id = int64_t(features.size()) + 1;
    features.push_back({{"type", "Feature"},
                        {"id", id},
                        {"properties", {{"w", 0.25 * double(id)}, {"tool", "feature"}}},
                        {"geometry", geometry}});
    return id;
  };
  for (int i = 0; i < 8; ++i) add({{"type", "Point"}, {"coordinates", position(random_point())}});
  for (int i = 0; i < 5; ++i) {
    json line = json::array();
    LonLat p = random_point();
    for (int k = 0; k < 4; ++k) {
      line.push_back({p.lon, p.lat, 100.0 * k});
      p = {p.lon + 0.02 * (rng.next() - 0.5), p.lat + 0.02 * (rng.next() - 0.5)};
    }
    add({{"type", "LineString"}, {"coordinates", line}});
  }
  auto square = [](LonLat c, double half) {
    return json::array(
        {position({c.lon - half, c.lat - half}), position({c.lon + half, c.lat - half}),
         position({c.lon + half, c.lat + half}), position({c.lon - half, c.lat + half}),
         position({c.lon - half, c.lat - half})});
  };
  for (int i = 0; i < 3; ++i)
    add({{"type", "Polygon"}, {"coordinates", json::array({square(random_point(), 0.004)})}});
  // A large square with a hole holding some cells: those are near its inner ring only.
  add({{"type", "Polygon"},
       {"coordinates", {square({10.03, 45.07}, 0.03), square({10.03, 45.07}, 0.018)}}});
  add({{"type", "MultiPoint"},
       {"coordinates", {position(random_point()), position(random_point())}}});
  add({{"type", "MultiLineString"},
       {"coordinates",
        {{position(random_point()), position(random_point())},
         {position(random_point()), position(random_point())}}}});
  add({{"type", "Point"}, {"coordinates", position({11.5, 46.0})}});  // far from everything

  // Points east (near) and west (far) of the centre cell at kReach -+ 1 m, found on the plane.
  const CellId centre = default_grid().cell_from_point(kCentre, kLevel);
  const auto outline = cell_polygon(centre);
  const OGRPoint c = plane().xy(default_grid().centre(centre));
  auto at_distance = [&](double sign, double target) {
    double t = target + 1500;
    for (int i = 0; i < 8; ++i) {
      const OGRPoint p(c.getX() + sign * t, c.getY());
      t += target - outline->Distance(&p);
    }
    return plane().lonlat(c.getX() + sign * t, c.getY());
  };
  Strokes s;
  s.near_id = add({{"type", "Point"}, {"coordinates", position(at_distance(1, kReach - 1))}});
  s.far_id = add({{"type", "Point"}, {"coordinates", position(at_distance(-1, kReach + 1))}});
  s.collection = {{"type", "FeatureCollection"}, {"features", features}};
  return s;
}

const Strokes& strokes() {
  static const Strokes s = make_strokes();
  return s;
}

struct Expected {
  double count = 0, ids = 0, w = 0;
};

// The oracle: per region cell, what the features within kReach of it add up to, and the ids of
// the features within kReach of some region cell. Distances within 5 cm of kReach (other than
// the two placed at 1 m) would make the data ambiguous for a measure of centimetre accuracy.
struct Oracle {
  std::map<CellId, Expected> cells;  // cells with at least one feature
  std::set<int64_t> near_region;
  std::map<int64_t, double> centre_cell_distance;  // by feature id
};

// The strokes written as GeoJSON in `dir` and read back through GDAL's own reader
// (formats/vector's open_vector). Under ThreadSanitizer, GDAL's driver manager takes its two
// mutexes in both orders inside Open and the report's stack ends at open_vector or its caller,
// this function: scripts/tsan-suppressions.txt names both.
VectorDataset open_strokes(const test::TempDir& dir) {
  const std::string path = dir.file("strokes.geojson");
  std::ofstream(path) << strokes().collection.dump();
  return open_vector(path);
}

Oracle compute_oracle(GDALDataset& ds) {
  struct F {
    int64_t id;
    double w;
    std::unique_ptr<OGRGeometry> geometry;
  };
  std::vector<F> features;
  int64_t position = 0;
  for (const auto& f : *ds.GetLayer(0))
    features.push_back(
        {++position, f->GetFieldAsDouble("w"), plane().project(*f->GetGeometryRef())});
  Oracle o;
  const CellId centre = default_grid().cell_from_point(kCentre, kLevel);
  for (const CellId cell : region_cells()) {
    const auto outline = cell_polygon(cell);
    for (const F& f : features) {
      const double d = outline->Distance(f.geometry.get());
      if (cell == centre) o.centre_cell_distance[f.id] = d;
      if (f.id != strokes().near_id && f.id != strokes().far_id) {
        EXPECT_GT(std::abs(d - kReach), 0.05) << "feature " << f.id << ", cell " << cell.ToText();
      }
      if (d > kReach) continue;
      Expected& e = o.cells[cell];
      e.count += 1;
      e.ids += double(f.id);
      e.w += f.w;
      o.near_region.insert(f.id);
    }
  }
  return o;
}

// A directory with the strokes ingested into out.mqt (layer "strokes") and the oracle.
struct StoreDir {
  test::TempDir dir;
  std::string store = dir.file("out.mqt");
};

const Oracle& oracle() {
  static const Oracle o = [] {
    const test::TempDir dir;
    const VectorDataset ds = open_strokes(dir);
    return compute_oracle(*ds);
  }();
  return o;
}

void ingest(const StoreDir& s) {
  std::ofstream(s.dir.file("strokes.geojson")) << strokes().collection.dump();
  const CliResult r = run_maquette("-q ingest " + s.store + " --layer strokes --as features " +
                                   s.dir.file("strokes.geojson"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
}

json pipeline(const json& steps) {
  return {{"store", "out.mqt"},
          {"region", {{"bbox", kBox}}},
          {"level", kLevel},
          {"tile_size", 4},
          {"steps", steps}};
}

const json kNearStep = {{"op", "fixture.near_features"},
                        {"inputs", {{"strokes", "strokes"}}},
                        {"outputs", {{"near", "near"}}}};

CliResult run(const StoreDir& s, const json& steps, const std::string& options = "") {
  std::ofstream(s.dir.file("pipeline.json")) << pipeline(steps).dump(2);
  return run_maquette("-q run " + options + " " + s.dir.file("pipeline.json"), kEnv);
}

// Every tile of `layer`: channel k of its first sample, checked equal in every sample.
std::map<CellId, std::vector<float>> tile_values(const std::string& store,
                                                 const std::string& layer) {
  const auto st = Store::open(store, Store::Mode::ReadOnly);
  std::map<CellId, std::vector<float>> out;
  for (const CellId cell : st->tile_cells(layer)) {
    const Tile<float> t = to_tile<float>(*st->get_tile(layer, cell));
    std::vector<float>& v = out[cell];
    for (int k = 0; k < t.channels(); ++k) {
      v.push_back(t.at(0, 0, k));
      for (int r = 0; r < t.size(); ++r)
        for (int c = 0; c < t.size(); ++c) EXPECT_EQ(t.at(c, r, k), v[k]) << cell.ToText();
    }
  }
  return out;
}

void expect_matches_oracle(const std::map<CellId, std::vector<float>>& got) {
  for (const auto& [cell, v] : got) {
    const auto it = oracle().cells.find(cell);
    const Expected e = it == oracle().cells.end() ? Expected{} : it->second;
    EXPECT_EQ(v[0], float(e.count)) << cell.ToText();
    EXPECT_EQ(v[1], float(e.ids)) << cell.ToText();
    EXPECT_EQ(v[2], float(e.w)) << cell.ToText();
  }
}

TEST(FeaturesPort, CellsGetTheFeaturesWithinReach) {
  ASSERT_TRUE(OGRGeometryFactory::haveGEOS());
  const Oracle& o = oracle();
  // The data covers every case: cells with and without features, features out of reach.
  ASSERT_GT(o.cells.size(), 10u);
  ASSERT_LT(o.cells.size(), region_cells().size());
  ASSERT_LT(o.near_region.size(), size_t(strokes().far_id));
  // The placed points: 1 m inside and 1 m beyond the reach of the centre cell.
  EXPECT_NEAR(o.centre_cell_distance.at(strokes().near_id), kReach - 1, 1e-3);
  EXPECT_NEAR(o.centre_cell_distance.at(strokes().far_id), kReach + 1, 1e-3);

  StoreDir s;
  ingest(s);
  const CliResult r = run(s, json::array({kNearStep}), "--threads 1");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto got = tile_values(s.store, "near");
  // A step reading only features runs on the region's cells within reach of a feature.
  std::set<CellId> cells, expected_cells;
  for (const auto& [cell, v] : got) cells.insert(cell);
  for (const auto& [cell, e] : o.cells) expected_cells.insert(cell);
  EXPECT_EQ(cells, expected_cells);
  expect_matches_oracle(got);
  // The centre cell got the near point and not the far one.
  const CellId centre = default_grid().cell_from_point(kCentre, kLevel);
  const Expected& e = o.cells.at(centre);
  EXPECT_EQ(got.at(centre)[1], float(e.ids));
  double ids_without_placed = 0;
  for (const auto& [id, d] : o.centre_cell_distance)
    if (d <= kReach && id != strokes().near_id) ids_without_placed += double(id);
  EXPECT_EQ(e.ids, ids_without_placed + double(strokes().near_id));
}

TEST(FeaturesPort, ARasterInputDecidesTheCells) {
  StoreDir s;
  ingest(s);
  const json fill = {
      {"op", "fixture.fill"}, {"outputs", {{"value", "height"}}}, {"params", {{"seed", 1}}}};
  json near = kNearStep;
  near["inputs"]["src"] = "height";
  const CliResult r = run(s, {fill, near});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto got = tile_values(s.store, "near");
  EXPECT_EQ(got.size(), region_cells().size());  // zeros where no feature is within reach
  expect_matches_oracle(got);
}

// Features ingested by an earlier step of the same pipeline are not known when planning: the step
// runs on all the region's cells and reads them when it starts.
TEST(FeaturesPort, FeaturesIngestedByAnEarlierStep) {
  StoreDir s;
  std::ofstream(s.dir.file("strokes.geojson")) << strokes().collection.dump();
  const json ingest_step = {{"op", "ingest"},
                            {"outputs", {{"layer", "strokes"}}},
                            {"params", {{"sources", {"strokes.geojson"}}, {"as", "features"}}}};
  const CliResult r = run(s, json::array({ingest_step, kNearStep}));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto got = tile_values(s.store, "near");
  EXPECT_EQ(got.size(), region_cells().size());
  expect_matches_oracle(got);
}

TEST(FeaturesPort, RegionOperatorsGetTheRegionsFeatures) {
  StoreDir s;
  ingest(s);
  const CliResult r = run(s, {{{"op", "fixture.region_features"},
                               {"inputs", {{"strokes", "strokes"}}},
                               {"outputs", {{"near", "near"}}}}});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto got = tile_values(s.store, "near");
  EXPECT_EQ(got.size(), oracle().cells.size());
  for (const auto& [cell, v] : got)
    EXPECT_EQ(v[0], float(oracle().near_region.size())) << cell.ToText();
}

TEST(FeaturesPort, ReduceOperatorsMapTheCellsFeatures) {
  StoreDir s;
  ingest(s);
  const CliResult r = run(s, json::array({{{"op", "fixture.features_total"},
                                           {"inputs", {{"strokes", "strokes"}}},
                                           {"outputs", {{"near", "total"}}}}}));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  double expected = 0;
  for (const auto& [cell, e] : oracle().cells) expected += e.count;
  const auto artifact = Store::open(s.store, Store::Mode::ReadOnly)->get_artifact("total");
  ASSERT_TRUE(artifact);
  EXPECT_EQ(json::parse(artifact->text()), expected);
}

TEST(FeaturesPort, ThreadsAndRanksGiveTheSameBits) {
  StoreDir one;
  ingest(one);
  const CliResult r1 = run(one, json::array({kNearStep}), "--threads 1");
  ASSERT_EQ(r1.exit_code, 0) << r1.err;
  const test::Snapshot expected = test::snapshot(one.store);
  ASSERT_GT(expected.size(), oracle().cells.size());  // tiles and overviews

  StoreDir two;
  ingest(two);
  const CliResult r = run(two, json::array({kNearStep}), "--threads 2");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(test::first_difference(test::snapshot(two.store), expected), "");
#ifdef MAQUETTE_MPIEXEC
  StoreDir ranks;
  ingest(ranks);
  std::ofstream(ranks.dir.file("pipeline.json")) << pipeline(json::array({kNearStep})).dump(2);
  const std::string command =
      std::string("env ") + kEnv + " " + MAQUETTE_MPIEXEC +
      " --oversubscribe --allow-run-as-root -x MAQUETTE_MODULE_PATH -np 2 " + MAQUETTE_BIN_DIR +
      "/maquette -q run --threads 1 " + ranks.dir.file("pipeline.json") + " 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0) << test::shell_output(command);
  EXPECT_EQ(test::first_difference(test::snapshot(ranks.store), expected), "");
#else
  GTEST_SKIP() << "built without MPI: 2 ranks not tested";
#endif
}

// Errors name the step, the port and the layer, before anything runs.
TEST(FeaturesPort, WrongKindsAreRefusedBeforeAnythingRuns) {
  StoreDir s;
  ingest(s);
  const json fill = {
      {"op", "fixture.fill"}, {"outputs", {{"value", "height"}}}, {"params", {{"seed", 1}}}};
  json near = kNearStep;
  near["inputs"]["strokes"] = "height";
  CliResult r = run(s, {fill, near});
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("step 2 (fixture.near_features): inputs.strokes: layer 'height' is a "
                       "raster layer, but the port takes a features layer"),
            std::string::npos)
      << r.err;
  r = run(s, {{{"op", "fixture.blur"},
               {"inputs", {{"src", "strokes"}}},
               {"outputs", {{"dst", "blurred"}}}}});
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("step 1 (fixture.blur): inputs.src: layer 'strokes' is a features layer, "
                       "but the port takes a raster layer"),
            std::string::npos)
      << r.err;
  const auto st = Store::open(s.store, Store::Mode::ReadOnly);
  for (const char* layer : {"height", "blurred"}) EXPECT_FALSE(st->layer(layer));
}

// parse_wkb keeps Z and the parts of Multi* geometries, as OGR writes them.
TEST(FeaturesPort, WkbParsesWithZ) {
  OGRGeometry* raw = nullptr;
  ASSERT_EQ(OGRGeometryFactory::createFromWkt(
                "MULTILINESTRING Z ((10 45 1, 10.1 45 2), (11 46 3, 11 46.5 4, 11.5 46.5 5))",
                nullptr, &raw),
            OGRERR_NONE);
  std::unique_ptr<OGRGeometry> g(raw);
  std::vector<std::byte> wkb(g->WkbSize());
  g->exportToWkb(wkbNDR, reinterpret_cast<unsigned char*>(wkb.data()), wkbVariantIso);
  const Geometry parsed = parse_wkb(wkb, "f");
  EXPECT_EQ(parsed.type, GeometryType::MultiLineString);
  EXPECT_TRUE(parsed.has_z);
  ASSERT_EQ(parsed.lines.size(), 2u);
  ASSERT_EQ(parsed.lines[1].size(), 3u);
  EXPECT_EQ(parsed.lines[1][2].lon, 11.5);
  EXPECT_EQ(parsed.lines[1][2].lat, 46.5);
  EXPECT_EQ(parsed.lines[1][2].z, 5);
  wkb.resize(wkb.size() - 1);
  EXPECT_EQ(test::error_of([&] { parse_wkb(wkb, "feature 3 of 'roads'"); }),
            "feature 3 of 'roads' has truncated WKB");
}

// A NaN coordinate reached a float-to-integer conversion in PolygonSet (UBSan), found by
// fuzz_strokes (fuzz/corpus/strokes/regress-*): refused, as the ingest refuses it.
TEST(FeaturesPort, WkbWithANonFiniteCoordinateIsRefused) {
  // ISO WKB, little endian: a LineString (type 2) or LineString Z (1002) of two points.
  auto line = [](uint32_t type, const std::vector<double>& xyz) {
    std::vector<std::byte> wkb(1 + 4 + 4 + 8 * xyz.size());
    wkb[0] = std::byte{1};
    const uint32_t points = 2;
    std::memcpy(wkb.data() + 1, &type, 4);
    std::memcpy(wkb.data() + 5, &points, 4);
    std::memcpy(wkb.data() + 9, xyz.data(), 8 * xyz.size());
    return wkb;
  };
  EXPECT_NO_THROW(parse_wkb(line(2, {0, 0, 1, 1}), "f"));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (const auto& wkb : {line(2, {0, 0, 1, nan}), line(1002, {0, 0, 1, 1, 1, inf})})
    EXPECT_EQ(test::error_of([&] { parse_wkb(wkb, "feature 3 of 'lakes'"); }),
              "feature 3 of 'lakes' has a coordinate that is not finite");
  // Found by fuzz_strokes (UBSan: a vegetation stroke's NaN latitude converted to an integer).
  EXPECT_NO_THROW(parse_wkb(line(2, {0, -90, 1, 90}), "f"));
  EXPECT_EQ(test::error_of([&] {
              parse_wkb(line(2, {0, 0, 1, -90.5}), "feature 3 of 'lakes'");
            }),
            "feature 3 of 'lakes' has a latitude of -90.500000 degrees");
}

// Found by fuzz_strokes (UBSan): a polygon so flat (a subnormal extent in latitude) that its
// bands per degree are infinite put its south edge in band NaN (0 * inf).
TEST(FeaturesPort, PolygonSetOfSubnormalHeightAgreesWithItsRings) {
  const double tiny = std::numeric_limits<double>::denorm_min();
  const PolygonRings square{{{0, 0}, {1, 0}, {1, tiny}, {0, tiny}, {0, 0}}};
  const PolygonSet set({square});
  for (const LonLat p : {LonLat{0.5, 0}, LonLat{0.5, tiny}, LonLat{0.5, -1}, LonLat{2, 0}})
    EXPECT_EQ(set.contains(p), polygon_contains(square, p));
}

// distance_m from a point against GEOS on the plane, for every stroke and points around.
TEST(FeaturesPort, PointDistancesMatchGeos) {
  const test::TempDir dir;
  const VectorDataset ds = open_strokes(dir);
  Lcg rng;
  int checked = 0;
  for (const auto& f : *ds->GetLayer(0)) {
    const OGRGeometry& g = *f->GetGeometryRef();
    if (g.getGeometryType() == wkbPoint && std::abs(g.toPoint()->getX() - 11.5) < 1e-9) continue;
    std::vector<std::byte> wkb(g.WkbSize());
    g.exportToWkb(wkbNDR, reinterpret_cast<unsigned char*>(wkb.data()), wkbVariantIso);
    const Geometry parsed = parse_wkb(wkb, "f");
    const auto projected = plane().project(g);
    for (int i = 0; i < 5; ++i) {
      const LonLat p{kBox[0] + 0.1 * rng.next(), kBox[1] + 0.1 * rng.next()};
      const OGRPoint xy = plane().xy(p);
      EXPECT_NEAR(distance_m(p, parsed), projected->Distance(&xy), 0.02);
      ++checked;
    }
  }
  EXPECT_GT(checked, 80);
}

// A line whose edge crosses a cell (no vertex in it) meets the cell: distance 0, as GEOS finds the
// line and the cell's outline (both straight in lon/lat between dense points) intersecting. Skew
// ECEF chords of crossing edges pass millimetres apart, which must not count as a gap (a reach of
// 0 would miss the cell). Cells on the equatorial and both polar faces, levels 4 to 16 (coarser
// cells would need lines beyond the poles).
TEST(FeaturesPort, EdgesCrossingACellMeetIt) {
  const Grid& grid = default_grid();
  Lcg rng;
  int crossing = 0, apart = 0;
  for (const LonLat place : {LonLat{10.05, 45.05}, LonLat{-121.7, 46.6}, LonLat{150.0, -62.0}})
    for (int level = 4; level <= 16; level += 2) {
      const CellId cell = grid.cell_from_point(place, level);
      const CellOutline outline(grid, cell);
      // The outline's own points (geo_distance.h), so only the chords between them differ.
      const double side = grid.level_info(level, 1).plane_side_m;
      OGRLinearRing ring;
      for (const LonLat& p :
           grid.boundary(cell, std::clamp(int(std::ceil(side / kOutlineSpacingM)), 1, 1024)))
        ring.addPoint(p.lon, p.lat);
      OGRPolygon polygon;
      polygon.addRing(&ring);
      const LonLat c = grid.centre(cell);
      const double half = 0.6 * std::sqrt(polygon.get_Area());  // degrees
      for (int i = 0; i < 40; ++i) {
        // A line through a point near the cell, long enough to have its ends outside.
        const double angle = 6.283185307179586 * rng.next();
        const LonLat via{c.lon + 3 * half * (rng.next() - 0.5),
                         c.lat + 3 * half * (rng.next() - 0.5)};
        const double dx = 3 * half * std::cos(angle), dy = 3 * half * std::sin(angle);
        Geometry line;
        line.lines.push_back({{via.lon - dx, via.lat - dy, 0}, {via.lon + dx, via.lat + dy, 0}});
        OGRLineString ogr_line;
        ogr_line.addPoint(via.lon - dx, via.lat - dy);
        ogr_line.addPoint(via.lon + dx, via.lat + dy);
        const OGRPoint end0(ogr_line.getX(0), ogr_line.getY(0));
        const OGRPoint end1(ogr_line.getX(1), ogr_line.getY(1));
        if (polygon.Contains(&end0) || polygon.Contains(&end1)) continue;
        const double d = outline.distance_m(GeometryPieces(line));
        if (ogr_line.Intersects(&polygon)) {
          EXPECT_EQ(d, 0) << cell.ToText() << " line " << i;
          ++crossing;
        } else {
          EXPECT_GT(d, 0) << cell.ToText() << " line " << i;
          ++apart;
        }
      }
    }
  EXPECT_GT(crossing, 100);
  EXPECT_GT(apart, 20);
}

}  // namespace
}  // namespace maquette
