// `maquette run` under mpirun with 2 and 3 ranks, as users run it: every layer's tile blobs,
// overview blobs and artifacts must be bit-identical to a single-process run, for the fixture and
// terrain operators and for every climate and texture operator (reduce ones included); a failing
// cell names its rank, step and cell; a rank killed with SIGKILL leaves a valid store that --resume
// completes (with 3 ranks, or one process) to the same bits. MPI is loaded from its plug-in by
// launched runs only, and a missing plug-in is named. With --store-copies, each rank in its own
// directory and the store in the writer's (rank 0's) only, the others given copies: the same
// bits with 2, 3 and 4 ranks, in the store and in every copy; --resume after a killed rank; a
// copy that differs from the writer's store refused before anything runs.
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sqlite3.h>
#include <stdlib.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>

#include "core/face_plane.h"
#include "core/grid.h"
#include "run_cli.h"
#include "store/store.h"
#include "turned_edges.h"

extern char** environ;

namespace maquette {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const std::string kMaquette = std::string(MAQUETTE_BIN_DIR) + "/maquette";
// No exemplar cache (synthesis.transfer): each run analyses its painting, on its ranks, and
// nothing is written to the user's cache.
const std::string kEnv = std::string("MAQUETTE_MODULE_PATH=") + MAQUETTE_FIXTURE_MODULE_DIR +
                         "/good MAQUETTE_CACHE_DIR=off";

// `maquette run` of DIR/pipeline.json, alone (ranks 0) or under mpirun, one thread per process.
// `rank_env` (NAME=value) is set for `program` only, not for mpirun.
std::string run_command(const std::string& dir, int ranks, const std::string& extra = "",
                        const std::string& rank_env = "", const std::string& program = kMaquette) {
  const std::string run = program + " run --threads 1 " + extra + " " + dir + "/pipeline.json";
  if (ranks == 0) return "env " + kEnv + " " + rank_env + " " + run;
  return "env " + kEnv + " " + MAQUETTE_MPIEXEC +
         " --oversubscribe --allow-run-as-root -x MAQUETTE_MODULE_PATH -x MAQUETTE_CACHE_DIR " +
         (rank_env.empty() ? "" : "-x " + rank_env) + " -np " + std::to_string(ranks) + " " + run;
}

struct Result {
  int exit_code = -1;
  std::string err;
};

// Runs `command`, its stderr kept in DIR/stderr.
Result run_shell(const std::string& command, const std::string& dir) {
  const std::string err = dir + "/stderr";
  const int status = std::system((command + " >/dev/null 2>" + err).c_str());
  std::ostringstream text;
  text << std::ifstream(err).rdbuf();
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, text.str()};
}

Result run(const std::string& dir, int ranks, const std::string& extra = "",
           const std::string& rank_env = "", const std::string& program = kMaquette) {
  return run_shell(run_command(dir, ranks, extra, rank_env, program), dir);
}

// The directory of this test process's pipelines, removed at exit.
struct TempRoot {
  fs::path path = fs::temp_directory_path() / ("maquette-mpi-" + std::to_string(getpid()));
  ~TempRoot() { fs::remove_all(path); }
};
const TempRoot temp_root;

// Every operator kind and every terrain operator, on 64 cells of 64 pixels. fixture.blur (step
// 5) takes `blur` as extra params (sleep_ms, fail_on).
// A new directory for one run.
fs::path new_dir() {
  static int counter = 0;
  const fs::path dir = temp_root.path / std::to_string(counter++);
  fs::create_directories(dir);
  return dir;
}

std::string write_pipeline(const json& blur = json::object()) {
  const fs::path dir = new_dir();
  const json pipeline = {
      {"store", "out.mqt"},
      {"region", {{"cells", {"Q2"}}}},
      {"level", 4},
      {"tile_size", 64},  // terrain.fill_voids has a halo of 64
      {"steps",
       {{{"op", "terrain.synthesize"}, {"outputs", {{"dem", "dem"}}}, {"params", {{"seed", 7}}}},
        {{"op", "terrain.fill_voids"},
         {"inputs", {{"dem", "dem"}}},
         {"outputs", {{"dem", "filled"}, {"filled", "filled_mask"}}}},
        {{"op", "terrain.derive"},
         {"inputs", {{"dem", "filled"}}},
         {"outputs", {{"slope", "slope"}, {"hillshade", "hillshade"}, {"normal", "normal"}}}},
        {{"op", "fixture.fill"}, {"outputs", {{"value", "height"}}}, {"params", {{"seed", 1.5}}}},
        {{"op", "fixture.blur"},
         {"inputs", {{"src", "height"}}},
         {"outputs", {{"dst", "smooth"}}},
         {"params", blur}},
        {{"op", "fixture.sum"},
         {"inputs", {{"src", "smooth"}}},
         {"outputs", {{"total", "smooth_sum"}}}},
        // The reduce step's artifact in a param of a step the copies do not run (its own params
        // are not read by the fixture: the pasting is what is tried).
        {{"op", "fixture.region_scan"},
         {"inputs", {{"src", "smooth"}}},
         {"outputs", {{"dst", "scan"}}},
         {"params", {{"total", {{"$artifact", "smooth_sum"}}}}}}}}};
  std::ofstream(dir / "pipeline.json") << pipeline.dump(2);
  return dir.string();
}

// The stations artifact climate.fit_stations reads from the store: elevations 200..2290 m around
// (30 E, 10 S), in the region the tests run on, t and p linear in elevation with some scatter.
void put_stations(const std::string& store) {
  json stations = json::array();
  for (int i = 0; i < 12; ++i) {
    const double z = 200 + 190 * i;
    stations.push_back({{"id", std::to_string(i)},
                        {"lon", 30 + 0.5 * (i % 4)},
                        {"lat", -10 + 0.5 * (i % 3)},
                        {"elevation", z},
                        {"values",
                         {{"t", 25 - 6.5 * z / 1000 + 0.1 * (i % 3)},
                          {"p", 400 + 300 * z / 1000 + 5.0 * (i % 2)}}}});
  }
  const std::string text = json{{"columns", {"t", "p"}}, {"stations", stations}}.dump();
  Store::open(store, Store::Mode::Create)->put_artifact(Artifact::FromText("stations", text));
}

// Every climate and texture operator on 16 cells of 64 pixels, on a synthesized DEM: the climate
// chain from a stations artifact put in the store beforehand, and an RGB image rendered by
// texture.procedural from a hand-made model (and 2 levels finer), clustered, classified, fitted and
// assessed.
std::string write_module_pipeline() {
  const fs::path dir = new_dir();
  put_stations((dir / "out.mqt").string());
  const json model = json::parse(R"({
    "format": "maquette.texture.model", "version": 1,
    "quantities": [{"name": "height", "range": [-500, 4000]}, {"name": "slope", "range": [0, 90]}],
    "root": {"colour": [150, 110, 90], "class": 0, "children": [
      {"class": 1, "colour": [90, 150, 60], "noise_scale": 0.2, "noise": {"seed": 5},
       "constraints": {"height": {"hat": [-500, 0, 800, 1200]}}},
      {"class": 2, "colour": [30, 75, 40], "noise_scale": 0.2, "noise": {"seed": 6},
       "constraints": {"slope": {"hat": [0, 0, 2, 5]}}}]}})");
  const json centres = {{{"id", 0}, {"hue", 20}, {"saturation", 0.4}},
                        {{"id", 1}, {"hue", 95}, {"saturation", 0.6}},
                        {{"id", 2}, {"hue", 140}, {"saturation", 0.6}}};
  const json pipeline = {
      {"store", "out.mqt"},
      {"region", {{"cells", {"Q21"}}}},
      {"level", 4},
      {"tile_size", 64},
      {"steps",
       {{{"op", "terrain.synthesize"}, {"outputs", {{"dem", "dem"}}}, {"params", {{"seed", 7}}}},
        {{"op", "climate.fit_stations"},
         {"outputs", {{"fit", "fit"}}},
         {"params", {{"stations", "stations"}, {"columns", {"t", "p"}}}}},
        {{"op", "climate.regionalize"},
         {"inputs", {{"dem", "dem"}}},
         {"outputs", {{"temperature", "t"}, {"precipitation", "p0"}}},
         {"params", {{"fit", "fit"}, {"temperature_column", "t"}, {"precipitation_column", "p"}}}},
        {{"op", "climate.orographic"},
         {"inputs", {{"dem", "dem"}, {"precipitation", "p0"}}},
         {"outputs", {{"precipitation", "p"}}}},
        {{"op", "climate.solar"},
         {"inputs", {{"dem", "dem"}}},
         {"outputs", {{"radiation", "sun"}}},
         {"params", {{"day_step", 60}, {"minutes", 60}}}},
        {{"op", "texture.procedural"},
         {"inputs", {{"dem", "dem"}}},
         {"outputs", {{"imagery", "rgb"}, {"classes", "truth"}}},
         {"params", {{"model", model}}}},
        {{"op", "texture.procedural"},
         {"inputs", {{"dem", "dem"}}},
         {"outputs", {{"imagery", "fine_rgb"}}},
         {"params", {{"model", model}}},
         {"refine", 2}},
        {{"op", "texture.cluster"},
         {"inputs", {{"rgb", "rgb"}}},
         {"outputs", {{"clusters", "clusters"}}},
         {"params", {{"k", 3}}}},
        {{"op", "texture.classify"},
         {"inputs", {{"rgb", "rgb"}, {"dem", "dem"}}},
         {"outputs", {{"classes", "classes"}}},
         {"params", {{"centres", centres}}}},
        {{"op", "texture.fit"},
         {"inputs", {{"classes", "classes"}, {"rgb", "rgb"}, {"dem", "dem"}}},
         {"outputs", {{"model", "model"}}},
         {"params", {{"ranges", {{"height", {-500, 4000}}}}}}},
        {{"op", "texture.assess"},
         {"inputs",
          {{"classes", "classes"}, {"predicted", "truth"}, {"rgb", "rgb"}, {"synthesized", "rgb"}}},
         {"outputs", {{"report", "assessment"}}}}}}};
  std::ofstream(dir / "pipeline.json") << pipeline.dump(2);
  return dir.string();
}

// Rows of a query on the store, each row's columns joined; blobs as FNV-1a hashes.
std::vector<std::string> rows(const std::string& store, const std::string& sql) {
  sqlite3* db = nullptr;
  sqlite3_open_v2(store.c_str(), &db, SQLITE_OPEN_READONLY, nullptr);
  sqlite3_busy_timeout(db, 10000);
  sqlite3_stmt* q = nullptr;
  std::vector<std::string> out;
  if (sqlite3_prepare_v2(db, sql.c_str(), -1, &q, nullptr) == SQLITE_OK) {
    while (sqlite3_step(q) == SQLITE_ROW) {
      std::string row;
      for (int i = 0; i < sqlite3_column_count(q); ++i) {
        if (sqlite3_column_type(q, i) == SQLITE_BLOB) {
          const auto* p = static_cast<const unsigned char*>(sqlite3_column_blob(q, i));
          uint64_t h = 14695981039346656037ull;
          for (int k = 0; k < sqlite3_column_bytes(q, i); ++k) h = (h ^ p[k]) * 1099511628211ull;
          row += std::to_string(h);
        } else if (const auto* t = sqlite3_column_text(q, i)) {
          row += reinterpret_cast<const char*>(t);
        }
        row += "|";
      }
      out.push_back(row);
    }
  }
  sqlite3_finalize(q);
  sqlite3_close(db);
  return out;
}

// Every tile blob, overview blob and artifact of the store, by layer and cell.
std::vector<std::string> blobs(const std::string& dir) {
  const std::string store = dir + "/out.mqt";
  auto all = rows(store,
                  "SELECT l.name, t.cell, t.blob FROM tiles t JOIN layers l ON l.id = t.layer "
                  "ORDER BY l.name, t.cell");
  for (auto& r : rows(store,
                      "SELECT l.name, o.level, o.cell, o.blob FROM overviews o JOIN layers l ON "
                      "l.id = o.layer ORDER BY l.name, o.level, o.cell"))
    all.push_back("overview|" + r);
  for (auto& r : rows(store, "SELECT name, data FROM artifacts ORDER BY name"))
    all.push_back("artifact|" + r);
  return all;
}

const std::vector<std::string>& reference() {
  static const std::vector<std::string> expected = [] {
    const std::string dir = write_pipeline();
    const Result r = run(dir, 0);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return blobs(dir);
  }();
  return expected;
}

TEST(Mpi, ModuleOperatorsGiveTheSingleProcessBits) {
  const std::string single = write_module_pipeline();
  const Result one = run(single, 0);
  ASSERT_EQ(one.exit_code, 0) << one.err;
  const std::vector<std::string> expected = blobs(single);
  // 9 raster layers of 16 tiles, 5 artifacts of steps and the stations.
  ASSERT_GT(expected.size(), 16u * 9 + 6);
  for (const char* artifact : {"fit", "clusters", "model", "assessment", "stations"})
    EXPECT_EQ(std::count_if(expected.begin(), expected.end(),
                            [&](const std::string& row) {
                              return row.starts_with("artifact|" + std::string(artifact) + "|");
                            }),
              1)
        << artifact;
  for (const int ranks : {2, 3}) {
    SCOPED_TRACE(std::to_string(ranks) + " ranks");
    const std::string dir = write_module_pipeline();
    const Result r = run(dir, ranks);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(blobs(dir), expected);
  }
}

bool store_valid(const std::string& dir) {
  return Store::open(dir + "/out.mqt", Store::Mode::ReadOnly)->integrity_ok();
}

TEST(Mpi, PlainRunPrintsNoMpiNoise) {
  const std::string dir = write_pipeline();
  const Result r = run(dir, 0);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find("MPI"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("rank"), std::string::npos) << r.err;
}

// The dynamic loader's trace (LD_DEBUG=files) names every library a process loads: a plain run
// loads neither MPI nor the MPI plug-in; a launched one loads the plug-in beside libmaquette, and
// MPI with it.
TEST(Mpi, OnlyALaunchedRunLoadsMpi) {
  const std::string plugin =
      (fs::path(MAQUETTE_BIN_DIR).parent_path() / "lib" / "libmaquette_mpi.so").string();
  const std::string plain_dir = write_pipeline();
  const Result plain = run(plain_dir, 0, "", "LD_DEBUG=files");
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  ASSERT_NE(plain.err.find("libmaquette.so"), std::string::npos) << "no loader trace";
  EXPECT_EQ(plain.err.find("libmpi"), std::string::npos);
  EXPECT_EQ(plain.err.find("libmaquette_mpi.so"), std::string::npos);

  const std::string dir = write_pipeline();
  const Result launched = run(dir, 2, "", "LD_DEBUG=files");
  ASSERT_EQ(launched.exit_code, 0) << launched.err;
  EXPECT_NE(launched.err.find("file=" + plugin), std::string::npos);
  EXPECT_NE(launched.err.find("libmpi.so"), std::string::npos);
  EXPECT_EQ(blobs(dir), blobs(plain_dir));
}

// A copy of the program in PREFIX/bin without PREFIX/lib, so without its plug-ins: under mpirun it
// stops before opening the store, naming the plug-in it looked for.
TEST(Mpi, MissingPluginIsNamed) {
  const std::string dir = write_pipeline();
  const fs::path prefix = fs::path(dir) / "prefix";
  const Result r = run(dir, 2, "", "", test::install_without_plugins(prefix.string()));
  EXPECT_NE(r.exit_code, 0);
  const std::string looked_for = (prefix / "lib" / "libmaquette_mpi.so").string();
  EXPECT_NE(r.err.find("maquette: error: cannot load the plug-in " + looked_for), std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(dir + "/out.mqt"));
}

TEST(Mpi, RanksGiveTheSingleProcessBits) {
  ASSERT_GT(reference().size(), 64u * 8);  // 8 raster layers of 64 tiles, overviews, artifact
  for (const int ranks : {2, 3}) {
    SCOPED_TRACE(std::to_string(ranks) + " ranks");
    const std::string dir = write_pipeline();
    const Result r = run(dir, ranks);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(blobs(dir), reference());
    EXPECT_EQ(rows(dir + "/out.mqt", "SELECT status FROM runs"), std::vector<std::string>{"ok|"});
  }
}

TEST(Mpi, FailingCellNamesRankStepAndCell) {
  // Cells are shared in id order: with 2 ranks Q23xx (the last 16 of 64) belong to rank 1.
  const std::string dir = write_pipeline({{"fail_on", "Q23"}});
  const Result r = run(dir, 2);
  EXPECT_NE(r.exit_code, 0);
  const std::string message =
      "rank 1 of 2: step 5 (fixture.blur) failed on cell Q2300: fixture failure requested";
  // The error names the pipeline; the run's record, of that pipeline, need not.
  EXPECT_NE(r.err.find("maquette: error: " + dir + "/pipeline.json: " + message), std::string::npos)
      << r.err;
  EXPECT_TRUE(store_valid(dir));
  EXPECT_EQ(rows(dir + "/out.mqt", "SELECT status FROM runs"),
            std::vector<std::string>{"failed: " + message + "|"});
}

// The pid of the process of `rank` started by mpirun `launcher`, or 0.
pid_t rank_pid(pid_t launcher, int rank) {
  for (const auto& entry : fs::directory_iterator("/proc")) {
    std::ifstream stat(entry.path() / "stat");
    std::string pid, comm, state;
    pid_t ppid = 0;
    if (!(stat >> pid >> comm >> state >> ppid) || ppid != launcher) continue;
    std::ifstream env(entry.path() / "environ");
    for (std::string var; std::getline(env, var, '\0');)
      if (var == "OMPI_COMM_WORLD_RANK=" + std::to_string(rank)) return std::stoi(pid);
  }
  return 0;
}

// Starts a 2-rank run (`command`: run_command's by default) whose fixture.blur takes 40 ms a
// cell, kills rank 1 with SIGKILL once some cells of that step are done, and waits for mpirun to
// end the job.
void kill_mid_step(const std::string& dir, std::string command = "") {
  if (command.empty()) command = run_command(dir, 2);
  const std::string cmd = "exec " + command + " >/dev/null 2>" + dir + "/stderr";
  const char* argv[] = {"/bin/sh", "-c", cmd.c_str(), nullptr};
  pid_t launcher = 0;
  ASSERT_EQ(
      posix_spawn(&launcher, "/bin/sh", nullptr, nullptr, const_cast<char* const*>(argv), environ),
      0);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  auto blur_cells_done = [&] {
    if (!fs::exists(dir + "/out.mqt")) return 0;
    const auto count = rows(dir + "/out.mqt", "SELECT count(*) FROM run_cells WHERE step = 5");
    return count.empty() ? 0 : std::stoi(count.front());
  };
  while (std::chrono::steady_clock::now() < deadline && blur_cells_done() < 6)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  const pid_t victim = rank_pid(launcher, 1);
  ASSERT_GT(victim, 0);
  kill(victim, SIGKILL);
  int status = 0;
  waitpid(launcher, &status, 0);
  EXPECT_FALSE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  EXPECT_TRUE(store_valid(dir));
  const auto statuses = rows(dir + "/out.mqt", "SELECT status FROM runs");
  EXPECT_EQ(statuses, std::vector<std::string>{"running|"});
}

TEST(Mpi, KilledRankResumesToTheSameBits) {
  for (const int resume_ranks : {3, 0}) {
    SCOPED_TRACE(resume_ranks == 0 ? "resumed by one process" : "resumed with 3 ranks");
    const json slow = {{"sleep_ms", 40}};
    const std::string dir = write_pipeline(slow);
    kill_mid_step(dir);
    const Result r = run(dir, resume_ranks, "--resume");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("resuming run 1"), std::string::npos) << r.err;
    EXPECT_EQ(blobs(dir), reference());
  }
}

// The working directory of `rank` under --store-copies: DIR for the writer, DIR/rank<R> else.
fs::path rank_dir(const std::string& dir, int rank) {
  return rank == 0 ? fs::path(dir) : fs::path(dir) / ("rank" + std::to_string(rank));
}

// Gives ranks 1..ranks-1 their directories, each with the pipeline and a copy of the writer's
// store as it is now (with its WAL: a killed run leaves commits there), if there is one.
void copy_store(const std::string& dir, int ranks) {
  for (int r = 1; r < ranks; ++r) {
    const fs::path to = rank_dir(dir, r);
    fs::remove_all(to);
    fs::create_directories(to);
    fs::copy_file(fs::path(dir) / "pipeline.json", to / "pipeline.json");
    for (const char* file : {"out.mqt", "out.mqt-wal"})
      if (fs::exists(fs::path(dir) / file)) fs::copy_file(fs::path(dir) / file, to / file);
  }
}

// `maquette run --store-copies pipeline.json` under mpirun, each rank started in its own
// directory (an app context per rank), so that each opens the store there: the writer's or a
// copy. `piece_bytes`: messages between ranks go in pieces of that many bytes
// (MAQUETTE_MPI_PIECE_BYTES), or of the default 1 GiB when 0.
std::string copies_command(const std::string& dir, int ranks, const std::string& extra = "",
                           size_t piece_bytes = 0) {
  const std::string pieces =
      piece_bytes == 0 ? "" : "MAQUETTE_MPI_PIECE_BYTES=" + std::to_string(piece_bytes);
  std::string command = "env " + kEnv + " " + pieces + " " + MAQUETTE_MPIEXEC +
                        " --oversubscribe --allow-run-as-root";
  for (int r = 0; r < ranks; ++r)
    command += std::string(r == 0 ? "" : " :") + " -x MAQUETTE_MODULE_PATH " +
               (pieces.empty() ? "" : "-x MAQUETTE_MPI_PIECE_BYTES ") + "-np 1 -wdir " +
               rank_dir(dir, r).string() + " " + kMaquette + " run --threads 1 --store-copies " +
               extra + " pipeline.json";
  return command;
}

Result run_copies(const std::string& dir, int ranks, const std::string& extra = "",
                  size_t piece_bytes = 0) {
  return run_shell(copies_command(dir, ranks, extra, piece_bytes), dir);
}

// With 3 ranks the messages go in pieces of 1021 bytes (a batch of the fixture's tiles is
// larger), as messages of 2 GiB or more go in pieces of 1 GiB.
TEST(MpiStoreCopies, RanksGiveTheSingleProcessBits) {
  for (const int ranks : {2, 3, 4}) {
    SCOPED_TRACE(std::to_string(ranks) + " ranks");
    const std::string dir = write_pipeline();
    copy_store(dir, ranks);  // no store yet: each rank makes its own
    const Result r = run_copies(dir, ranks, "", ranks == 3 ? 1021 : 0);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(blobs(dir), reference());
    EXPECT_EQ(rows(dir + "/out.mqt", "SELECT status FROM runs"), std::vector<std::string>{"ok|"});
    // Every copy got what every rank wrote for the next steps, and built the same overviews:
    // all but the outputs of the last two steps (a reduce and a region step), which no step
    // after them reads on the copies.
    std::vector<std::string> read_later = reference();
    std::erase_if(read_later, [](const std::string& row) {
      return row.starts_with("scan|") || row.starts_with("overview|scan|") ||
             row.starts_with("artifact|smooth_sum|");
    });
    ASSERT_LT(read_later.size(), reference().size());
    for (int rank = 1; rank < ranks; ++rank) EXPECT_EQ(blobs(rank_dir(dir, rank)), read_later);
  }
}

// Reduce steps whose artifacts later steps read (climate.fit_stations, then
// climate.regionalize), an artifact put in the store before the run (the stations), refined
// tiles.
TEST(MpiStoreCopies, ModuleOperatorsGiveTheSingleProcessBits) {
  const std::string single = write_module_pipeline();
  const Result one = run(single, 0);
  ASSERT_EQ(one.exit_code, 0) << one.err;
  for (const int ranks : {2, 4}) {
    SCOPED_TRACE(std::to_string(ranks) + " ranks");
    const std::string dir = write_module_pipeline();
    copy_store(dir, ranks);
    const Result r = run_copies(dir, ranks);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(blobs(dir), blobs(single));
  }
}

// Every row of every table of the store (blobs hashed), sorted, and its file's bytes hashed.
std::vector<std::string> store_state(const std::string& dir) {
  const std::string store = dir + "/out.mqt";
  std::vector<std::string> state;
  for (const std::string& table :
       rows(store, "SELECT name FROM sqlite_master WHERE type = 'table'")) {
    const std::string name = table.substr(0, table.size() - 1);  // without the column's '|'
    std::vector<std::string> table_rows = rows(store, "SELECT * FROM " + name);
    std::sort(table_rows.begin(), table_rows.end());
    for (std::string& row : table_rows) state.push_back(name + "|" + row);
  }
  std::ostringstream bytes;
  bytes << std::ifstream(store, std::ios::binary).rdbuf();
  state.push_back("file|" + std::to_string(std::hash<std::string>{}(bytes.str())));
  return state;
}

// A copy that differs from the writer's store (here: missing) stops the run before any rank
// writes: the writer's store, complete from an earlier run, and the other copy keep every row
// and byte (no run record, no layer marked incomplete), and no copy is made where none was.
TEST(MpiStoreCopies, DifferentCopyIsRefusedBeforeAnythingRuns) {
  const std::string dir = write_module_pipeline();
  const Result first = run(dir, 0);
  ASSERT_EQ(first.exit_code, 0) << first.err;
  copy_store(dir, 3);
  fs::remove(rank_dir(dir, 2) / "out.mqt");
  const std::vector<std::string> writer = store_state(dir);
  const std::vector<std::string> copy = store_state(rank_dir(dir, 1));
  ASSERT_GT(writer.size(), 16u * 9);
  ASSERT_TRUE(std::any_of(writer.begin(), writer.end(),
                          [](const std::string& row) { return row.starts_with("runs|1|"); }));
  const Result r = run_copies(dir, 3);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(
      r.err.find(
          "maquette: error: pipeline.json: rank 2 of 3: its copy of the store out.mqt differs from "
          "the writer's (rank 0): /artifacts/assessment is nothing there"),
      std::string::npos)
      << r.err;
  EXPECT_EQ(store_state(dir), writer);
  EXPECT_EQ(store_state(rank_dir(dir, 1)), copy);
  EXPECT_FALSE(fs::exists(rank_dir(dir, 2) / "out.mqt"));
}

// Ranks cutting messages into pieces of different sizes are refused when they start, naming the
// variable and the ranks (the variable set for rank 1's program only).
TEST(MpiStoreCopies, DifferentPieceSizesAreRefused) {
  const std::string dir = write_pipeline();
  copy_store(dir, 2);
  std::string command = copies_command(dir, 2);
  const std::string rank1 = "-wdir " + rank_dir(dir, 1).string() + " ";
  const size_t at = command.find(rank1);
  ASSERT_NE(at, std::string::npos) << command;
  command.insert(at + rank1.size(), "env MAQUETTE_MPI_PIECE_BYTES=4096 ");
  const Result r = run_shell(command, dir);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("MAQUETTE_MPI_PIECE_BYTES differs between the ranks: 1073741824 on rank 0, "
                       "4096 on rank 1: give every rank the same (mpirun -x "
                       "MAQUETTE_MPI_PIECE_BYTES)"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(fs::path(dir) / "out.mqt"));
}

// An ingest writes the store outside the relayed batches: refused before the store is made.
TEST(MpiStoreCopies, IngestIsRefused) {
  const fs::path dir = new_dir();
  const json pipeline = {{"store", "out.mqt"},
                         {"region", {{"cells", {"Q2"}}}},
                         {"level", 4},
                         {"steps",
                          {{{"op", "ingest"},
                            {"outputs", {{"layer", "points"}}},
                            {"params", {{"sources", {"points.geojson"}}, {"as", "features"}}}}}}};
  std::ofstream(dir / "pipeline.json") << pipeline.dump(2);
  copy_store(dir.string(), 2);
  for (const fs::path& d : {dir, rank_dir(dir.string(), 1)})
    std::ofstream(d / "points.geojson")
        << R"({"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {},
               "geometry": {"type": "Point", "coordinates": [30.5, -10.2]}}]})";
  const Result r = run_copies(dir.string(), 2);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("maquette: error: pipeline.json: rank 0 of 2: step 1 (ingest): writes on "
                       "the writer rank "
                       "alone, which --store-copies cannot pass to the other ranks' copies"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(dir / "out.mqt"));
}

// A run failing before it writes a complete layer leaves it with the provenance it had (the
// params later steps read), in the writer's store and in every copy alike (each copy took the
// run's params too when the run created its output layers).
TEST(MpiStoreCopies, AFailedRunGivesTheUntouchedLayersTheirProvenanceBackInEveryCopy) {
  const std::string dir = write_pipeline();
  copy_store(dir, 2);
  ASSERT_EQ(run_copies(dir, 2).exit_code, 0);
  const std::string provenance = "SELECT name, provenance FROM layers ORDER BY name";
  const std::vector<std::string> before = rows(dir + "/out.mqt", provenance);
  // fixture.blur (step 5) fails on every cell: it and the steps after it write nothing. The
  // copies staged again from the writer's store, as a new job would.
  const fs::path pipeline = fs::path(dir) / "pipeline.json";
  json p = json::parse(std::ifstream(pipeline));
  p["steps"][4]["params"] = {{"fail_on", "Q"}};
  std::ofstream(pipeline) << p.dump(2);
  copy_store(dir, 2);
  const Result failed = run_copies(dir, 2);
  EXPECT_NE(failed.exit_code, 0);
  EXPECT_NE(failed.err.find("fixture failure requested"), std::string::npos) << failed.err;
  EXPECT_EQ(rows(dir + "/out.mqt", provenance), before);
  EXPECT_EQ(rows(rank_dir(dir, 1).string() + "/out.mqt", provenance), before);
}

TEST(MpiStoreCopies, KilledRankResumesToTheSameBits) {
  const std::string dir = write_pipeline({{"sleep_ms", 40}});
  copy_store(dir, 2);
  kill_mid_step(dir, copies_command(dir, 2));
  std::ostringstream err;
  err << std::ifstream(dir + "/stderr").rdbuf();
  EXPECT_NE(err.str().find("maquette: error: rank 0 (the writer): the launcher is ending the job"),
            std::string::npos)
      << err.str();
  // The writer committed the cells of both ranks it received: the copies are made again from
  // its store, as a new job would stage them.
  copy_store(dir, 3);
  const Result r = run_copies(dir, 3, "--resume");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("resuming run 1"), std::string::npos) << r.err;
  EXPECT_EQ(blobs(dir), reference());
}

// synthesis.transfer (issue 18: the same bits for any ranks and window) on a land cover made by
// texture.procedural: a 128 x 96 painting of two regions written as a binary PPM, cells of 256
// pixels (the transfer's halo is 213). The land cover is made once over the windows and a ring
// of cells around them, so that every window's halo reads it; each transfer runs on a copy.
void write_painting(const fs::path& file) {
  const int w = 128, h = 96;
  std::ofstream out(file, std::ios::binary);
  out << "P6\n" << w << " " << h << "\n255\n";
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int noise = int((uint32_t(x * 7919 + y * 104729) * 2654435761u) >> 27);  // 0..31
      const bool right = x >= w / 2;
      const char rgb[3] = {char(right ? 40 + 2 * (x % 9) + noise : 180 + 2 * (y % 13) + noise),
                           char(right ? 110 + noise : 170 + noise), char(right ? 50 : 60 + noise)};
      out.write(rgb, 3);
    }
}

json synthesis_pipeline(const std::vector<std::string>& cells, const json& steps) {
  return {{"store", "out.mqt"},
          {"region", {{"cells", cells}}},
          {"level", 3},
          {"tile_size", 256},
          {"steps", steps}};
}

std::vector<std::string> cell_texts(const std::vector<CellId>& cells) {
  std::vector<std::string> out;
  for (const CellId c : cells) out.push_back(c.ToText());
  return out;
}

// The transfer's tile blobs of `cells` (all of them when empty).
std::vector<std::string> painted(const std::string& dir, const std::vector<CellId>& cells = {}) {
  std::vector<std::string> out;
  for (const std::string& row : blobs(dir)) {
    if (!row.starts_with("painted")) continue;
    if (cells.empty() || std::any_of(cells.begin(), cells.end(), [&](CellId c) {
          return row.find("|" + std::to_string(c.id()) + "|") != std::string::npos;
        }))
      out.push_back(row);
  }
  return out;
}

// Window A: the 4 children of `parent`; window B: A's right column and the cells right of it.
// The transfer of A on 2 ranks is the single process's, and B's on A's right column is A's.
void expect_transfer_same_bits_on_two_ranks_and_a_shifted_window(const char* parent) {
  const Grid& grid = default_grid();
  const CellId p = CellId::Parse(parent);
  const std::vector<CellId> a = {p.child(0), p.child(1), p.child(2), p.child(3)};
  std::vector<CellId> b, common;
  for (const CellId c : a) {
    const CellId right = grid.edge_neighbours(c)[1];
    if (std::find(a.begin(), a.end(), right) != a.end()) continue;
    common.push_back(c);
    b.insert(b.end(), {c, right});
  }
  ASSERT_EQ(common.size(), 2u);
  std::vector<CellId> around = b;
  around.insert(around.end(), a.begin(), a.end());
  for (const CellId c : std::vector<CellId>(around)) {
    const auto ring = grid.vertex_neighbours(c);
    around.insert(around.end(), ring.begin(), ring.end());
  }
  std::sort(around.begin(), around.end());
  around.erase(std::unique(around.begin(), around.end()), around.end());

  const fs::path base = new_dir();
  write_painting(base / "painting.ppm");
  const json model = json::parse(R"({
    "format": "maquette.texture.model", "version": 1,
    "quantities": [{"name": "height", "range": [-500, 4000]}, {"name": "slope", "range": [0, 90]}],
    "root": {"colour": [150, 110, 90], "class": 0, "children": [
      {"class": 1, "colour": [90, 150, 60], "constraints": {"height": {"hat": [-500, 0, 300, 600]}}},
      {"class": 2, "colour": [30, 75, 40], "constraints": {"slope": {"hat": [0, 0, 1, 3]}}}]}})");
  std::ofstream(base / "pipeline.json")
      << synthesis_pipeline(cell_texts(around), {{{"op", "terrain.synthesize"},
                                                  {"outputs", {{"dem", "dem"}}},
                                                  {"params", {{"seed", 7}}}},
                                                 {{"op", "texture.procedural"},
                                                  {"inputs", {{"dem", "dem"}}},
                                                  {"outputs", {{"classes", "landcover"}}},
                                                  {"params", {{"model", model}}}}})
             .dump(2);
  const Result made = run(base.string(), 0);
  ASSERT_EQ(made.exit_code, 0) << made.err;

  const json transfer = {{"op", "synthesis.transfer"},
                         {"inputs", {{"landcover", "landcover"}}},
                         {"outputs", {{"rgb", "painted"}, {"source", "painted_source"}}},
                         {"params",
                          {{"painting", (base / "painting.ppm").string()},
                           {"classes", 2},
                           {"landcover_classes", {{"0", 0}, {"1", 1}, {"2", 1}}},
                           {"exemplar_scale", 1}}}};
  const auto transfer_run = [&](const std::vector<CellId>& cells, int ranks) {
    const fs::path dir = new_dir();
    for (const char* file : {"out.mqt", "out.mqt-wal"})
      if (fs::exists(base / file)) fs::copy_file(base / file, dir / file);
    std::ofstream(dir / "pipeline.json")
        << synthesis_pipeline(cell_texts(cells), json::array({transfer})).dump(2);
    const Result r = run(dir.string(), ranks);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return dir.string();
  };
  const std::string single = transfer_run(a, 0);
  const std::vector<std::string> expected = painted(single);
  ASSERT_EQ(expected.size(), 2 * a.size());  // rgb and source, every cell
  EXPECT_EQ(painted(transfer_run(a, 2)), expected);
  const std::vector<std::string> shifted = painted(transfer_run(b, 0), common);
  ASSERT_EQ(shifted.size(), 2 * common.size());
  EXPECT_EQ(shifted, painted(single, common));
}

TEST(MpiSynthesis, TransferGivesTheSameBitsOnTwoRanksAndOnAShiftedWindow) {
  expect_transfer_same_bits_on_two_ranks_and_a_shifted_window("Q21");
}

// N13's right column lies on N's right edge, where an equatorial face meets N turned: those cells
// synthesize their band in the neighbour's chart and cut it in (turned_edges.h); window B holds
// the neighbour's cells beside them.
TEST(MpiSynthesis, ACellBesideAPolarFacesTurnedEdgeToo) {
  const Grid& grid = default_grid();
  const CellId n13 = CellId::Parse("N13");
  // The right column joins a band (tiles of 256 at refine 0, as synthesis_pipeline lays them).
  for (const int child : {1, 3})
    ASSERT_EQ(synthesis::turned_edges(grid, FacePlane(grid), n13.child(child), 256, 0).size(), 1u)
        << child;
  const CellId right = grid.edge_neighbours(n13.child(1))[1];
  ASSERT_NE(right.face(), n13.face());
  ASSERT_NE(right.face(), CellId::Parse("O").face());  // not the edge laid unturned
  expect_transfer_same_bits_on_two_ranks_and_a_shifted_window("N13");
}

}  // namespace
}  // namespace maquette
