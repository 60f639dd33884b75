// climate.fit_stations + climate.regionalize run by the runner on a store, reading the stations,
// the zones and the fit from it: synthetic stations from known gradients, zones from a features
// layer, the Colorado stations, and bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>

#include "../station_fit.h"
#include "climate_module.h"
#include "vector/vector_ingest.h"

namespace maquette::climate {
namespace {

namespace fs = std::filesystem;
using climate_test::centre_of;
using climate_test::error_of;
using climate_test::run_steps;
using climate_test::sample;

constexpr int kSize = 16;

class Regionalize : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("climate_test_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    path_ = (dir_ / "s.mqt").string();
    store_ = Store::open(path_, Store::Mode::Create);
  }
  void TearDown() override {
    store_.reset();
    fs::remove_all(dir_);
  }

  void put_json(const std::string& name, const json& j) {
    const std::string text = j.dump();
    Artifact a;
    a.name = name;
    for (char c : text) a.data.push_back(std::byte(c));
    store_->put_artifact(a);
  }

  // Runs the fit over `cells` into the artifact "fit".
  StationFit fit(const json& params, const std::vector<CellId>& cells) {
    run_steps(
        path_, cells, kSize,
        {{{"op", "climate.fit_stations"}, {"outputs", {{"fit", "fit"}}}, {"params", params}}});
    const Artifact a = *store_->get_artifact("fit");
    return StationFit::from_json(json::parse(a.text()), "fit");
  }

  // Runs climate.regionalize on `cell` of the DEM tile `dem`, its `outputs` mapped to layers of
  // the same names; returns their tiles.
  std::map<std::string, Tile<float>> regionalize(CellId cell, const Tile<float>& dem,
                                                 const json& params,
                                                 const std::vector<std::string>& outputs = {
                                                     "temperature", "precipitation"}) {
    LayerInfo info;
    info.name = "dem";
    info.tile_size = kSize;
    info.level = cell.level();
    store_->create_layer(info);
    store_->put_tile("dem", cell, from_tile(dem, DType::F32));
    json mapped = json::object();
    for (const std::string& port : outputs) mapped[port] = port;
    run_steps(path_, {cell}, kSize,
              {{{"op", "climate.regionalize"},
                {"inputs", {{"dem", "dem"}}},
                {"outputs", mapped},
                {"params", params}}});
    std::map<std::string, Tile<float>> tiles;
    for (const std::string& port : outputs)
      tiles.emplace(port, to_tile<float>(*store_->get_tile(port, cell), nullptr));
    return tiles;
  }

  fs::path dir_;
  std::string path_;
  std::unique_ptr<Store> store_;
};

// Stations on a lon/lat grid around Colorado: t = 20 - 6 z/km + 0.01 x/km, p = 300 + 250 z/km.
json synthetic_stations() {
  json stations = json::array();
  int i = 0;
  for (double lon = -109; lon <= -102; lon += 1)
    for (double lat = 37; lat <= 41; lat += 1, ++i) {
      const double z = 1200 + std::fmod(i * 731.0, 2800);
      stations.push_back({{"id", std::to_string(i)},
                          {"lon", lon},
                          {"lat", lat},
                          {"elevation", z},
                          {"values", {{"t", 20 - 6 * z / 1000}, {"p", 300 + 250 * z / 1000}}}});
    }
  return {{"columns", {"t", "p"}}, {"stations", stations}};
}

// A cell among the synthetic stations.
const CellId kCell = default_grid().cell_from_point({-105.5, 39.5}, 6);

TEST_F(Regionalize, OutputsFollowTheRegression) {
  put_json("stations", synthetic_stations());
  const StationFit f = fit({{"stations", "stations"}, {"columns", {"t", "p"}}}, {kCell});
  EXPECT_NEAR(f.fits[0].at("t").per_km_elevation, -6, 1e-9);
  EXPECT_NEAR(f.fits[0].at("p").per_km_elevation, 250, 1e-9);

  Tile<float> dem = sample(kCell, kSize, [](LonLat p) { return 500 + 100 * p.lat; });
  dem.at(3, 4) = NAN;
  const auto out = regionalize(
      kCell, dem, {{"fit", "fit"}, {"temperature_column", "t"}, {"precipitation_column", "p"}});
  for (int row = 0; row < kSize; ++row)
    for (int col = 0; col < kSize; ++col) {
      const double z = dem.at(col, row);
      if (std::isnan(z)) {
        EXPECT_TRUE(std::isnan(out.at("temperature").at(col, row)));
        continue;
      }
      EXPECT_NEAR(out.at("temperature").at(col, row), 20 - 6 * z / 1000, 1e-4);
      EXPECT_NEAR(out.at("precipitation").at(col, row), 300 + 250 * z / 1000, 1e-3);
    }
}

// Below the stations' elevations a precipitation regression can extrapolate below 0 (here at
// z < -1200 m); the layer holds 0 there, temperature follows the regression.
TEST_F(Regionalize, PrecipitationIsNeverNegative) {
  put_json("stations", synthetic_stations());
  fit({{"stations", "stations"}, {"columns", {"t", "p"}}}, {kCell});
  Tile<float> dem = sample(kCell, kSize, [](LonLat) { return -2000; });
  const auto out = regionalize(
      kCell, dem, {{"fit", "fit"}, {"temperature_column", "t"}, {"precipitation_column", "p"}});
  EXPECT_EQ(out.at("precipitation").at(5, 5), 0.0f);
  EXPECT_NEAR(out.at("temperature").at(5, 5), 20 + 6 * 2.0, 1e-4);
}

TEST_F(Regionalize, ZonesFromAFeaturesLayer) {
  // Two zones split at 105.5 W with different lapse rates; one more station far away.
  json stations = synthetic_stations();
  for (json& s : stations["stations"])
    if (s["lon"].get<double>() > -105.5)
      s["values"]["t"] = 25 - 7 * s["elevation"].get<double>() / 1000;
  put_json("stations", stations);
  const std::string geojson = (dir_ / "zones.geojson").string();
  std::ofstream(geojson) << R"({"type": "FeatureCollection", "features": [
    {"type": "Feature", "properties": {"name": "west"}, "geometry": {"type": "Polygon",
     "coordinates": [[[-110, 36], [-105.5, 36], [-105.5, 42], [-110, 42], [-110, 36]]]}},
    {"type": "Feature", "properties": {"name": "east"}, "geometry": {"type": "Polygon",
     "coordinates": [[[-105.5, 36], [-101, 36], [-101, 42], [-105.5, 42], [-105.5, 36]]]}}]})";
  FeatureIngestOptions zones;
  zones.layer = "zones";
  zones.src_crs = "EPSG:4326";
  ingest_features(*store_, {geojson}, zones);
  const StationFit f = fit(
      {{"stations", "stations"}, {"columns", {"t"}}, {"zones", "zones"}, {"zone_field", "name"}},
      {kCell});
  ASSERT_EQ(f.zones.size(), 2u);
  EXPECT_EQ(f.zones[0].name, "west");
  EXPECT_NEAR(f.fits[0].at("t").per_km_elevation, -6, 1e-9);
  EXPECT_NEAR(f.fits[1].at("t").per_km_elevation, -7, 1e-9);

  // A cell straddling the border gets each zone's regression.
  const CellId cell = default_grid().cell_from_point({-105.5, 39}, 10);
  const auto out = regionalize(cell, sample(cell, kSize, [](LonLat) { return 2000.0; }),
                               {{"fit", "fit"}, {"temperature_column", "t"}}, {"temperature"});
  int west = 0, east = 0;
  for (int row = 0; row < kSize; ++row)
    for (int col = 0; col < kSize; ++col) {
      const bool is_west = centre_of(cell, kSize, col, row).lon < -105.5;
      EXPECT_NEAR(out.at("temperature").at(col, row), is_west ? 8.0 : 11.0, 1e-4);
      (is_west ? west : east)++;
    }
  EXPECT_GT(west, 0);
  EXPECT_GT(east, 0);
}

TEST_F(Regionalize, Colorado) {
  const std::string csv = MAQUETTE_SHARED_DIR "/data/climate/CO_stations_annual_climate.csv";
  if (!fs::exists(csv)) GTEST_SKIP() << "no " << csv << " (../shared is absent)";
  StationsIngestOptions o;
  o.layer = "co";
  ingest_stations(*store_, csv, o);
  const std::vector<CellId> region =
      default_grid().cover_bbox(-109.1, 36.9, -102.0, 41.1, 6, Containment::Overlap);
  const StationFit f = fit(
      {{"stations", "co"}, {"columns", {"mean_annual_tmean_C", "mean_annual_precip_mm"}}}, region);
  const ColumnFit& t = f.fits[0].at("mean_annual_tmean_C");
  const ColumnFit& p = f.fits[0].at("mean_annual_precip_mm");
  RecordProperty("lapse_rate_K_per_km", std::to_string(t.per_km_elevation));
  RecordProperty("precip_per_km", std::to_string(p.per_km_elevation));
  std::printf(
      "Colorado: %lld stations, lapse rate %.3f K/km (r2 %.3f, rmse %.2f K); precipitation "
      "%+.2f per km (r2 %.3f)\n",
      static_cast<long long>(t.stations), t.per_km_elevation, t.r2, t.rmse, p.per_km_elevation,
      p.r2);
  EXPECT_GT(t.stations, 300);
  EXPECT_GT(t.per_km_elevation, -7);
  EXPECT_LT(t.per_km_elevation, -5);
  // Precipitation in mm: Colorado's gains ~190 mm per km of elevation (in cm it would be ~19).
  EXPECT_GT(p.per_km_elevation, 100);
  EXPECT_LT(p.per_km_elevation, 400);
  // With both horizontal gradients the lapse rate stays plausible.
  const StationFit h = fit(
      {{"stations", "co"}, {"columns", {"mean_annual_tmean_C"}}, {"horizontal", "both"}}, region);
  const ColumnFit& th = h.fits[0].at("mean_annual_tmean_C");
  std::printf(
      "Colorado with horizontal terms: %.3f K/km elevation, %.4f K/km east, %.4f K/km "
      "north (r2 %.3f)\n",
      th.per_km_elevation, th.per_km_east, th.per_km_north, th.r2);
  EXPECT_GT(th.per_km_elevation, -8);
  EXPECT_LT(th.per_km_elevation, -4);
}

// Missing values as they arrive from the store (NaN is stored as null): left out of the fit and
// counted; the remaining stations still give the exact regression.
TEST_F(Regionalize, MissingValuesAreLeftOut) {
  json stations = synthetic_stations();
  stations["stations"][0]["values"]["t"] = std::nan("");
  stations["stations"][1]["elevation"] = nullptr;
  stations["stations"][2]["values"].erase("t");
  put_json("stations", stations);
  const StationFit f = fit({{"stations", "stations"}, {"columns", {"t", "p"}}}, {kCell});
  EXPECT_EQ(f.fits[0].at("t").stations, 37);
  EXPECT_EQ(f.fits[0].at("t").missing, 3);
  EXPECT_EQ(f.fits[0].at("p").missing, 1);
  EXPECT_NEAR(f.fits[0].at("t").per_km_elevation, -6, 1e-9);
  // A station off the globe is an error naming it.
  stations["stations"][3]["lat"] = 95;
  put_json("stations", stations);
  EXPECT_EQ(error_of([&] {
              fit({{"stations", "stations"}, {"columns", {"t"}}}, {kCell});
            }),
            "test: step 1 (climate.fit_stations) failed: climate.fit_stations: params.stations: "
            "artifact 'stations': station 4 ('3'): lat 95 is outside [-90, 90]");
}

TEST_F(Regionalize, BadInput) {
  const json base = {{"stations", "stations"}, {"columns", {"t"}}};
  const std::string fit_failed =
      "test: step 1 (climate.fit_stations) failed: climate.fit_stations: ";
  // What the step reads by name is there before anything runs, and is not what it writes.
  const std::string not_here = " (not in " + path_ + " nor written by an earlier step)";
  EXPECT_EQ(error_of([&] { fit(base, {kCell}); }),
            "test: step 1 (climate.fit_stations): params.stations: unknown artifact 'stations'" +
                not_here);
  put_json("stations", synthetic_stations());
  const std::string stations(store_->get_artifact("stations")->text());
  EXPECT_EQ(error_of([&] {
              run_steps(path_, {kCell}, kSize,
                        {{{"op", "climate.fit_stations"},
                          {"outputs", {{"fit", "stations"}}},
                          {"params", base}}});
            }),
            "test: step 1 (climate.fit_stations): outputs.fit: 'stations' is also what the step "
            "reads (params.stations)");
  EXPECT_EQ(std::string(store_->get_artifact("stations")->text()), stations);
  json p = base;
  p["columns"] = {"tmax"};
  EXPECT_EQ(error_of([&] { fit(p, {kCell}); }),
            fit_failed + "params.columns: no station has a column 'tmax'");
  // Stations outside the region: used (default), dropped or refused.
  const CellId small = default_grid().cell_from_point({-105, 39}, 6);
  EXPECT_EQ(fit(base, {small}).fits[0].at("t").stations, 40);
  p = base;
  p["outside_region"] = "error";
  EXPECT_NE(error_of([&] { fit(p, {small}); }).find("params.outside_region: station 0 at"),
            std::string::npos);
  p["outside_region"] = "drop";
  EXPECT_NE(error_of([&] { fit(p, {small}); }).find("the regression needs at least 3"),
            std::string::npos);
  // A region away from every station (e.g. a DEM of another area) would get an extrapolated
  // fit: refused whatever the policy.
  const CellId alps = default_grid().cell_from_point({10, 47}, 6);
  for (const char* policy : {"use", "drop"}) {
    p["outside_region"] = policy;
    EXPECT_NE(error_of([&] { fit(p, {alps}); })
                  .find(fit_failed + "params.stations: the 40 stations of 'stations' (lon "
                                     "-109..-102, lat 37..41) do not overlap the step's region"),
              std::string::npos)
        << policy;
  }
  // A zones layer of points.
  const std::string geojson = (dir_ / "points.geojson").string();
  std::ofstream(geojson) << R"({"type": "FeatureCollection", "features": [{"type": "Feature",
    "properties": {}, "geometry": {"type": "Point", "coordinates": [-105, 39]}}]})";
  FeatureIngestOptions points;
  points.layer = "points";
  points.src_crs = "EPSG:4326";
  ingest_features(*store_, {geojson}, points);
  p = base;
  p["zones"] = "points";
  EXPECT_EQ(error_of([&] { fit(p, {kCell}); }),
            fit_failed + "params.zones: feature 1 of 'points' is a Point, not a polygon");
  p["zones"] = "nothing";
  EXPECT_EQ(
      error_of([&] { fit(p, {kCell}); }),
      "test: step 1 (climate.fit_stations): params.zones: unknown layer 'nothing'" + not_here);
  // Regionalize: a mapped output without its column, and an unknown column.
  fit(base, {kCell});
  const Tile<float> dem = sample(kCell, kSize, [](LonLat) { return 1.0; });
  const std::string failed = "test: step 1 (climate.regionalize) failed on cell " + kCell.ToText() +
                             ": climate.regionalize: ";
  EXPECT_EQ(
      error_of([&] {
        regionalize(kCell, dem, {{"fit", "fit"}});
      }),
      failed + "params.temperature_column: output 'temperature' is mapped but no column is given");
  EXPECT_EQ(
      error_of([&] {
        regionalize(kCell, dem, {{"fit", "fit"}, {"temperature_column", "p"}}, {"temperature"});
      }),
      failed + "params.temperature_column: column 'p' is not in fit 'fit'");
  EXPECT_EQ(error_of([&] {
              regionalize(kCell, dem, {{"fit", "nofit"}});
            }),
            "test: step 1 (climate.regionalize): params.fit: unknown artifact 'nofit'" + not_here);
  EXPECT_EQ(error_of([&] {
              regionalize(kCell, dem, {{"fit", "stations"}, {"temperature_column", "t"}},
                          {"temperature"});
            }),
            failed + "params.fit: artifact 'stations': not a station fit of climate.fit_stations");
}

}  // namespace
}  // namespace maquette::climate
