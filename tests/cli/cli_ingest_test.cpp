// `maquette ingest --as features|stations` through the real program, on ../shared/data.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "run_cli.h"
#include "store/store.h"

namespace maquette::test {
namespace {

using json = nlohmann::json;

const std::string kShared = MAQUETTE_SHARED_DIR;

TEST(CliIngest, FootprintsBecomeAFeaturesLayer) {
  const std::string source = kShared + "/data/buildings/london_soho_buildings_wgs84.geojson";
  if (!std::filesystem::exists(source)) GTEST_SKIP() << "no ../shared/data (" << source << ")";
  const std::string store = temp_dir() + "/s.mqt";
  const CliResult r = run_maquette("-q ingest " + store + " --layer soho --as features " + source);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const CliResult info = run_maquette("info " + store + " --json");
  ASSERT_EQ(info.exit_code, 0) << info.err;
  const json report = json::parse(info.out);
  ASSERT_EQ(report["layers"].size(), 1u);
  const json& layer = report["layers"][0];
  EXPECT_EQ(layer["kind"], "features");
  EXPECT_EQ(layer["features"], 158);  // SOURCES.md: 158 footprints
  // Soho is around 0.13 W, 51.51 N.
  EXPECT_NEAR(layer["bbox"][0].get<double>(), -0.135, 0.01);
  EXPECT_NEAR(layer["bbox"][1].get<double>(), 51.51, 0.01);
}

// `info` describes a features layer as features: their count by geometry type, the attributes.
TEST(CliIngest, InfoDescribesFeatures) {
  const std::string dir = temp_dir(), store = dir + "/s.mqt";
  std::ofstream(dir + "/f.geojson") << R"({"type": "FeatureCollection", "features": [
    {"type": "Feature", "properties": {"name": "a", "height": 12.5},
     "geometry": {"type": "Polygon", "coordinates": [[[7, 45], [7.1, 45], [7.1, 45.1], [7, 45]]]}},
    {"type": "Feature", "properties": {"name": "b", "kind": "well"},
     "geometry": {"type": "Point", "coordinates": [7.2, 45.2]}},
    {"type": "Feature", "properties": {"name": "c"},
     "geometry": {"type": "Point", "coordinates": [7.3, 45.3]}}]})";
  ASSERT_EQ(run_maquette("-q ingest " + store + " --layer f --as features " + dir + "/f.geojson")
                .exit_code,
            0);
  const CliResult info = run_maquette("info " + store + " --json");
  ASSERT_EQ(info.exit_code, 0) << info.err;
  const json layer = json::parse(info.out)["layers"][0];
  EXPECT_EQ(layer["features"], 3);
  EXPECT_EQ(layer["geometry_types"], json({{"Point", 2}, {"Polygon", 1}}));
  EXPECT_EQ(layer["attributes"], json({"height", "kind", "name"}));
  const CliResult text = run_maquette("info " + store);
  EXPECT_NE(text.out.find("f: features indexed in cells at level"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("features 3 (Point 2, Polygon 1)"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("attributes height, kind, name"), std::string::npos) << text.out;
  EXPECT_EQ(text.out.find("px tiles"), std::string::npos) << text.out;
}

TEST(CliIngest, StationsBecomeAnArtifact) {
  const std::string source = kShared + "/data/climate/CO_stations_annual_climate.csv";
  if (!std::filesystem::exists(source)) GTEST_SKIP() << "no ../shared/data (" << source << ")";
  const std::string store = temp_dir() + "/s.mqt";
  const CliResult r = run_maquette("-q ingest " + store + " --layer co --as stations " + source);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto s = Store::open(store, Store::Mode::ReadOnly);
  const auto artifact = s->get_artifact("co");
  ASSERT_TRUE(artifact);
  const json doc = json::parse(std::string(artifact->text()));
  EXPECT_EQ(doc["stations"].size(), 376u);
}

TEST(CliIngest, StationsWithAMissingColumnAreRefused) {
  const std::string dir = temp_dir();
  const CliResult r =
      run_maquette("ingest " + dir + "/s.mqt --layer co --as stations " + dir + "/none.csv");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("none.csv"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace maquette::test
