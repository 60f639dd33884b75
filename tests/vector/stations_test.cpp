// ingest_stations: CSV station tables into an artifact, and their validation messages.
#include <filesystem>

#include "vector/vector_ingest.h"
#include "vector_test_util.h"

namespace maquette::test {
namespace {

using json = nlohmann::json;

json artifact_json(const Store& store, const std::string& name) {
  const auto a = store.get_artifact(name);
  if (!a) return nullptr;
  return json::parse(a->text());
}

StationsIngestOptions stations(const std::string& layer = "stations") {
  StationsIngestOptions o;
  o.layer = layer;
  return o;
}

constexpr const char* kHeader = "\"id\",\"name\",\"lon\",\"lat\",\"elev_m\",\"tmean\",\"note\"\n";

TEST(IngestStations, ValidTableWithQuotesAndEmptyCells) {
  TempDir dir;
  const std::string csv = dir.file("st.csv");
  write_text(csv, std::string(kHeader) +
                      "\"001\",\"A, \"\"the\"\" first\",-105.5,40.25,1600,9.5,x\r\n"
                      "\"002\",B,-104,39,,,\n"
                      "\n"
                      "\"003\",C,-103, 38 ,2000, 7 ,y\n");
  auto store = new_store(dir);
  const auto r = ingest_stations(*store, csv, stations());
  EXPECT_EQ(r.stations, 3);
  EXPECT_EQ(r.value_columns, std::vector<std::string>{"tmean"});  // "note" is text
  const json doc = artifact_json(*store, "stations");
  EXPECT_EQ(doc["columns"], json::array({"tmean"}));
  ASSERT_EQ(doc["stations"].size(), 3u);
  EXPECT_EQ(doc["stations"][0], (json{{"id", "001"},
                                      {"name", "A, \"the\" first"},
                                      {"lon", -105.5},
                                      {"lat", 40.25},
                                      {"elevation", 1600.0},
                                      {"values", {{"tmean", 9.5}}}}));
  EXPECT_EQ(doc["stations"][1]["elevation"], nullptr);
  EXPECT_EQ(doc["stations"][1]["values"]["tmean"], nullptr);
  EXPECT_EQ(doc["stations"][2]["lat"], 38.0);
  EXPECT_EQ(store->get_artifact("stations")->metadata["kind"], "stations");
}

TEST(IngestStations, BadTablesNameFileLineAndColumn) {
  TempDir dir;
  auto store = new_store(dir);
  const std::string csv = dir.file("CO.csv");

  write_text(csv, "id,lon,lat,elevation\n1,-105,40,1600\n");
  expect_error([&] { ingest_stations(*store, csv, stations()); },
               {csv + ": no column 'elev_m' (columns: id, lon, lat, elevation)"});

  write_text(csv, std::string(kHeader) + "1,a,-105,40,1600,9,x\n2,b,-105,40,abc,9,x\n");
  expect_error([&] { ingest_stations(*store, csv, stations()); },
               {csv + " line 3: column 'elev_m': 'abc' is not a number"});

  write_text(csv, std::string(kHeader) + "1,a,-105,95,1600,9,x\n");
  expect_error([&] { ingest_stations(*store, csv, stations()); },
               {csv + " line 2: column 'lat': 95 is outside -90..90"});

  auto named = stations();
  named.value_columns = {"note"};
  write_text(csv, std::string(kHeader) + "1,a,-105,40,1600,9,x\n");
  expect_error([&] { ingest_stations(*store, csv, named); },
               {csv + " line 2: column 'note': 'x' is not a number"});
  named.value_columns = {"rain"};
  expect_error([&] { ingest_stations(*store, csv, named); }, {"no column 'rain'"});

  write_text(csv, std::string(kHeader) + "1,a,-105,40\n");
  expect_error([&] { ingest_stations(*store, csv, stations()); },
               {csv + " line 2: 4 fields, the header has 7"});
  write_text(csv, std::string(kHeader) + "1,\"a,-105,40,1600,9,x\n");
  expect_error([&] { ingest_stations(*store, csv, stations()); },
               {csv + " line 2: unterminated quoted field"});
  // Text that is not UTF-8 let nlohmann's type_error escape when the artifact was written
  // (fuzz/corpus/stations/regress-*).
  write_text(csv, std::string(kHeader) + "1,caf\xe9,-105,40,1600,9,x\n");
  expect_error([&] { ingest_stations(*store, csv, stations()); },
               {csv + " line 2: column 'name': not UTF-8 text"});
  write_text(csv, "id,lon,lat,elev_m,r\xe9gion\n1,-105,40,1600,9\n");
  expect_error([&] { ingest_stations(*store, csv, stations()); },
               {csv + ": column 5's name is not UTF-8 text"});
  EXPECT_TRUE(store->artifact_names().empty());
}

TEST(IngestStations, ColoradoStations) {
  const std::string csv =
      std::string(MAQUETTE_SHARED_DIR) + "/data/climate/CO_stations_annual_climate.csv";
  if (!std::filesystem::exists(csv)) GTEST_SKIP() << "../shared/data is absent";
  TempDir dir;
  auto store = new_store(dir);
  const auto r = ingest_stations(*store, csv, stations("co"));
  EXPECT_EQ(r.stations, 376);
  EXPECT_EQ(r.value_columns, (std::vector<std::string>{"mean_annual_tmean_C", "n_years_temp",
                                                       "mean_annual_precip_mm", "n_years_precip"}));
  const json doc = artifact_json(*store, "co");
  const json& first = doc["stations"][0];
  EXPECT_EQ(first["id"], "028468");
  EXPECT_EQ(first["name"], "TEEC NOS POS");
  EXPECT_EQ(first["lon"], -109.1);
  EXPECT_EQ(first["lat"], 36.9);
  EXPECT_EQ(first["elevation"], 1580.0);
  EXPECT_EQ(first["values"]["mean_annual_tmean_C"], 12.854);
  for (const json& s : doc["stations"]) {
    EXPECT_GT(s["lat"].get<double>(), 36.0);
    EXPECT_LT(s["lat"].get<double>(), 41.5);
  }
}

}  // namespace
}  // namespace maquette::test
