// ingest_features on files the tests write: GeoJSON, a GeoPackage in a projected CRS, a
// Shapefile; geometries at fault refused before anything is written, regions, the default level,
// resume and re-ingest.
#include <algorithm>
#include <cmath>
#include <filesystem>

#include "core/grid.h"
#include "vector/vector_ingest.h"
#include "vector_test_util.h"

namespace maquette::test {
namespace {

using json = nlohmann::json;

bool has(const std::vector<CellId>& cells, CellId c) {
  return std::find(cells.begin(), cells.end(), c) != cells.end();
}

json geojson_feature(const json& geometry, const json& properties) {
  return {{"type", "Feature"}, {"geometry", geometry}, {"properties", properties}};
}

std::string collection(const json& features) {
  return json{{"type", "FeatureCollection"}, {"features", features}}.dump();
}

const json kSquare = {
    {"type", "Polygon"},
    {"coordinates", {{{9.8, 44.9}, {10.2, 44.9}, {10.2, 45.2}, {9.8, 45.2}, {9.8, 44.9}}}}};
const json kLine = {{"type", "LineString"}, {"coordinates", {{10.5, 45.2}, {10.9, 45.27}}}};
const json kPoint = {{"type", "Point"}, {"coordinates", {11.0, 45.5}}};
const json kBowtie = {
    {"type", "Polygon"},
    {"coordinates", {{{12, 45}, {12.1, 45.1}, {12.1, 45}, {12, 45.1}, {12, 45}}}}};

// A square, a line and a point.
std::string mixed_geojson(const TempDir& dir) {
  const std::string path = dir.file("mixed.geojson");
  write_text(path, collection({
                       geojson_feature(kSquare, {{"n", 3}, {"x", 1.5}, {"name", "square"}}),
                       geojson_feature(kLine, {{"n", 4}, {"ok", true}, {"name", "line"}}),
                       geojson_feature(kPoint, {{"n", 5}, {"name", nullptr}}),
                   }));
  return path;
}

FeatureIngestOptions at_level(int level, const std::string& layer = "things") {
  FeatureIngestOptions o;
  o.layer = layer;
  o.level = level;
  return o;
}

TEST(IngestFeatures, GeoJsonPolygonsLinesAndPointsAreIndexedInTheCellsTheyTouch) {
  TempDir dir;
  auto store = new_store(dir);
  const FeatureIngestReport r = ingest_features(*store, {mixed_geojson(dir)}, at_level(10));
  EXPECT_EQ(r.features, 3);
  EXPECT_EQ(r.invalid_skipped, 0);
  EXPECT_EQ(r.level, 10);
  EXPECT_EQ(store->feature_count("things"), 3);
  const Grid& grid = default_grid();

  // The square (fid 1) crosses several cells: stored once, found in each.
  const auto square = store->feature_cells("things", 1);
  EXPECT_GT(square.size(), 4u);
  for (const auto& ring : kSquare["coordinates"])
    for (const auto& p : ring) EXPECT_TRUE(has(square, grid.cell_from_point({p[0], p[1]}, 10)));
  for (CellId c : square) {
    const auto in = store->features_in("things", c.range_min(), c.range_max());
    EXPECT_EQ(std::count_if(in.begin(), in.end(), [](const Feature& f) { return f.fid == 1; }), 1);
  }
  EXPECT_EQ(r.cell_entries, int64_t(square.size() + store->feature_cells("things", 2).size() + 1));

  // The line (fid 2): every point along it is in one of its cells.
  const auto line = store->feature_cells("things", 2);
  for (int i = 0; i <= 1000; ++i) {
    const double t = i / 1000.0;
    EXPECT_TRUE(has(line, grid.cell_from_point({10.5 + 0.4 * t, 45.2 + 0.07 * t}, 10))) << t;
  }
  EXPECT_EQ(store->feature_cells("things", 3),
            std::vector<CellId>{grid.cell_from_point({11.0, 45.5}, 10)});

  // Typed attributes; fields a feature lacks are null.
  const auto all = store->features_in("things", CellId(0), CellId(uint64_t(INT64_MAX)));
  ASSERT_EQ(all.size(), 3u);
  EXPECT_EQ(all[0].attributes, (json{{"n", 3}, {"x", 1.5}, {"name", "square"}, {"ok", nullptr}}));
  EXPECT_EQ(all[1].attributes["ok"], true);
  EXPECT_EQ(all[2].attributes["name"], nullptr);
  EXPECT_NEAR(all[0].bbox[0], 9.8, 1e-12);
  EXPECT_NEAR(all[0].bbox[3], 45.2, 1e-12);
  EXPECT_EQ(store->stats("things").feature_count, 3);
}

// A GeoPackage of a point and of a line whose second vertex's longitude is NaN (which WKT
// cannot write), feature ids 1 and 2.
void write_nan_line(const std::string& path) {
  write_vector(path, "GPKG", 4326,
               {{"POINT (11 45)", 1, "a"}, {"LINESTRING (10 45, 10.5 45.1)", 2, "b"}});
  std::unique_ptr<GDALDataset> ds(GDALDataset::Open(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_UPDATE));
  ASSERT_NE(ds, nullptr);
  OGRLayer* layer = ds->GetLayer(0);
  OGRFeatureUniquePtr f(layer->GetFeature(2));
  ASSERT_NE(f, nullptr);
  f->GetGeometryRef()->toLineString()->setPoint(1, std::nan(""), 45.1);
  ASSERT_EQ(layer->SetFeature(f.get()), OGRERR_NONE);
}

// Strokes at fault: each an error naming the file, layer and feature id, before anything is
// written, whether the layer is new or holds features already.
TEST(IngestFeatures, GeometriesAtFaultAreErrorsAndStoreNothing) {
  TempDir dir;
  auto store = new_store(dir);
  ingest_features(*store, {mixed_geojson(dir)}, at_level(10));
  const auto before = store->features_in("things", CellId(0), CellId(uint64_t(INT64_MAX)));
  const auto fid_17 = [](const json& geometry) {
    json f = geojson_feature(geometry, {{"n", 17}});
    f["id"] = 17;
    return f;
  };
  struct Case {
    std::string file, fault;
  };
  std::vector<Case> cases;
  const auto add_geojson = [&](const std::string& name, const json& geometry,
                               const std::string& fault) {
    const std::string path = dir.file(name + ".geojson");
    write_text(path, collection({geojson_feature(kPoint, {{"n", 1}}), fid_17(geometry)}));
    cases.push_back({path, fault});
  };
  add_geojson("bowtie", kBowtie, "has an invalid geometry (Self-intersection");
  add_geojson("none", nullptr, "has no geometry");
  // GeoJSON reads an empty geometry as none, and cannot hold NaN: GeoPackages can.
  const std::string empty_path = dir.file("empty.gpkg");
  write_vector(empty_path, "GPKG", 4326, {{"POINT (11 45)", 1, "a"}, {"POLYGON EMPTY", 2, "b"}});
  cases.push_back({empty_path, "feature 2 has an empty geometry"});
  const std::string nan_path = dir.file("nan.gpkg");
  write_nan_line(nan_path);
  cases.push_back({nan_path, "feature 2 has a coordinate that is not a number: (nan, 45.1"});
  for (const Case& c : cases) {
    for (const std::string layer : {"things", "fresh"})
      expect_error([&] { ingest_features(*store, {c.file}, at_level(10, layer)); },
                   {c.file, "feature", c.fault});
    EXPECT_FALSE(store->layer("fresh")) << c.file;
    EXPECT_FALSE(store->incomplete("things")) << c.file;
    const auto after = store->features_in("things", CellId(0), CellId(uint64_t(INT64_MAX)));
    ASSERT_EQ(after.size(), before.size());
    for (size_t i = 0; i < after.size(); ++i) {
      EXPECT_EQ(after[i].fid, before[i].fid);
      EXPECT_EQ(after[i].wkb, before[i].wkb);
    }
  }
  // The GeoJSON features at fault carry the id 17.
  expect_error([&] { ingest_features(*store, {cases[0].file}, at_level(10, "fresh")); },
               {"feature 17 has an invalid geometry"});
}

TEST(IngestFeatures, GeoPackageInAProjectedCrsIsTransformedToLonLat) {
  TempDir dir;
  // A lon/lat square written in UTM zone 32N.
  const std::vector<LonLat> corners = {{9.5, 45.0}, {9.6, 45.0}, {9.6, 45.1}, {9.5, 45.1}};
  OGRSpatialReference wgs84, utm;
  wgs84.importFromEPSG(4326);
  utm.importFromEPSG(32632);
  wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  std::unique_ptr<OGRCoordinateTransformation> ct(OGRCreateCoordinateTransformation(&wgs84, &utm));
  std::string wkt = "POLYGON((";
  for (size_t i = 0; i <= corners.size(); ++i) {
    double x = corners[i % 4].lon, y = corners[i % 4].lat;
    ASSERT_TRUE(ct->Transform(1, &x, &y));
    wkt += (i ? "," : "") + std::to_string(x) + " " + std::to_string(y);
  }
  const std::string path = dir.file("utm.gpkg");
  write_vector(path, "GPKG", 32632, {{wkt + "))", 42, "utm square"}});

  auto store = new_store(dir);
  const auto r = ingest_features(*store, {path}, at_level(12));
  ASSERT_EQ(r.features, 1);
  const auto f = store->features_in("things", CellId(0), CellId(uint64_t(INT64_MAX)));
  ASSERT_EQ(f.size(), 1u);
  EXPECT_EQ(f[0].attributes, (json{{"n", 42}, {"label", "utm square"}}));
  EXPECT_NEAR(f[0].bbox[0], 9.5, 1e-6);
  EXPECT_NEAR(f[0].bbox[1], 45.0, 1e-6);
  EXPECT_NEAR(f[0].bbox[2], 9.6, 1e-6);
  EXPECT_NEAR(f[0].bbox[3], 45.1, 1e-6);
  OGRGeometry* g = nullptr;
  ASSERT_EQ(OGRGeometryFactory::createFromWkb(f[0].wkb.data(), nullptr, &g, f[0].wkb.size()),
            OGRERR_NONE);
  std::unique_ptr<OGRGeometry> owned(g);
  const auto& ring = *g->toPolygon()->getExteriorRing();
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(ring.getX(i), corners[i].lon, 1e-6);
    EXPECT_NEAR(ring.getY(i), corners[i].lat, 1e-6);
  }
  const auto cells = store->feature_cells("things", 1);
  for (const LonLat& p : corners) EXPECT_TRUE(has(cells, default_grid().cell_from_point(p, 12)));
}

TEST(IngestFeatures, ShapefileWithoutCrsNeedsTheSourceCrs) {
  TempDir dir;
  const std::string path = dir.file("points.shp");
  write_vector(path, "ESRI Shapefile", 0,
               {{"POINT (2.35 48.85)", 1, "paris"}, {"POINT (-0.13 51.5)", 2, "london"}});
  auto store = new_store(dir);
  expect_error([&] { ingest_features(*store, {path}, at_level(14)); },
               {path, "layer 'points'", "has no CRS", "--src-crs"});
  EXPECT_TRUE(store->layers().empty());  // refused before anything was written

  FeatureIngestOptions o = at_level(14);
  o.src_crs = "EPSG:4326";
  EXPECT_EQ(ingest_features(*store, {path}, o).features, 2);
  const auto london = default_grid().cell_from_point({-0.13, 51.5}, 14);
  const auto in = store->features_in("things", london.range_min(), london.range_max());
  ASSERT_EQ(in.size(), 1u);
  EXPECT_EQ(in[0].attributes["label"], "london");
}

TEST(IngestFeatures, SeveralSourcesGetDistinctFidsAndARegionFilters) {
  TempDir dir;
  const std::string shp = dir.file("points.shp");
  write_vector(shp, "ESRI Shapefile", 4326, {{"POINT (11.0 45.5)", 1, "a"}});
  auto store = new_store(dir);
  FeatureIngestOptions o = at_level(10);
  o.region = {default_grid().cell_from_point({11.0, 45.5}, 10)};  // holds the point only
  const auto r = ingest_features(*store, {mixed_geojson(dir), shp}, o);
  EXPECT_EQ(r.features, 2);  // fid 3 (GeoJSON point) and fid 4 (the Shapefile's point)
  EXPECT_EQ(r.outside_skipped, 2);
  EXPECT_EQ(r.invalid_skipped, 0);
  const auto all = store->features_in("things", CellId(0), CellId(uint64_t(INT64_MAX)));
  ASSERT_EQ(all.size(), 2u);
  EXPECT_EQ(all[0].fid, 3);
  EXPECT_EQ(all[1].fid, 4);
  const auto layers = store->require_layer("things").provenance["layers"];
  ASSERT_EQ(layers.size(), 2u);
  EXPECT_EQ(layers[1]["first_fid"], 4);
  EXPECT_EQ(layers[1]["features"], 1);
}

// An ingest that stores no feature (sources without any, or none in the region) is an error that
// leaves no layer (it exited 0 with an empty layer).
TEST(IngestFeatures, AnIngestStoringNoFeatureIsAnErrorAndLeavesNoLayer) {
  TempDir dir;
  auto store = new_store(dir);
  FeatureIngestOptions o = at_level(10);
  o.region = {default_grid().cell_from_point({-100.0, 40.0}, 10)};  // far from every feature
  expect_error([&] { ingest_features(*store, {mixed_geojson(dir)}, o); },
               {"no feature stored in layer 'things': 3 outside the region"});
  EXPECT_FALSE(store->layer("things"));
  const std::string none = dir.file("none.geojson");
  write_text(none, collection(json::array()));
  expect_error([&] { ingest_features(*store, {none}, at_level(10)); },
               {"no feature stored in layer 'things': the sources hold none"});
  EXPECT_FALSE(store->layer("things"));
}

TEST(IngestFeatures, DefaultLevelFitsTheMedianFeature) {
  TempDir dir;
  json features = json::array();
  for (int i = 0; i < 9; ++i) {  // ~0.0004 deg (~30-45 m) squares
    const double x = -0.14 + 0.001 * i, y = 51.51, d = 0.0004;
    features.push_back(geojson_feature(
        {{"type", "Polygon"},
         {"coordinates", {{{x, y}, {x + d, y}, {x + d, y + d}, {x, y + d}, {x, y}}}}},
        json::object()));
  }
  const std::string path = dir.file("small.geojson");
  write_text(path, collection(features));
  auto store = new_store(dir);
  FeatureIngestOptions o;
  o.layer = "small";
  const int level = ingest_features(*store, {path}, o).level;
  const double size = 0.0004 * 111195;  // the north-south side, the larger one here
  EXPECT_GE(default_grid().level_info(level, 1).cell_side_m, size);
  EXPECT_LT(default_grid().level_info(level + 1, 1).cell_side_m, size);
  EXPECT_EQ(store->require_layer("small").level, level);
}

TEST(IngestFeatures, AnotherIngestIntoAFilledLayerIsRefused) {
  TempDir dir;
  auto store = new_store(dir);
  ingest_features(*store, {mixed_geojson(dir)}, at_level(10));
  const std::string other = dir.file("other.geojson");
  write_text(other, collection(json::array({geojson_feature(kPoint, json::object())})));
  expect_error([&] { ingest_features(*store, {other}, at_level(10)); },
               {"layer 'things'", "another ingest", "another layer name"});
}

// The same source named relative to another working directory is the same ingest (a pipeline run
// from another directory), not another one.
TEST(IngestFeatures, TheSameSourceFromAnotherDirectoryIsTheSameIngest) {
  TempDir dir;
  auto store = new_store(dir);
  const std::string path = mixed_geojson(dir);
  ingest_features(*store, {path}, at_level(10));
  const auto before = store->feature_count("things");
  const std::filesystem::path cwd = std::filesystem::current_path();
  std::filesystem::current_path(std::filesystem::path(path).parent_path());
  const auto again = [&] { ingest_features(*store, {"mixed.geojson"}, at_level(10)); };
  EXPECT_NO_THROW(again());
  std::filesystem::current_path(cwd);
  EXPECT_EQ(store->feature_count("things"), before);
}

// All of a layer's features with their cells, for comparing stores.
std::vector<std::pair<Feature, std::vector<CellId>>> contents(const Store& s) {
  std::vector<std::pair<Feature, std::vector<CellId>>> out;
  for (Feature& f : s.features_in("things", CellId(0), CellId(uint64_t(INT64_MAX)))) {
    auto cells = s.feature_cells("things", f.fid);
    out.emplace_back(std::move(f), std::move(cells));
  }
  return out;
}

bool same(const std::vector<std::pair<Feature, std::vector<CellId>>>& a,
          const std::vector<std::pair<Feature, std::vector<CellId>>>& b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](const auto& x, const auto& y) {
    return x.first.fid == y.first.fid && x.first.wkb == y.first.wkb &&
           x.first.attributes == y.first.attributes && x.first.bbox == y.first.bbox &&
           x.second == y.second;
  });
}

TEST(IngestFeatures, AnInterruptedIngestResumesToTheSameResult) {
  TempDir dir;
  json features = json::array();
  for (int i = 0; i < 10; ++i)
    features.push_back(
        geojson_feature({{"type", "Point"}, {"coordinates", {5.0 + i, 40.0}}}, {{"i", i}}));
  const std::string path = dir.file("ten.geojson");
  write_text(path, collection(features));
  FeatureIngestOptions o = at_level(12);
  o.batch_size = 3;

  auto store = new_store(dir);
  int batches = 0;
  const auto interrupted = [&](const FeatureIngestReport&) {
    if (++batches == 2) throw Error("killed");
  };
  // A failed ingest of a new layer removes it again.
  EXPECT_THROW(ingest_features(*store, {path}, o, interrupted), Error);
  EXPECT_FALSE(store->layer("things"));

  // Into a layer that exists, it leaves the layer marked incomplete for resume to finish.
  ingest_features(*store, {path}, o);
  batches = 0;
  EXPECT_THROW(ingest_features(*store, {path}, o, interrupted), Error);
  EXPECT_TRUE(store->incomplete("things"));
  o.resume = true;
  const auto resumed = ingest_features(*store, {path}, o);
  EXPECT_EQ(resumed.batches_resumed, 2);  // two committed batches
  EXPECT_EQ(resumed.features, 4);
  EXPECT_EQ(store->feature_count("things"), 10);
  EXPECT_FALSE(store->incomplete("things"));

  auto fresh = new_store(dir, "fresh.mqt");
  o.resume = false;
  EXPECT_EQ(ingest_features(*fresh, {path}, o).features, 10);
  EXPECT_TRUE(same(contents(*store), contents(*fresh)));

  // Ingesting the same sources again changes nothing.
  EXPECT_EQ(ingest_features(*store, {path}, o).features, 10);
  EXPECT_TRUE(same(contents(*store), contents(*fresh)));
  EXPECT_EQ(store->stats("things").tile_count, 10);
  EXPECT_TRUE(store->integrity_ok());
}

TEST(IngestFeatures, UnreadableSourcesAreNamed) {
  TempDir dir;
  auto store = new_store(dir);
  const std::string missing = dir.file("missing.geojson");
  expect_error([&] { ingest_features(*store, {missing}, at_level(10)); }, {"cannot open", missing});
  const std::string garbage = dir.file("garbage.geojson");
  write_text(garbage, "{ not json");
  expect_error([&] { ingest_features(*store, {garbage}, at_level(10)); }, {garbage});
  EXPECT_TRUE(store->layers().empty());
}

}  // namespace
}  // namespace maquette::test
