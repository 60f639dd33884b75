// Stores and outputs on hostile file systems, through the real program: a store on a read-only
// file system is read (info, export, a pipeline that only exports) and writing to it says the
// file system is read-only; exports onto a full file system fail and leave no file behind, and
// one that cannot replace its output leaves the old one's sidecar. The file systems are mounted by
// the test (root only; skipped otherwise).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "run_cli.h"
#include "synthetic_raster.h"

namespace maquette::test {
namespace {

using json = nlohmann::json;
namespace fs = std::filesystem;

bool sh(const std::string& cmd) { return std::system((cmd + " >/dev/null 2>&1").c_str()) == 0; }

// A mount made by the test, unmounted when the test ends.
class Mount {
 public:
  // `how`: "bind,ro SOURCE" or "tmpfs SIZE".
  static std::unique_ptr<Mount> make(const std::string& command, const std::string& point) {
    if (::geteuid() != 0) return nullptr;
    fs::create_directories(point);
    if (!sh(command)) return nullptr;
    return std::unique_ptr<Mount>(new Mount(point));
  }
  ~Mount() { sh("umount " + point_); }

 private:
  explicit Mount(std::string point) : point_(std::move(point)) {}
  std::string point_;
};

// A DEM of 400 x 400 pixels around 7.5 E 45.5 N, rough (so that its exports compress little):
// level 8 (152 m pixels).
std::string dem(const std::string& dir) {
  const std::string path = dir + "/dem.tif";
  write_raster(path, lonlat_raster(7, 46, 400, 0.0025, "Float32"), [](int, double lon, double lat) {
    const double n = std::sin(lon * 12345.678 + lat * 98765.4321) * 43758.5453;
    return 1000 + 200 * (lon - 7) + 100 * (n - std::floor(n));
  });
  return path;
}

TEST(FileSystems, StoreOnAReadOnlyFileSystemIsReadAndNotWritten) {
  const std::string dir = temp_dir(), src = dir + "/src", ro = dir + "/ro";
  fs::create_directories(src);
  const std::string tif = dem(dir);
  ASSERT_EQ(run_maquette("-q ingest " + src + "/s.mqt --layer d --as dem " + tif).exit_code, 0);
  const json pipeline = {
      {"store", "s.mqt"},
      {"region", {{"bbox", {7.2, 45.2, 7.6, 45.6}}}},
      {"level", 8},
      {"steps",
       {{{"op", "export"},
         {"params", {{"format", "png"}, {"layer", "d"}, {"out", dir + "/p.png"}}}}}}};
  std::ofstream(src + "/export.json") << pipeline.dump(1);
  const auto mount =
      Mount::make("mount --bind " + src + " " + ro + " && mount -o remount,bind,ro " + ro, ro);
  if (!mount) GTEST_SKIP() << "cannot mount a read-only bind mount here (root needed)";
  ASSERT_FALSE(sh("touch " + ro + "/x")) << "the mount is writable";

  const CliResult info = run_maquette("info " + ro + "/s.mqt");
  EXPECT_EQ(info.exit_code, 0) << info.err;
  EXPECT_NE(info.out.find("d: raster float32"), std::string::npos) << info.out;
  const CliResult png = run_maquette("export png " + ro + "/s.mqt --layer d " + dir + "/d.png");
  EXPECT_EQ(png.exit_code, 0) << png.err;
  EXPECT_TRUE(fs::exists(dir + "/d.png"));
  const CliResult tiff = run_maquette("export gtiff " + ro + "/s.mqt --layer d " + dir + "/d.tif");
  EXPECT_EQ(tiff.exit_code, 0) << tiff.err;
  const CliResult run = run_maquette("run " + ro + "/export.json");
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(fs::exists(dir + "/p.png"));

  for (const std::string& args : {"ingest " + ro + "/s.mqt --layer e --as dem " + tif,
                                  "ingest " + ro + "/new.mqt --layer e --as dem " + tif}) {
    const CliResult w = run_maquette(args);
    EXPECT_EQ(w.exit_code, 1) << args;
    EXPECT_NE(w.err.find("read-only file system"), std::string::npos) << w.err;
    EXPECT_EQ(w.err.find("free"), std::string::npos) << w.err;
  }
}

// 300 squares of 0.01 degrees around 7.5 E 45.5 N, as GeoJSON features.
std::string squares(const std::string& dir) {
  json features = json::array();
  for (int i = 0; i < 300; ++i) {
    const double w = 7.3 + 0.02 * (i % 20), s = 45.3 + 0.02 * (i / 20);
    const json ring = {{w, s}, {w + 0.01, s}, {w + 0.01, s + 0.01}, {w, s + 0.01}, {w, s}};
    features.push_back({{"type", "Feature"},
                        {"properties", {{"n", i}}},
                        {"geometry", {{"type", "Polygon"}, {"coordinates", {ring}}}}});
  }
  const std::string path = dir + "/squares.geojson";
  std::ofstream(path) << json{{"type", "FeatureCollection"}, {"features", features}}.dump();
  return path;
}

// Every writer onto a full file system: an error naming the file the user gave (not the
// temporary one written), and no file (nor a temporary one, nor a sidecar) left behind.
TEST(FileSystems, ExportsOntoAFullFileSystemFailAndLeaveNothing) {
  const std::string dir = temp_dir(), full = dir + "/full";
  const std::string store = dir + "/s.mqt";
  ASSERT_EQ(run_maquette("-q ingest " + store + " --layer d --as dem " + dem(dir)).exit_code, 0);
  ASSERT_EQ(
      run_maquette("-q ingest " + store + " --layer f --as features " + squares(dir)).exit_code, 0);
  const auto mount = Mount::make("mount -t tmpfs -o size=1m tmpfs " + full, full);
  if (!mount) GTEST_SKIP() << "cannot mount a tmpfs here (root needed)";
  // Filled but for 4 kB: every export below needs more.
  sh("dd if=/dev/zero of=" + full + "/filler bs=4k count=255");
  const std::string s = store + " --layer d ";
  std::string cell = run_maquette("cells from-point 7.5 45.5 --level 8").out;
  cell.erase(cell.find_last_not_of("\n") + 1);
  for (const auto& [args, out] : std::vector<std::pair<std::string, std::string>>{
           {"export gtiff " + s, "d.tif"},
           {"export gtiff " + s + "--crs EPSG:4326 ", "d.tif"},
           {"export png " + s, "d.png"},
           {"export geojson " + store + " --layer f ", "f.geojson"},
           {"export gpkg " + store + " --layer f ", "f.gpkg"},
           {"export tiles3d " + store + " --dem d ", "t"},
           {"export glb " + store + " --dem d --cells " + cell + " ", "d.glb"},
           {"export drc " + store + " --dem d --cells " + cell + " ", "drc"}}) {
    const CliResult r = run_maquette(args + full + "/" + out);
    EXPECT_EQ(r.exit_code, 1) << args << "\n" << r.err;
    EXPECT_NE(r.err.find(full + "/" + out), std::string::npos) << args << "\n" << r.err;
    EXPECT_EQ(r.err.find(".part."), std::string::npos) << args << "\n" << r.err;
    for (const auto& e : fs::recursive_directory_iterator(full))
      EXPECT_TRUE(e.is_directory() || e.path().filename() == "filler") << args << ": " << e.path();
  }
}

// A georeferenced PNG and its sidecars (.aux.xml, .pgw) appear together or not at all, whatever
// room the file system has left: from none to more than all need.
TEST(FileSystems, PngAndItsSidecarsAppearTogetherOrNotAtAll) {
  const std::string dir = temp_dir(), full = dir + "/full";
  const std::string store = dir + "/s.mqt";
  ASSERT_EQ(run_maquette("-q ingest " + store + " --layer d --as dem " + dem(dir)).exit_code, 0);
  const auto mount = Mount::make("mount -t tmpfs -o size=1m tmpfs " + full, full);
  if (!mount) GTEST_SKIP() << "cannot mount a tmpfs here (root needed)";
  const std::string png = full + "/d.png";
  bool some_failed = false, some_written = false;
  for (int free_pages = 0; free_pages <= 8; ++free_pages) {
    sh("dd if=/dev/zero of=" + full + "/filler bs=4k count=" + std::to_string(256 - free_pages));
    const CliResult r =
        run_maquette("-q export png " + store + " --layer d " + png + " --max-size 96");
    const bool written = r.exit_code == 0;
    (written ? some_written : some_failed) = true;
    for (const std::string& file : {png, png + ".aux.xml", full + "/d.pgw"})
      EXPECT_EQ(fs::exists(file), written) << free_pages << " pages free: " << file << r.err;
    for (const auto& e : fs::directory_iterator(full))
      EXPECT_EQ(e.path().string().find(".part."), std::string::npos) << e.path();
    if (written) {
      EXPECT_NE(shell_output("gdalinfo " + png).find("Pixel Size"), std::string::npos);
      EXPECT_GT(fs::file_size(full + "/d.pgw"), 0U);
    }
    sh("rm -f " + full + "/d.* " + full + "/filler");
  }
  EXPECT_TRUE(some_failed && some_written) << "the room tried never split the files";
}

// An rHEALPix GeoTIFF that cannot replace what is at OUT (here a directory) leaves OUT's sidecar
// as it was: the .aux.xml holds the CRS of the GeoTIFF it describes.
TEST(FileSystems, AnOutputThatCannotBeReplacedKeepsItsSidecar) {
  const std::string dir = temp_dir(), store = dir + "/s.mqt", out = dir + "/d.tif";
  ASSERT_EQ(run_maquette("-q ingest " + store + " --layer d --as dem " + dem(dir)).exit_code, 0);
  fs::create_directories(out + "/inside");
  std::ofstream(out + ".aux.xml") << "<PAMDataset/>\n";
  const CliResult r = run_maquette("-q export gtiff " + store + " --layer d " + out);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find(out), std::string::npos) << r.err;
  ASSERT_TRUE(fs::exists(out + ".aux.xml")) << r.err;
  EXPECT_EQ(fs::file_size(out + ".aux.xml"), 14U);
  for (const auto& e : fs::directory_iterator(dir))
    EXPECT_EQ(e.path().string().find(".part."), std::string::npos) << e.path();
}

}  // namespace
}  // namespace maquette::test
