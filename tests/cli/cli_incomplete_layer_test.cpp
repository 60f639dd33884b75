// A command that fails or is killed midway leaves the store as it was where it can (a layer it
// created is removed), or its layer marked incomplete: `export` and `run` refuse such a layer and
// `info` flags it, until `ingest --resume` (or a new ingest) finishes it.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>

#include "run_cli.h"
#include "store/store.h"
#include "synthetic_raster.h"

namespace maquette::test {
namespace {

using json = nlohmann::json;
namespace fs = std::filesystem;

// An Int16 DEM west of 7 E, north of 46 N, `size` pixels of `pixel` degrees a side.
RasterSpec lonlat_dem(int size, double pixel) {
  RasterSpec s = lonlat_raster(7, 46, size, pixel, "Int16");
  s.nodata = -32768;
  return s;
}

double heights(int, double lon, double lat) { return 1000 * (lon - 7) + 500 * (lat - 45); }

// `info --json` without the file's size, which a rolled-back write may change.
json info_of(const std::string& store) {
  const CliResult r = run_maquette("info " + store + " --json");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  json j = json::parse(r.out);
  j.erase("size_bytes");
  return j;
}

class IncompleteLayer : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = temp_dir();
    store = dir + "/s.mqt";
    good = dir + "/good.tif";
    write_raster(good, lonlat_dem(2000, 0.0005), heights);
    // The same file cut short: its first rows read (so the planning accepts it), its last ones
    // fail ("IReadBlock failed") while the tiles are written.
    cut = dir + "/cut.tif";
    fs::copy_file(good, cut);
    fs::resize_file(cut, fs::file_size(good) * 6 / 10);
    small = dir + "/small.tif";
    write_raster(small, lonlat_dem(100, 0.002), heights);
    const CliResult r =
        run_maquette("-q ingest " + store + " --layer a --as dem --level 9 " + small);
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }

  // Exports a PNG of `layer`: the exit code and stderr.
  CliResult export_png(const std::string& layer) {
    return run_maquette("export png " + store + " --layer " + layer + " " + dir + "/" + layer +
                        ".png");
  }

  // Runs a pipeline whose step reads `layer` as its DEM.
  CliResult run_reading(const std::string& layer) {
    const json pipeline = {{"store", store},
                           {"region", {{"bbox", {7.05, 45.55, 7.15, 45.65}}}},
                           {"level", 9},
                           {"steps",
                            {{{"op", "terrain.derive"},
                              {"inputs", {{"dem", layer}}},
                              {"outputs", {{"slope", "slope_of_" + layer}}}}}}};
    std::ofstream(dir + "/p.json") << pipeline.dump(1);
    return run_maquette("run " + dir + "/p.json");
  }

  std::string dir, store, good, cut, small;
};

TEST_F(IncompleteLayer, FailedIngestOfANewLayerLeavesTheStoreAsItWas) {
  const json before = info_of(store);
  const CliResult r =
      run_maquette("ingest " + store + " --layer b --as dem --level 9 --threads 1 " + cut);
  ASSERT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find(cut), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("read error"), std::string::npos) << r.err;
  EXPECT_EQ(info_of(store), before);  // no layer b, no tiles, no overviews
  const auto s = Store::open(store, Store::Mode::ReadOnly);
  EXPECT_FALSE(s->layer("b"));
  EXPECT_TRUE(s->integrity_ok());
  // No run record of it is left to resume.
  EXPECT_EQ(run_maquette("-q ingest " + store + " --layer b --as dem --level 9 --resume " + cut)
                .err.find("resuming"),
            std::string::npos);
}

TEST_F(IncompleteLayer, FailedIngestIntoANewStoreLeavesNoStore) {
  const std::string fresh = dir + "/fresh.mqt";
  const CliResult r = run_maquette("ingest " + fresh + " --layer b --as dem --level 9 " + cut);
  ASSERT_EQ(r.exit_code, 1) << r.err;
  for (const char* suffix : {"", "-wal", "-shm", "-journal"})
    EXPECT_FALSE(fs::exists(fresh + suffix)) << suffix;
}

TEST_F(IncompleteLayer, FailedIngestIntoAnExistingLayerIsRefusedByReadersUntilRewritten) {
  ASSERT_EQ(export_png("a").exit_code, 0);
  fs::remove(dir + "/a.png");
  const CliResult r = run_maquette("ingest " + store + " --layer a --as dem --level 9 " + cut);
  ASSERT_EQ(r.exit_code, 1) << r.err;

  const json info = info_of(store);
  ASSERT_EQ(info["layers"].size(), 1u);
  const std::string why = info["layers"][0].value("incomplete", "");
  EXPECT_NE(why.find("failed"), std::string::npos) << info.dump(1);
  EXPECT_NE(why.find("read error"), std::string::npos) << why;
  EXPECT_NE(run_maquette("info " + store).out.find("INCOMPLETE"), std::string::npos);

  const CliResult png = export_png("a");
  EXPECT_EQ(png.exit_code, 1);
  EXPECT_NE(png.err.find("layer 'a' in " + store + " is incomplete"), std::string::npos) << png.err;
  EXPECT_NE(png.err.find("--resume"), std::string::npos) << png.err;
  EXPECT_FALSE(fs::exists(dir + "/a.png"));
  const CliResult run = run_reading("a");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.err.find("inputs.dem: layer 'a'"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("is incomplete"), std::string::npos) << run.err;

  // Written again whole, it is read again.
  ASSERT_EQ(run_maquette("-q ingest " + store + " --layer a --as dem --level 9 " + good).exit_code,
            0);
  EXPECT_TRUE(info_of(store)["layers"][0]["incomplete"].is_null());
  EXPECT_EQ(export_png("a").exit_code, 0);
  const CliResult rerun = run_reading("a");
  EXPECT_EQ(rerun.exit_code, 0) << rerun.err;
}

TEST_F(IncompleteLayer, KilledIngestIsRefusedByReadersUntilResumed) {
  const std::string big = dir + "/big.mqt";
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    const std::string bin = std::string(MAQUETTE_BIN_DIR) + "/maquette";
    execl(bin.c_str(), bin.c_str(), "-q", "ingest", big.c_str(), "--layer", "d", "--as", "dem",
          "--level", "11", "--threads", "1", good.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  for (int i = 0; i < 4000; ++i) {  // killed once a few tiles are committed
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    try {
      if (fs::exists(big) && Store::open(big, Store::Mode::ReadOnly)->tile_cells("d").size() >= 3)
        break;
    } catch (const std::exception&) {
    }
  }
  kill(pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
  if (!WIFSIGNALED(status)) GTEST_SKIP() << "the ingest ended before it could be killed";

  const CliResult refused =
      run_maquette("export png " + big + " --layer d " + dir + "/d.png --max-size 64");
  EXPECT_EQ(refused.exit_code, 1);
  EXPECT_NE(refused.err.find("is running or was interrupted"), std::string::npos) << refused.err;
  const CliResult resumed =
      run_maquette("ingest " + big + " --layer d --as dem --level 11 --threads 1 --resume " + good);
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  const CliResult png =
      run_maquette("export png " + big + " --layer d " + dir + "/d.png --max-size 64");
  EXPECT_EQ(png.exit_code, 0) << png.err;
}

// A pipeline step failing on its last cell: its output layer holds the cells before, and stays
// marked until a run writes it whole.
TEST_F(IncompleteLayer, RunFailingMidwayLeavesItsOutputRefused) {
  std::string cells = run_maquette("cells cover --bbox 6 44 9 46 --level 5").out;
  cells.pop_back();
  const std::string last = cells.substr(cells.rfind('\n') + 1);
  json p = {{"store", store},
            {"region", {{"bbox", {6, 44, 9, 46}}}},
            {"level", 5},
            {"tile_size", 16},
            {"steps",
             {{{"op", "fixture.fill"},
               {"outputs", {{"value", "v"}}},
               {"params", {{"seed", 2}, {"fail_on", last}}}}}}};
  std::ofstream(dir + "/fail.json") << p.dump();
  const std::string env =
      "MAQUETTE_MODULE_PATH=" + std::string(MAQUETTE_FIXTURE_MODULE_DIR) + "/good";
  const CliResult failed = run_maquette("run " + dir + "/fail.json --threads 1", env);
  ASSERT_EQ(failed.exit_code, 1) << failed.err;
  EXPECT_GT(Store::open(store, Store::Mode::ReadOnly)->tile_cells("v").size(), 0u);

  const CliResult png = export_png("v");
  EXPECT_EQ(png.exit_code, 1);
  EXPECT_NE(png.err.find("layer 'v' in " + store + " is incomplete"), std::string::npos) << png.err;
  EXPECT_NE(png.err.find("fixture failure requested"), std::string::npos) << png.err;

  p["steps"][0]["params"].erase("fail_on");
  std::ofstream(dir + "/ok.json") << p.dump();
  const CliResult ok = run_maquette("run " + dir + "/ok.json", env);
  ASSERT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_EQ(export_png("v").exit_code, 0);
}

// A run failing before it writes a layer that was complete (its step failing on every cell, or
// a later step never started) leaves that layer as it was: complete, the same tiles. A task
// (an ingest) writes before it records its cells, so its layers stay marked whatever it wrote.
TEST_F(IncompleteLayer, RunFailingBeforeItWritesALayerLeavesItReadable) {
  std::string cells = run_maquette("cells cover --bbox 6 44 9 46 --level 5").out;
  const std::string face = cells.substr(0, 1);  // every cell's id starts with its face
  json p = {{"store", store},
            {"region", {{"bbox", {6, 44, 9, 46}}}},
            {"level", 5},
            {"tile_size", 16},
            {"steps",
             {{{"op", "fixture.fill"}, {"outputs", {{"value", "v"}}}, {"params", {{"seed", 2}}}},
              {{"op", "fixture.blur"},
               {"inputs", {{"src", "v"}}},
               {"outputs", {{"dst", "w"}}},
               {"params", json::object()}}}}};
  const std::string env =
      "MAQUETTE_MODULE_PATH=" + std::string(MAQUETTE_FIXTURE_MODULE_DIR) + "/good";
  const auto run = [&](const json& pipeline) {
    std::ofstream(dir + "/p2.json") << pipeline.dump();
    return run_maquette("run " + dir + "/p2.json --threads 2", env);
  };
  const auto png_bytes = [&](const std::string& layer) {
    const CliResult r = export_png(layer);
    EXPECT_EQ(r.exit_code, 0) << layer << ": " << r.err;
    std::ifstream in(dir + "/" + layer + ".png", std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  ASSERT_EQ(run(p).exit_code, 0);
  const std::string v = png_bytes("v"), w = png_bytes("w");
  ASSERT_FALSE(v.empty());
  // Each layer's provenance, the params of the step that wrote its tiles.
  const auto provenance = [&] {
    const json info = info_of(store);
    std::map<std::string, json> out;
    for (const json& layer : info.at("layers"))
      out[layer.at("name").get<std::string>()] = layer.at("provenance");
    return out;
  };
  const auto written_by = provenance();
  ASSERT_EQ(written_by.at("v")["params"]["seed"], 2);

  // The first step fails on every cell: neither layer is written, both stay readable.
  json failing = p;
  failing["steps"][0]["params"]["fail_on"] = face;
  const CliResult first = run(failing);
  ASSERT_EQ(first.exit_code, 1) << first.err;
  EXPECT_NE(first.err.find("fixture failure requested"), std::string::npos) << first.err;
  EXPECT_EQ(run_maquette("info " + store).out.find("INCOMPLETE"), std::string::npos);
  EXPECT_EQ(png_bytes("v"), v);
  EXPECT_EQ(png_bytes("w"), w);
  EXPECT_EQ(provenance(), written_by);  // not the failed run's params

  // The second fails on every cell: the first rewrote v whole, w is as it was.
  failing = p;
  failing["steps"][1]["params"]["fail_on"] = face;
  ASSERT_EQ(run(failing).exit_code, 1);
  EXPECT_EQ(png_bytes("v"), v);
  EXPECT_EQ(png_bytes("w"), w);
  EXPECT_EQ(provenance().at("w"), written_by.at("w"));

  // Failing on its last cell, the first step has written the others: v is refused (as in
  // RunFailingMidwayLeavesItsOutputRefused), w, never started, is not.
  cells.pop_back();
  failing = p;
  failing["steps"][0]["params"]["fail_on"] = cells.substr(cells.rfind('\n') + 1);
  ASSERT_EQ(run(failing).exit_code, 1);
  EXPECT_EQ(export_png("v").exit_code, 1);
  EXPECT_EQ(png_bytes("w"), w);
}

}  // namespace
}  // namespace maquette::test
