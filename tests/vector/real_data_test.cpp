// ingest_features on real data from ../shared/data (skipped when it is absent): London
// building footprints (GeoJSON, WGS84) and the Zion park boundary (GeoPackage, UTM 12N).
#include <filesystem>

#include "core/grid.h"
#include "vector/vector_ingest.h"
#include "vector_test_util.h"

namespace maquette::test {
namespace {

std::string shared_file(const std::string& relative) {
  const std::string path = std::string(MAQUETTE_SHARED_DIR) + "/data/" + relative;
  return std::filesystem::exists(path) ? path : "";
}

bool has(const std::vector<CellId>& cells, CellId c) {
  return std::find(cells.begin(), cells.end(), c) != cells.end();
}

TEST(RealData, LondonFootprintsAreIndexedWhereTheyStand) {
  const std::string path = shared_file("buildings/london_soho_buildings_wgs84.geojson");
  if (path.empty()) GTEST_SKIP() << "../shared/data is absent";
  TempDir dir;
  auto store = new_store(dir);
  FeatureIngestOptions o;
  o.layer = "buildings";
  const auto r = ingest_features(*store, {path}, o);
  EXPECT_EQ(r.features + r.invalid_skipped, 158);
  EXPECT_EQ(r.features, 158);
  EXPECT_GE(r.level, 16);  // footprints of tens of metres
  EXPECT_EQ(store->feature_count("buildings"), r.features);

  // Every footprint's centroid cell is among its cells.
  auto ds = std::unique_ptr<GDALDataset>(
      GDALDataset::Open(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY));
  ASSERT_NE(ds, nullptr);
  OGRLayer* layer = ds->GetLayer(0);
  int64_t fid = 0;
  for (const auto& f : *layer) {
    ++fid;  // store fids are 1-based positions in reading order
    OGRPoint centroid;
    ASSERT_EQ(f->GetGeometryRef()->Centroid(&centroid), OGRERR_NONE);
    const CellId cell = default_grid().cell_from_point({centroid.getX(), centroid.getY()}, r.level);
    EXPECT_TRUE(has(store->feature_cells("buildings", fid), cell)) << "fid " << fid;
  }
  EXPECT_EQ(fid, 158);
  // A typical footprint touches a few cells.
  EXPECT_LT(double(r.cell_entries) / double(r.features), 6.0);
}

TEST(RealData, ZionBoundaryCellsCoverItsTransformedVertices) {
  const std::string path = shared_file("zion/zion.gpkg");
  if (path.empty()) GTEST_SKIP() << "../shared/data is absent";
  TempDir dir;
  auto store = new_store(dir);
  FeatureIngestOptions o;
  o.layer = "park";
  o.level = 12;
  ASSERT_EQ(ingest_features(*store, {path}, o).features, 1);
  const auto cells = store->feature_cells("park", 1);

  auto ds = std::unique_ptr<GDALDataset>(
      GDALDataset::Open(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY));
  ASSERT_NE(ds, nullptr);
  OGRLayer* layer = ds->GetLayer(0);
  OGRSpatialReference wgs84;
  wgs84.importFromEPSG(4326);
  wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  std::unique_ptr<OGRCoordinateTransformation> ct(
      OGRCreateCoordinateTransformation(layer->GetSpatialRef(), &wgs84));
  ASSERT_NE(ct, nullptr);
  OGRFeatureUniquePtr f(layer->GetNextFeature());
  std::unique_ptr<OGRGeometry> g(f->GetGeometryRef()->clone());
  ASSERT_EQ(g->transform(ct.get()), OGRERR_NONE);
  OGREnvelope env;
  g->getEnvelope(&env);
  EXPECT_NEAR(env.MinX, -113.2, 0.1);  // Zion National Park, Utah
  EXPECT_NEAR(env.MinY, 37.15, 0.1);
  const OGRPolygon& polygon = *g->toPolygon();
  int vertices = 0;
  for (const OGRPoint& p : *polygon.getExteriorRing()) {
    EXPECT_TRUE(has(cells, default_grid().cell_from_point({p.getX(), p.getY()}, 12)));
    ++vertices;
  }
  EXPECT_GT(vertices, 10);
}

}  // namespace
}  // namespace maquette::test
