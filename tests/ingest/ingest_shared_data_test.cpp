// Real data from ../shared/data (skipped when absent): SRTM with voids, NLCD land cover with its
// class table, a Landsat composite with --bands.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <set>

#include "core/data_footprint.h"
#include "ingest_fixture.h"

namespace maquette::test {
namespace {

std::string shared(const std::string& rel) {
  const std::string path = std::string(MAQUETTE_SHARED_DIR) + "/data/" + rel;
  return std::filesystem::exists(path) ? path : "";
}

#define REQUIRE_SHARED(var, rel)       \
  const std::string var = shared(rel); \
  if (var.empty()) GTEST_SKIP() << "../shared/data/" rel " is absent"

TEST(IngestSharedData, MtRainierSrtmKeepsVoids) {
  REQUIRE_SHARED(tif, "srtm3/mt_rainier_90m.tif");
  RasterIngestOptions o;
  o.layer = "dem";
  o.as = "dem";
  const auto store = ingest(temp_dir(), "rainier", {tif}, o);
  const LayerInfo info = store->require_layer("dem");
  EXPECT_EQ(info.level, 9);
  EXPECT_EQ(info.units, "m");
  EXPECT_EQ(info.dtype, DType::F32);
  EXPECT_TRUE(info.provenance.contains("vertical_datum"));
  EXPECT_EQ(info.provenance["sources"][0]["nodata"][0], -32768.0);
  int64_t voids = 0, valid = 0;
  float top = -1e9f;
  for_each_sample(*store, "dem", [&](CellId, LonLat p, const float* v) {
    const bool inside = p.lon > -121.99 && p.lon < -121.01 && p.lat > 46.01 && p.lat < 46.99;
    if (!inside) return;
    if (std::isnan(v[0])) {
      ++voids;
      return;
    }
    ++valid;
    top = std::max(top, v[0]);
    ASSERT_GT(v[0], -100.0f);  // no -32768 leaked into the interpolation
  });
  EXPECT_GT(voids, 0);  // the SRTM voids stay missing
  EXPECT_GT(valid, 1000000);
  EXPECT_GT(top, 4000.0f);  // the summit, 4392 m
  EXPECT_LT(top, 4400.0f);
  EXPECT_TRUE(store->get_overview("dem", store->tile_cells("dem").front().parent()));
}

// The layer records where its samples come from: the source's outline (its pixels' outer edges,
// from its geotransform) within --bbox, and a later ingest into the layer adds its own. Every
// sample with data lies inside it.
TEST(IngestSharedData, MtRainierFootprintIsRecorded) {
  REQUIRE_SHARED(tif, "srtm3/mt_rainier_90m.tif");
  RasterIngestOptions o;
  o.layer = "dem";
  o.as = "dem";
  o.bbox = std::array<double, 4>{-121.6, 46.3, -121.2, 46.7};
  const std::string dir = temp_dir();
  const auto footprint = [&] {
    return DataFootprint::from_provenance(
        ingest(dir, "rainier", {tif}, o)->require_layer("dem").provenance, "dem");
  };
  const std::optional<DataFootprint> box = footprint();
  ASSERT_TRUE(box);
  EXPECT_TRUE(box->contains({-121.4, 46.5}));
  EXPECT_FALSE(box->contains({-121.7, 46.5}));  // in the source, beyond the box
  EXPECT_FALSE(box->contains({-121.4, 46.8}));
  o.bbox = std::array<double, 4>{-121.9, 46.75, -121.7, 46.9};
  const std::optional<DataFootprint> boxes = footprint();
  ASSERT_TRUE(boxes);
  EXPECT_TRUE(boxes->contains({-121.4, 46.5}));
  EXPECT_TRUE(boxes->contains({-121.8, 46.8}));
  EXPECT_FALSE(boxes->contains({-121.7, 46.5}));
  EXPECT_EQ(footprint()->to_json(), boxes->to_json());  // the same ingest again adds nothing
  // The source's edge: 1201 pixels of 3" from -122.00042, 47.00042.
  o.bbox.reset();
  o.layer = "whole";
  const auto whole = ingest(temp_dir(), "rainier", {tif}, o);
  const std::optional<DataFootprint> outline =
      DataFootprint::from_provenance(whole->require_layer("whole").provenance, "whole");
  ASSERT_TRUE(outline);
  constexpr double kWest = -122.0 - 1.5 / 3600, kNorth = 47.0 + 1.5 / 3600, kSide = 1201.0 / 1200;
  for (const double f : {0.001, 0.5, 0.999}) {
    EXPECT_TRUE(outline->contains({kWest + 1e-6, kNorth - f * kSide}));
    EXPECT_FALSE(outline->contains({kWest - 1e-6, kNorth - f * kSide}));
    EXPECT_TRUE(outline->contains({kWest + f * kSide, kNorth - kSide + 1e-6}));
    EXPECT_FALSE(outline->contains({kWest + f * kSide, kNorth - kSide - 1e-6}));
  }
  int64_t with_data = 0;
  for_each_sample(*whole, "whole", [&](CellId, LonLat p, const float* v) {
    if (std::isnan(v[0])) return;
    ++with_data;
    EXPECT_TRUE(outline->contains(p)) << p.lon << ", " << p.lat;
  });
  EXPECT_GT(with_data, 1000000);
}

TEST(IngestSharedData, ZionLandCoverKeepsItsClassTable) {
  REQUIRE_SHARED(tif, "zion/nlcd.tif");
  RasterIngestOptions o;
  o.layer = "lc";
  o.as = "landcover";
  const auto store = ingest(temp_dir(), "nlcd", {tif}, o);
  const LayerInfo info = store->require_layer("lc");
  EXPECT_EQ(info.dtype, DType::U8);
  EXPECT_EQ(info.semantics, Semantics::Categorical);
  EXPECT_EQ(info.provenance["classes"]["1"]["name"], "Water");
  EXPECT_EQ(info.provenance["classes"]["1"]["color"], "#476ba0");
  EXPECT_EQ(info.provenance["classes"].size(), 9u);
  std::set<int> seen;
  for_each_sample(*store, "lc", [&](CellId, LonLat, const float* v) {
    if (!std::isnan(v[0])) seen.insert(int(v[0]));
  });
  for (int c : seen) EXPECT_TRUE(c >= 0 && c <= 8) << c;
  EXPECT_GE(seen.size(), 5u);
}

TEST(IngestSharedData, LandsatBandsAsImagery) {
  REQUIRE_SHARED(tif, "zion/landsat_rgb_b4b3b2_8bit.tif");
  RasterIngestOptions o;
  o.layer = "rgb";
  o.as = "imagery";
  o.bands = {3, 2, 1};
  o.level = 10;  // coarser than the source: area-weighted averaging
  const auto store = ingest(temp_dir(), "landsat", {tif}, o);
  const LayerInfo info = store->require_layer("rgb");
  EXPECT_EQ(info.dtype, DType::U8);
  EXPECT_EQ(info.channels, 3);
  EXPECT_EQ(info.provenance["resampling"], "average");
  int64_t valid = 0;
  for_each_sample(*store, "rgb", [&](CellId, LonLat, const float* v) {
    valid += !std::isnan(v[0]) && !std::isnan(v[1]) && !std::isnan(v[2]);
  });
  EXPECT_GT(valid, 100000);
}

}  // namespace
}  // namespace maquette::test
