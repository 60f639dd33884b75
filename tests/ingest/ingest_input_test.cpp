// Bad input through the real program (clear message naming the file or option, non-zero exit,
// store bytes untouched), mosaics, and a killed ingest resumed to the same bits.
#include <gdal_priv.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sqlite3.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <future>
#include <thread>

#include "ingest_fixture.h"
#include "run_cli.h"
#include "synthetic_raster.h"

namespace maquette::test {
namespace {

RasterSpec small_lonlat(double west, int bands = 1) {
  RasterSpec s;
  s.width = s.height = 100;
  s.bands = bands;
  s.geotransform = {west, 0.01, 0, 46, 0, -0.01};
  s.crs = "EPSG:4326";
  s.type = "Int16";
  s.nodata = -32768;
  return s;
}

double ramp(int band, double lon, double lat) { return 100 * band + 1000 * (lon + lat); }

class IngestInput : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = temp_dir();
    good = dir + "/good.tif";
    write_raster(good, small_lonlat(7), ramp);
    store = dir + "/s.mqt";
    const CliResult r = run_maquette("-q ingest " + store + " --layer a --as dem " + good);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    before = file_fingerprint(store);
  }
  // Runs a bad ingest into the store: it must fail naming `expected`, leaving the store as it was.
  void expect_refused(const std::string& args, const std::string& expected) {
    const CliResult r = run_maquette("ingest " + store + " --layer b " + args);
    EXPECT_EQ(r.exit_code, 1) << r.err;
    EXPECT_NE(r.err.find("maquette: error: "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(expected), std::string::npos) << r.err;
    EXPECT_EQ(file_fingerprint(store), before) << args;
  }
  std::string dir, good, store, before;
};

TEST_F(IngestInput, TruncatedGeoTiff) {
  const std::string bad = dir + "/truncated.tif";
  std::filesystem::copy_file(good, bad);
  std::filesystem::resize_file(bad, std::filesystem::file_size(good) / 3);
  expect_refused("--as dem " + bad, bad);
}

// A failed ingest into a layer that wrote none of its tiles leaves the layer readable, with its
// tiles and footprint as they were (it was left incomplete: unreadable until the sources were
// ingested again, an audit's find).
TEST_F(IngestInput, AFailedIngestThatWroteNothingLeavesTheLayerReadable) {
  // Tiled, its header whole and its last tiles cut: the ingest fails reading them, after the
  // store is ready.
  const std::string tiled = dir + "/tiled.tif", bad = dir + "/cut.tif";
  shell_output("gdal_translate -q -co TILED=YES -co BLOCKXSIZE=32 -co BLOCKYSIZE=32 " + good + " " +
               tiled);
  std::filesystem::copy_file(tiled, bad);
  std::filesystem::resize_file(bad, std::filesystem::file_size(tiled) * 2 / 3);
  const auto layer_before = Store::open(store, Store::Mode::ReadOnly)->require_layer("a");
  const CliResult r = run_maquette("ingest " + store + " --layer a --as dem " + bad);
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find(bad + ": read error"), std::string::npos) << r.err;
  const auto after = Store::open(store, Store::Mode::ReadOnly);
  EXPECT_EQ(after->require_layer("a").provenance, layer_before.provenance);
  EXPECT_EQ(run_maquette("-q export png " + store + " " + dir + "/a.png --layer a").exit_code, 0);
}

TEST_F(IngestInput, CorruptFile) {
  const std::string bad = dir + "/corrupt.tif";
  std::ofstream(bad) << "II*\0 this is not a tiff at all";
  expect_refused("--as dem " + bad, bad + ": cannot read the raster");
}

// A source GDAL reads but not as a GeoTIFF: the program opens sources with the GTiff driver alone
// and registers every driver only when that fails. The same pixels in ENVI give the same tiles.
TEST_F(IngestInput, NonGeoTiffSourceGivesTheTilesOfTheGeoTiff) {
  const std::string envi = dir + "/good.envi";
  {
    GDALAllRegister();
    const GDALDatasetUniquePtr tif(GDALDataset::Open(good.c_str(), GDAL_OF_RASTER));
    ASSERT_TRUE(tif);
    const GDALDatasetUniquePtr copy(GetGDALDriverManager()->GetDriverByName("ENVI")->CreateCopy(
        envi.c_str(), tif.get(), FALSE, nullptr, nullptr, nullptr));
    ASSERT_TRUE(copy);
  }
  const std::string other = dir + "/envi.mqt";
  const CliResult r = run_maquette("-q ingest " + other + " --layer a --as dem " + envi);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto a = Store::open(store, Store::Mode::ReadOnly),
             b = Store::open(other, Store::Mode::ReadOnly);
  const std::vector<CellId> cells = a->tile_cells("a");
  ASSERT_FALSE(cells.empty());
  ASSERT_EQ(cells, b->tile_cells("a"));
  for (CellId c : cells) EXPECT_EQ(a->get_tile("a", c)->bytes, b->get_tile("a", c)->bytes);
}

TEST_F(IngestInput, RasterWithoutCrsUnlessSrcCrs) {
  const std::string bad = dir + "/nocrs.tif";
  RasterSpec spec = small_lonlat(7);
  spec.crs = "";
  write_raster(bad, spec, ramp);
  expect_refused("--as dem " + bad, bad + ": the raster has no CRS; give one with --src-crs");
  const CliResult r =
      run_maquette("-q ingest " + dir + "/other.mqt --layer b --as dem --src-crs EPSG:4326 " + bad);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  // A raster with a CRS of its own: --src-crs is not its (it read degrees as UTM metres, exit 0,
  // an audit's find), and the same CRS is no error.
  expect_refused("--as dem --src-crs EPSG:32612 " + good,
                 good + ": the raster has its own CRS (WGS 84), not --src-crs EPSG:32612");
  EXPECT_EQ(
      run_maquette("-q ingest " + dir + "/same.mqt --layer b --as dem --src-crs EPSG:4326 " + good)
          .exit_code,
      0);
}

TEST_F(IngestInput, RegionNotOverlappingTheSource) {
  expect_refused("--as dem --bbox 100 10 101 11 " + good, "--bbox does not overlap the sources");
}

TEST_F(IngestInput, GeoJsonRegionNotOverlappingTheSource) {
  const std::string region = dir + "/far.geojson";
  std::ofstream(region) << R"({"type": "Polygon", "coordinates": [[[100, 10], [101, 10], )"
                        << R"([101, 11], [100, 10]]]})";
  expect_refused("--as dem --region " + region + " " + good,
                 "--region " + region + " does not overlap the sources (" + good + ": lon 7..8");
}

TEST_F(IngestInput, BadClassTable) {
  expect_refused(R"(--as landcover --classes '{"1": {"color": "blue"}}' )" + good,
                 R"(--classes: class 1.color: expected "#rrggbb", got "blue")");
  expect_refused(R"(--as landcover --classes '{"water": {}}' )" + good,
                 "--classes: class key 'water' is not an integer value");
}

TEST_F(IngestInput, AllNodata) {
  const std::string bad = dir + "/void.tif";
  write_raster(bad, small_lonlat(7), [](int, double, double) { return -32768; });
  expect_refused("--as dem " + bad, bad + ": every sample is nodata");
}

// A level so coarse that no pixel centre falls on the source writes no tile: an error leaving no
// layer (it exited 0 with an empty layer).
TEST_F(IngestInput, AnIngestWritingNoTileIsAnErrorAndLeavesNoLayer) {
  const CliResult r =
      run_maquette("ingest " + store + " --layer b --as dem --level 0 --tile-size 2 " + good);
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("ingest b: no tile written: no pixel of the 1 cells at level 0"),
            std::string::npos)
      << r.err;
  const auto after = Store::open(store, Store::Mode::ReadOnly);
  EXPECT_FALSE(after->layer("b"));
  EXPECT_FALSE(after->incomplete("a"));
}

// An ingest waiting for another process's write says so after a while (it waited silently, for
// up to a minute and more), and goes on once the lock is released.
TEST_F(IngestInput, AnIngestWaitingForAnotherWriterSaysSo) {
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(store.c_str(), &db), SQLITE_OK);
  ASSERT_EQ(sqlite3_exec(db, "BEGIN IMMEDIATE", nullptr, nullptr, nullptr), SQLITE_OK);
  auto ingest = std::async(std::launch::async, [&] {
    return run_maquette("ingest " + store + " --layer b --as dem " + good);
  });
  std::this_thread::sleep_for(std::chrono::seconds(4));
  EXPECT_EQ(sqlite3_exec(db, "COMMIT", nullptr, nullptr, nullptr), SQLITE_OK);
  sqlite3_close(db);
  const CliResult r = ingest.get();
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find(store + ": another connection holds its lock; waiting for it"),
            std::string::npos)
      << r.err;
}

TEST_F(IngestInput, LevelTooFineIsRefusedWithTheEstimate) {
  expect_refused("--as dem --level 19 " + good, "tiles of 256x256x1 float32 at level 19");
}

// A new store is created while the ingest is planned: a refused ingest must not leave it behind.
TEST_F(IngestInput, RefusedIngestLeavesNoNewStore) {
  const std::string fresh = dir + "/fresh.mqt";
  for (const std::string args : {"--bbox 100 10 101 11 ", "--level 19 "}) {
    const CliResult r = run_maquette("ingest " + fresh + " --layer a --as dem " + args + good);
    EXPECT_EQ(r.exit_code, 1) << r.err;
    for (const char* suffix : {"", "-wal", "-shm"})
      EXPECT_FALSE(std::filesystem::exists(fresh + suffix)) << args << suffix;
  }
  // A name the store refuses, after the store is made (it was left behind).
  const CliResult blank = run_maquette("ingest " + fresh + " --layer ' a' --as dem " + good);
  EXPECT_EQ(blank.exit_code, 1) << blank.err;
  EXPECT_NE(blank.err.find("layer name ' a': no blank at either end"), std::string::npos)
      << blank.err;
  for (const char* suffix : {"", "-wal", "-shm"})
    EXPECT_FALSE(std::filesystem::exists(fresh + suffix)) << suffix;
  const CliResult ok = run_maquette("-q ingest " + fresh + " --layer a --as dem " + good);
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_TRUE(std::filesystem::exists(fresh));
}

TEST_F(IngestInput, MismatchedBandCounts) {
  const std::string three = dir + "/three.tif";
  write_raster(three, small_lonlat(8, 3), ramp);
  expect_refused("--as raster " + good + " " + three,
                 "band counts differ: " + good + " has 1 band(s) (1), " + three + " has 3");
}

TEST_F(IngestInput, BadOptionValues) {
  expect_refused("--as dem --resampling lanczos " + good, "--resampling 'lanczos'");
  expect_refused("--as heights " + good, "--as 'heights'");
  expect_refused("--as dem --classes '{\"1\": {\"name\": \"forest\"}}' " + good,
                 "--classes is for class layers (--as landcover), not --as dem");
  expect_refused("--as dem --bands 2 " + good, "--bands: " + good + " has no band 2");
  // Before the store is touched (tile size 1 failed at the overviews, the layer left incomplete).
  expect_refused("--as dem --tile-size 1 " + good,
                 "--tile-size: tile size 1 is not a power of two in [2, 4096]");
  expect_refused("--as dem --tile-size 100 " + good, "--tile-size: tile size 100 is not a power");
}

TEST_F(IngestInput, MosaicLaterSourcesFillOnlyNodata) {
  // Two overlapping rasters: the first has a hole (nodata) where the second must show through,
  // and elsewhere the first wins.
  const std::string a = dir + "/a.tif", b = dir + "/b.tif";
  write_raster(a, small_lonlat(7),
               [](int, double lon, double) { return lon > 7.4 && lon < 7.6 ? -32768 : 1; });
  write_raster(b, small_lonlat(7.5), [](int, double, double) { return 2; });
  RasterIngestOptions o;
  o.layer = "m";
  o.as = "raster";
  o.resampling = Resampling::Nearest;
  const auto s = ingest(dir, "mosaic", {a, b}, o);
  int ones = 0, twos = 0;
  for_each_sample(*s, "m", [&](CellId, LonLat p, const float* v) {
    if (std::isnan(v[0]) || p.lat < 45.01 || p.lat > 45.99) return;
    if (p.lon > 7.01 && p.lon < 7.39) {
      EXPECT_EQ(v[0], 1.0f);
    }
    if (p.lon > 7.41 && p.lon < 7.59) {
      EXPECT_EQ(v[0], 2.0f) << p.lon;
    }
    if (p.lon > 7.61 && p.lon < 7.99) {
      EXPECT_EQ(v[0], 1.0f);
    }
    if (p.lon > 8.01 && p.lon < 8.49) {
      EXPECT_EQ(v[0], 2.0f);
    }
    (v[0] == 1.0f ? ones : twos)++;
  });
  EXPECT_GT(ones, 1000);
  EXPECT_GT(twos, 1000);
}

// Two sources side by side, their edge inside tiles: ingested one after the other into the same
// layer, the tiles they share hold both parts, as when ingested together (the second ingest's
// tiles replaced the first's: a strip of nodata along the edge, an audit's find).
TEST_F(IngestInput, ALaterIngestIntoTheLayerKeepsTheEarlierSourcesSamples) {
  const std::string west = dir + "/west.tif", east = dir + "/east.tif";
  write_raster(west, small_lonlat(7.0), ramp);
  write_raster(east, small_lonlat(8.0), ramp);
  RasterIngestOptions o;
  o.layer = "m";
  o.as = "dem";
  o.level = 9;
  o.tile_size = 64;
  o.resampling = Resampling::Nearest;
  const auto together = ingest(dir, "together", {west, east}, o);
  ingest(dir, "apart", {west}, o);
  const auto apart = ingest(dir, "apart", {east}, o);
  const std::vector<CellId> cells = together->tile_cells("m");
  ASSERT_EQ(apart->tile_cells("m"), cells);
  for (const CellId c : cells)
    EXPECT_EQ(apart->get_tile("m", c)->bytes, together->get_tile("m", c)->bytes) << c.ToText();
  EXPECT_GT(cells.size(), 4u);
  int with_data = 0;
  for_each_sample(*apart, "m", [&](CellId, LonLat p, const float* v) {
    if (p.lon > 7.005 && p.lon < 8.995 && p.lat > 45.005 && p.lat < 45.995) {
      EXPECT_FALSE(std::isnan(v[0])) << p.lon << ", " << p.lat;
      ++with_data;
    }
  });
  EXPECT_GT(with_data, 1000);
}

// --bbox takes its four values and --bands its one list, not the sources after them too
// ("--bbox: At Most 4 required but received 5").
TEST_F(IngestInput, BboxAndBandsTakeOnlyTheirValues) {
  const std::string east = dir + "/east.tif";
  write_raster(east, small_lonlat(8.0), ramp);
  CliResult r = run_maquette("-q ingest " + dir +
                             "/b.mqt --layer m --as dem --level 6 --bbox 7 45 9 "
                             "46 " +
                             good + " " + east);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  r = run_maquette("-q ingest " + dir + "/b.mqt --layer n --as dem --level 6 --bands 1 " + good +
                   " " + east);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  const auto store = Store::open(dir + "/b.mqt", Store::Mode::ReadOnly);
  EXPECT_EQ(store->tile_cells("m"), store->tile_cells("n"));
}

TEST_F(IngestInput, ClassTableFromTheCommandLine) {
  const CliResult r = run_maquette(
      "-q ingest " + store +
      R"( --layer lc --as landcover --classes '{"11": {"name": "Open water", "color": "#466b9f"}}' )" +
      good);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const LayerInfo lc = Store::open(store, Store::Mode::ReadOnly)->require_layer("lc");
  EXPECT_EQ(lc.provenance["classes"]["11"]["name"], "Open water");
  EXPECT_EQ(lc.dtype, DType::I16);
  EXPECT_EQ(lc.nodata, -32768.0);
}

TEST(IngestResume, KilledIngestResumesToTheSameTilesAsAnyThreadCount) {
  const std::string dir = temp_dir(), tif = dir + "/big.tif";
  RasterSpec spec = small_lonlat(7);
  spec.width = spec.height = 2000;
  spec.geotransform = {7, 0.0005, 0, 46, 0, -0.0005};
  write_raster(tif, spec, ramp);
  const std::string args = " --layer d --as dem --threads 1 " + tif;
  const std::string clean = dir + "/clean.mqt", killed = dir + "/killed.mqt";
  ASSERT_EQ(run_maquette("-q ingest " + clean + args).exit_code, 0);

  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    const std::string bin = std::string(MAQUETTE_BIN_DIR) + "/maquette";
    execl(bin.c_str(), bin.c_str(), "-q", "ingest", killed.c_str(), "--layer", "d", "--as", "dem",
          "--threads", "1", tif.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  // Kill it once a few tiles are committed.
  for (int i = 0; i < 2000; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    if (!std::filesystem::exists(killed)) continue;
    try {
      if (Store::open(killed, Store::Mode::ReadOnly)->tile_cells("d").size() >= 3) break;
    } catch (const std::exception&) {
    }
  }
  kill(pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
  const int64_t partial =
      int64_t(Store::open(killed, Store::Mode::ReadOnly)->tile_cells("d").size());
  const CliResult r = run_maquette("ingest " + killed + args + " --resume");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  if (WIFSIGNALED(status)) {
    EXPECT_NE(r.err.find("resum"), std::string::npos) << r.err;
  }
  const std::string two = dir + "/two_threads.mqt";
  ASSERT_EQ(run_maquette("-q ingest " + two + " --layer d --as dem --threads 2 " + tif).exit_code,
            0);
  const auto t = Store::open(two, Store::Mode::ReadOnly);
  const auto a = Store::open(clean, Store::Mode::ReadOnly),
             b = Store::open(killed, Store::Mode::ReadOnly);
  const std::vector<CellId> cells = a->tile_cells("d");
  ASSERT_EQ(cells, b->tile_cells("d"));
  EXPECT_LE(partial, int64_t(cells.size()));
  ASSERT_EQ(cells, t->tile_cells("d"));
  for (CellId c : cells) {
    EXPECT_EQ(a->get_tile("d", c)->bytes, b->get_tile("d", c)->bytes);
    EXPECT_EQ(a->get_tile("d", c)->bytes, t->get_tile("d", c)->bytes);  // any thread count
  }
  for (CellId c : cells)
    EXPECT_EQ(a->get_overview("d", c.parent())->bytes, b->get_overview("d", c.parent())->bytes);
}

}  // namespace
}  // namespace maquette::test
