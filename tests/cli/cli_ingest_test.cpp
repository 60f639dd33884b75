// `maquette ingest --as features|stations` through the real program, on ../shared/data.
#include <gtest/gtest.h>

#include <filesystem>
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
