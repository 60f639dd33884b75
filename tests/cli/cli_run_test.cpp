// `maquette run`, `info`, `modules` and `demo` as a user runs them. Every bad input gives a
// clear message naming what is wrong, a non-zero exit, and leaves the store's bytes untouched.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <set>
#include <sstream>
#include <thread>

#include "core/json_file.h"
#include "run_cli.h"
#include "store/store.h"

namespace maquette::test {
namespace {

using json = nlohmann::json;
namespace fs = std::filesystem;

const std::string kFixtures = MAQUETTE_FIXTURE_MODULE_DIR;

void write_file(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

// The store's bytes, WAL included: what "untouched" means. An empty WAL (left by a reader, as
// SQLite does) holds nothing, like a missing one.
std::string store_fingerprint(const std::string& store) {
  const std::string wal = store + "-wal";
  const bool has_wal = fs::exists(wal) && fs::file_size(wal) > 0;
  return file_fingerprint(store) + "|" + (has_wal ? file_fingerprint(wal) : "");
}

// Every tile of a layer, as stored (decoded bytes), by cell id.
std::map<uint64_t, std::vector<std::byte>> tile_bytes(const std::string& store_path,
                                                      const std::string& layer) {
  const auto store = Store::open(store_path, Store::Mode::ReadOnly);
  std::map<uint64_t, std::vector<std::byte>> out;
  for (CellId c : store->tile_cells(layer)) out[c.id()] = store->get_tile(layer, c)->bytes;
  return out;
}

// A small valid pipeline: synthetic terrain on 16-pixel tiles and its derivatives.
json small_pipeline(const std::string& store) {
  return {
      {"store", store},
      {"region", {{"bbox", {6.0, 44.0, 9.0, 46.0}}}},
      {"level", 5},
      {"tile_size", 16},
      {"steps",
       {{{"op", "terrain.synthesize"}, {"outputs", {{"dem", "dem"}}}, {"params", {{"seed", 3}}}},
        {{"op", "terrain.derive"},
         {"inputs", {{"dem", "dem"}}},
         {"outputs", {{"slope", "slope"}, {"hillshade", "hs"}}}}}}};
}

class CliRun : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = temp_dir();
    store_ = dir_ + "/s.mqt";
    write_file(dir_ + "/good.json", small_pipeline(store_).dump(2));
    const CliResult r = run_maquette("-q run " + dir_ + "/good.json --threads 2");
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  // Runs a pipeline given as text; expects failure naming `message`, and the store untouched.
  void expect_refused(const std::string& pipeline_text, const std::string& message,
                      const std::string& env = "") {
    const std::string before = store_fingerprint(store_);
    const std::string file = dir_ + "/bad.json";
    write_file(file, pipeline_text);
    const CliResult r = run_maquette("run " + file, env);
    EXPECT_NE(r.exit_code, 0) << pipeline_text;
    EXPECT_NE(r.err.find(message), std::string::npos)
        << "expected '" << message << "' in: " << r.err;
    EXPECT_NE(r.err.find("error"), std::string::npos) << r.err;
    EXPECT_EQ(store_fingerprint(store_), before) << "store changed by: " << pipeline_text;
  }
  std::string dir_, store_;
};

TEST_F(CliRun, InfoDescribesTheLayersWritten) {
  const CliResult r = run_maquette("info " + store_ + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json info = json::parse(r.out);
  std::set<std::string> names;
  for (const json& l : info["layers"]) {
    names.insert(l["name"]);
    EXPECT_EQ(l["level"], 5);
    EXPECT_EQ(l["tile_size"], 16);
    EXPECT_GT(l["tiles"].get<int>(), 0);
    // The layer's bbox holds the pipeline's bbox (cells overlap it).
    const json b = l["bbox"];
    EXPECT_LE(b[0].get<double>(), 6.0);
    EXPECT_LE(b[1].get<double>(), 44.0);
    EXPECT_GE(b[2].get<double>(), 9.0);
    EXPECT_GE(b[3].get<double>(), 46.0);
  }
  EXPECT_EQ(names, (std::set<std::string>{"dem", "slope", "hs"}));
  EXPECT_GT(info["size_bytes"].get<long long>(), 0);
  // The tiles are exactly the cells covering the bbox (as `cells cover` lists them).
  const CliResult cover = run_maquette("cells cover --bbox 6 44 9 46 --level 5");
  ASSERT_EQ(cover.exit_code, 0);
  const long lines = std::count(cover.out.begin(), cover.out.end(), '\n');
  EXPECT_EQ(info["layers"][0]["tiles"].get<long>(), lines);
}

TEST_F(CliRun, KilledRunResumesToTheSameBits) {
  // A slow pipeline (fixture.fill sleeps per cell) killed mid-run, then resumed.
  json p = small_pipeline(dir_ + "/killed.mqt");
  p["steps"] = {{{"op", "fixture.fill"},
                 {"outputs", {{"value", "v"}}},
                 {"params", {{"seed", 2}, {"sleep_ms", 100}}}},
                p["steps"][1]};
  p["level"] = 7;  // about 20 cells: some 1 s of work on 2 threads
  p["steps"][1]["inputs"]["dem"] = "v";
  write_file(dir_ + "/killed.json", p.dump());
  const std::string env = "MAQUETTE_MODULE_PATH=" + kFixtures + "/good";
  const int pid = spawn_maquette("run " + dir_ + "/killed.json --threads 2", env);
  ASSERT_GT(pid, 0);
  // Kill it once a few cells are stored (polling, since a loaded machine may start it slowly).
  const std::string killed = dir_ + "/killed.mqt";
  auto cells_done = [&]() -> size_t {
    if (!fs::exists(killed)) return 0;
    try {
      return Store::open(killed, Store::Mode::ReadOnly)->tile_cells("v").size();
    } catch (const std::exception&) {
      return 0;  // layer not created yet
    }
  };
  for (int i = 0; i < 2000 && cells_done() < 2; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  ASSERT_EQ(::kill(pid, SIGKILL), 0);
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the run ended before it was killed: make it slower";
  EXPECT_TRUE(Store::open(killed, Store::Mode::ReadOnly)->integrity_ok());

  const CliResult resumed =
      run_maquette("-q run " + dir_ + "/killed.json --resume --threads 1", env);
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  p["store"] = dir_ + "/whole.mqt";
  write_file(dir_ + "/whole.json", p.dump());
  ASSERT_EQ(run_maquette("-q run " + dir_ + "/whole.json --threads 2", env).exit_code, 0);
  for (const char* layer : {"v", "slope", "hs"})
    EXPECT_EQ(tile_bytes(dir_ + "/killed.mqt", layer), tile_bytes(dir_ + "/whole.mqt", layer))
        << layer;
}

TEST_F(CliRun, DryRunWritesNothing) {
  const std::string before = store_fingerprint(store_);
  const CliResult r = run_maquette("run " + dir_ + "/good.json --dry-run");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("terrain.derive"), std::string::npos) << r.out;
  EXPECT_EQ(store_fingerprint(store_), before);
}

// A region beside the data computes nothing, and says so (it passed in silence).
TEST_F(CliRun, ARegionBesideTheDataIsSaid) {
  json p = small_pipeline(store_);
  p["region"]["bbox"] = {100.0, 10.0, 101.0, 11.0};
  p["steps"].erase(0);  // derive alone, from the stored dem
  write_file(dir_ + "/beside.json", p.dump());
  const CliResult r = run_maquette("run " + dir_ + "/beside.json");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("step 1 (terrain.derive): no tile of inputs.dem (layer 'dem') lies in the "
                       "region: nothing computed"),
            std::string::npos)
      << r.err;
}

TEST_F(CliRun, BadPipelinesAreRefusedBeforeAnythingRuns) {
  json p = small_pipeline(store_);
  expect_refused("{\"store\": \"s.mqt\",\n  \"steps\": [,]}", "line 2");

  p = small_pipeline(store_);
  p["steps"][1]["op"] = "terrain.nope";
  expect_refused(p.dump(), "terrain.nope");

  p = small_pipeline(store_);
  p["steps"][1]["params"] = {{"azimuth", "north"}};
  expect_refused(p.dump(), "azimuth");

  p = small_pipeline(store_);
  p["steps"][1]["params"] = {{"azimuth", 400}};
  expect_refused(p.dump(), "400");

  p = small_pipeline(store_);
  p["steps"][1]["inputs"]["dem"] = "dme";
  expect_refused(p.dump(), "dme");

  p = small_pipeline(store_);
  p["region"] = {{"cells", {"N12", "X9"}}};
  expect_refused(p.dump(), "X9");

  p = small_pipeline(store_);
  p["level"] = 40;
  expect_refused(p.dump(), "40");

  p = small_pipeline(store_);
  p["region"] = {{"bbox", {6.0, 44.0, 9.0, 95.0}}};
  expect_refused(p.dump(), "95");
}

// An output naming a stored layer of another definition is refused naming the step, the port and
// the difference, before anything is written (not even the new layer of the step before it), and
// by a dry run.
TEST_F(CliRun, AnOutputRedefiningAStoredLayerIsRefusedBeforeAnyWrite) {
  json p = small_pipeline(store_);
  p["steps"] = {{{"op", "terrain.synthesize"}, {"outputs", {{"dem", "fresh"}}}},
                {{"op", "terrain.synthesize"}, {"outputs", {{"dem", "hs"}}}}};
  const std::string message =
      "step 2 (terrain.synthesize): outputs.dem: layer 'hs' already "
      "exists in " +
      store_ + " with another definition: dtype ";
  expect_refused(p.dump(), message);
  const CliResult dry = run_maquette("run " + dir_ + "/bad.json --dry-run");
  EXPECT_NE(dry.exit_code, 0);
  EXPECT_NE(dry.err.find(message), std::string::npos) << dry.err;
}

// A file an operator writes (texture.cluster's "out", "plot") may not be the store or the
// pipeline: it replaced the store with JSON or a PNG, exit 0 (an audit's find).
TEST_F(CliRun, AFileAStepWritesIsNeitherTheStoreNorThePipeline) {
  json p = small_pipeline(store_);
  p["steps"] = {{{"op", "texture.cluster"},
                 {"inputs", {{"rgb", "hs"}}},
                 {"outputs", {{"clusters", "clusters"}}},
                 {"params", {{"k", 3}, {"out", store_}}}}};
  expect_refused(p.dump(), "bad.json: step 1 (texture.cluster): params.out: " + store_ +
                               " is the store " + store_ +
                               ": it would be replaced; give another output path");
  p["steps"][0]["params"] = {{"k", 3}, {"plot", dir_ + "/bad.json"}};
  expect_refused(p.dump(), "step 1 (texture.cluster): params.plot: " + dir_ +
                               "/bad.json is the pipeline " + dir_ + "/bad.json: it would be");
  EXPECT_EQ(read_text_file(dir_ + "/bad.json"), p.dump());
}

// texture.cluster's params and its image told when the pipeline is read or planned, a dry run
// too: they failed at the step's end, after the steps before it had run (an audit's find).
TEST_F(CliRun, ATextureStepsParamsAndImageAreCheckedBeforeAnythingRuns) {
  json p = small_pipeline(store_);
  const json cluster = {{"op", "texture.cluster"},
                        {"inputs", {{"rgb", "hs"}}},
                        {"outputs", {{"clusters", "clusters"}}},
                        {"params", {{"k", 3}}}};
  p["steps"] = {cluster};
  p["steps"][0]["params"]["k"] = "many";
  expect_refused(p.dump(),
                 "step 1 (texture.cluster): texture.cluster: params.k: expected an "
                 "integer 1..");
  p["steps"][0]["params"] = {{"k", 3}, {"sun_altitude", 30}};
  expect_refused(p.dump(),
                 "step 1 (texture.cluster): texture.cluster: params.sun_altitude needs "
                 "inputs.hillshade");
  p["steps"] = {cluster};
  expect_refused(p.dump(), "step 1 (texture.cluster): inputs.rgb: layer 'hs' has 1 channel");
  const CliResult dry = run_maquette("run " + dir_ + "/bad.json --dry-run");
  EXPECT_NE(dry.exit_code, 0);
  // texture.classify without classes, texture.fit's reversed range and unmapped quantity (they
  // failed on the first cell).
  p["steps"] = {{{"op", "texture.classify"},
                 {"inputs", {{"rgb", "hs"}}},
                 {"outputs", {{"classes", "classes"}}}}};
  expect_refused(p.dump(),
                 "step 1 (texture.classify): texture.classify: params: give \"boxes\", "
                 "\"polygons\" or \"centres\"");
  json fit = {{"op", "texture.fit"},
              {"inputs", {{"classes", "slope"}, {"rgb", "hs"}, {"dem", "dem"}}},
              {"outputs", {{"model", "model"}}},
              {"params", {{"ranges", {{"height", {10, 5}}}}}}};
  p["steps"] = {fit};
  expect_refused(p.dump(),
                 "step 1 (texture.fit): texture.fit: params.ranges.height: expected [lo, hi] "
                 "with lo < hi, got [10,5]");
  fit["params"] = {{"ranges", {{"height", {0, 3000}}}}, {"quantities", {"height", "rainfall"}}};
  fit["params"]["ranges"]["rainfall"] = {0, 900};
  p["steps"] = {fit};
  expect_refused(p.dump(),
                 "step 1 (texture.fit): texture.fit: params.quantities: 'rainfall' has no input "
                 "(map inputs.rainfall)");
}

// climate.solar's period and texture.procedural's model, told when the pipeline is read (they
// failed on the first cell, after the steps before it had run).
TEST_F(CliRun, PeriodAndModelAreToldWhenThePipelineIsRead) {
  json p = small_pipeline(store_);
  p["steps"] = {{{"op", "climate.solar"},
                 {"inputs", {{"dem", "dem"}}},
                 {"outputs", {{"radiation", "rad"}}},
                 {"params", {{"first_day", 200}, {"last_day", 100}}}}};
  expect_refused(p.dump(),
                 "bad.json: step 1 (climate.solar): climate.solar: params.last_day: 100 "
                 "is before first_day 200");
  p["steps"] = {{{"op", "texture.procedural"},
                 {"inputs", {{"dem", "dem"}}},
                 {"outputs", {{"imagery", "tex"}}}}};
  expect_refused(p.dump(),
                 "bad.json: step 1 (texture.procedural): texture.procedural: params: "
                 "give exactly one of \"model\" and \"model_file\"");
}

// texture.calibrate's coefficients (three, one per band) and its one-channel bands told when the
// pipeline is read or planned (they failed on the first cell, after the steps before it).
TEST_F(CliRun, CalibrateParamsAndBandsAreCheckedBeforeAnythingRuns) {
  json p = small_pipeline(store_);
  const json calibrate = {{"op", "texture.calibrate"},
                          {"inputs", {{"red", "dem"}, {"green", "dem"}, {"blue", "dem"}}},
                          {"outputs", {{"rgb", "rgb"}}},
                          {"params",
                           {{"reflectance_mult", {2e-5, 2e-5, 2e-5}},
                            {"reflectance_add", {-0.1, -0.1, -0.1}},
                            {"sun_elevation", 60}}}};
  p["steps"] = {calibrate};
  p["steps"][0]["params"]["reflectance_add"] = {-0.1, -0.1};
  expect_refused(p.dump(),
                 "bad.json: step 1 (texture.calibrate): params.reflectance_add: expected at "
                 "least 3 items");
  json second = calibrate;
  second["inputs"]["red"] = "rgb";
  second["outputs"]["rgb"] = "rgb2";
  p["steps"] = {calibrate, second};
  expect_refused(p.dump(),
                 "bad.json: step 2 (texture.calibrate): inputs.red: layer 'rgb' has 3 channels, "
                 "but the port takes 1");
}

TEST_F(CliRun, MissingRequiredParameterIsNamed) {
  json p = small_pipeline(store_);
  p["steps"] = {{{"op", "fixture.fill"}, {"outputs", {{"value", "v"}}}}};
  expect_refused(p.dump(), "seed", "MAQUETTE_MODULE_PATH=" + kFixtures + "/good");
}

TEST_F(CliRun, OperatorThrowingNamesStepAndCellAndKeepsEarlierTiles) {
  json p = small_pipeline(store_);
  p["steps"] = {{{"op", "fixture.fill"},
                 {"outputs", {{"value", "v"}}},
                 {"params", {{"seed", 1}, {"fail_on", "N1111"}}}}};
  p["region"] = {{"cells", {"N1110", "N1111", "N1112"}}};
  p["level"] = 4;
  write_file(dir_ + "/fail.json", p.dump());
  const auto dem_before = tile_bytes(store_, "dem");
  const CliResult r = run_maquette("run " + dir_ + "/fail.json --threads 1",
                                   "MAQUETTE_MODULE_PATH=" + kFixtures + "/good");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("step 1 (fixture.fill)"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("N1111"), std::string::npos) << r.err;
  // What was stored before is intact, and with one thread the cells before the failing one
  // were written while the failing one and those after it were not.
  EXPECT_EQ(tile_bytes(store_, "dem"), dem_before);
  const auto store = Store::open(store_, Store::Mode::ReadOnly);
  EXPECT_TRUE(store->has_tile("v", CellId::Parse("N1110")));
  EXPECT_FALSE(store->has_tile("v", CellId::Parse("N1111")));
  EXPECT_FALSE(store->has_tile("v", CellId::Parse("N1112")));
}

TEST_F(CliRun, StoreErrorsAreNamed) {
  json p = small_pipeline(dir_ + "/notes.txt");
  write_file(dir_ + "/notes.txt", "not a database, just notes\n");
  const std::string notes_before = file_fingerprint(dir_ + "/notes.txt");
  write_file(dir_ + "/p.json", p.dump());
  CliResult r = run_maquette("run " + dir_ + "/p.json");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("not a Maquette store"), std::string::npos) << r.err;
  EXPECT_EQ(file_fingerprint(dir_ + "/notes.txt"), notes_before);

  // A read-only store file opened for writing (even as root, who could write it).
  fs::permissions(store_, fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
  const std::string before = store_fingerprint(store_);
  r = run_maquette("run " + dir_ + "/good.json");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("read-only"), std::string::npos) << r.err;
  EXPECT_EQ(store_fingerprint(store_), before);
  // Reading it is fine.
  EXPECT_EQ(run_maquette("info " + store_).exit_code, 0);
}

TEST(CliModules, ListsTheTerrainOperators) {
  const CliResult r = run_maquette("modules --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("terrain.derive"), std::string::npos);
  EXPECT_NE(r.out.find("terrain.synthesize"), std::string::npos);
  EXPECT_TRUE(json::accept(r.out)) << r.out;
}

// `modules NAME`: one module's operators, or one operator; a name that is neither is refused,
// listing the modules.
TEST(CliModules, ANameSelectsAModuleOrAnOperator) {
  CliResult r = run_maquette("modules terrain --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  json modules = json::parse(r.out);
  ASSERT_EQ(modules.size(), 1u);
  EXPECT_EQ(modules[0]["name"], "terrain");
  EXPECT_GT(modules[0]["operators"].size(), 1u);
  r = run_maquette("modules terrain.derive");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("terrain.derive ("), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("terrain.synthesize"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("climate"), std::string::npos) << r.out;
  r = run_maquette("modules terrian");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("no module or operator 'terrian' (the modules: "), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("terrain"), std::string::npos) << r.err;
}

TEST(CliModules, BadModulesAreRefusedNamingTheFile) {
  CliResult r = run_maquette("modules", "MAQUETTE_MODULE_PATH=" + kFixtures + "/bad_abi");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("bad_abi"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("ABI"), std::string::npos) << r.err;
  r = run_maquette("modules", "MAQUETTE_MODULE_PATH=" + kFixtures + "/no_entry");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("no_entry"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("entry point"), std::string::npos) << r.err;
}

// Checks a demo's quicklooks: decodable RGBA, mostly opaque, not one flat colour.
void expect_quicklooks(const std::string& dir, const std::vector<std::string>& names) {
  for (const std::string& name : names) {
    const cv::Mat png = cv::imread(dir + "/" + name, cv::IMREAD_UNCHANGED);
    ASSERT_FALSE(png.empty()) << name;
    EXPECT_EQ(png.channels(), 4) << name;
    std::vector<cv::Mat> planes;
    cv::split(png, planes);
    EXPECT_GT(cv::countNonZero(planes[3]), int(0.6 * double(png.total()))) << name;
    double lo = 0, hi = 0;
    cv::minMaxLoc(planes[1], &lo, &hi, nullptr, nullptr, planes[3]);
    EXPECT_GT(hi - lo, 50) << name;
  }
}

std::set<std::string> layer_names(const std::string& store) {
  const CliResult info = run_maquette("info " + store + " --json");
  EXPECT_EQ(info.exit_code, 0) << info.err;
  const json report = json::parse(info.out);  // a named object: the loop below refers into it
  std::set<std::string> names;
  for (const json& l : report["layers"]) names.insert(l["name"]);
  return names;
}

TEST(CliDemo, WithoutDataRunsTheSyntheticTerrain) {
  const std::string dir = temp_dir() + "/demo";
  const CliResult r = run_maquette("demo --output " + dir + " --threads 2 --data " + dir + "/none");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("synthetic"), std::string::npos) << r.err;  // says why
  expect_quicklooks(dir, {"dem.png", "hillshade.png", "slope.png"});
  EXPECT_EQ(layer_names(dir + "/demo.mqt"),
            (std::set<std::string>{"dem", "slope", "aspect", "curvature", "hillshade", "normal"}));
  EXPECT_NE(r.out.find("maquette info"), std::string::npos) << r.out;
}

// The real-data demo, with the Olinda data scripts/setup.sh extracts next to the build's bin/:
// terrain, and a texture fitted to the Landsat scene synthesized two levels finer than the DEM,
// on the 3D Tiles terrain.
TEST(CliDemo, IngestsTheOlindaDataAndSynthesizesItsTexture) {
  const std::string data = std::string(MAQUETTE_BIN_DIR) + "/../demo-data";
  if (!fs::exists(data + "/L7_ETMs.tif"))
    GTEST_SKIP() << "no demo data in " << data << " (scripts/setup.sh fetches it)";
  const std::string dir = temp_dir() + "/demo";
  const CliResult r = run_maquette("demo --output " + dir + " --threads 2");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("Olinda"), std::string::npos) << r.out;
  expect_quicklooks(dir, {"dem.png", "hillshade.png", "slope.png", "imagery.png", "texture.png"});
  EXPECT_EQ(layer_names(dir + "/demo.mqt"),
            (std::set<std::string>{"dem_source", "red_dn", "green_dn", "blue_dn", "imagery",
                                   "red_dn_dem_grid", "green_dn_dem_grid", "blue_dn_dem_grid",
                                   "imagery_dem_grid", "dem", "dem_filled", "slope", "aspect",
                                   "curvature", "hillshade", "normal", "classes", "texture"}));
  const auto store = Store::open(dir + "/demo.mqt", Store::Mode::ReadOnly);
  const LayerInfo dem = store->require_layer("dem"), texture = store->require_layer("texture");
  EXPECT_EQ(texture.level, dem.level);
  EXPECT_EQ(texture.tile_size, dem.tile_size << 2);  // "refine": 2
  EXPECT_EQ(store->tile_cells("texture"), store->tile_cells("dem"));
  EXPECT_TRUE(store->get_artifact("texture_model"));
  // The finest 3D Tiles carry the synthesized texture: JPEG images of its tile size (the
  // imagery's would be 256 pixels).
  int textured = 0;
  for (const auto& entry :
       fs::directory_iterator(dir + "/tiles3d/tiles/" + std::to_string(dem.level))) {
    std::ifstream in(entry.path(), std::ios::binary);
    const std::vector<uchar> glb((std::istreambuf_iterator<char>(in)),
                                 std::istreambuf_iterator<char>());
    const uchar soi[] = {0xFF, 0xD8, 0xFF};
    const auto jpeg = std::search(glb.begin(), glb.end(), std::begin(soi), std::end(soi));
    ASSERT_NE(jpeg, glb.end()) << entry.path();
    const cv::Mat image = cv::imdecode(std::vector<uchar>(jpeg, glb.end()), cv::IMREAD_COLOR);
    EXPECT_EQ(image.cols, texture.tile_size) << entry.path();
    ++textured;
  }
  EXPECT_EQ(textured, int(store->tile_cells("dem").size()));
  // demo.json names its data by absolute paths: it runs from any working directory.
  const CliResult again = run_maquette("-q run --dry-run " + dir + "/demo.json");
  EXPECT_EQ(again.exit_code, 0) << again.err;
}

}  // namespace
}  // namespace maquette::test
