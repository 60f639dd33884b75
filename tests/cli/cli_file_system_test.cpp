// Stores and outputs on hostile file systems, through the real program: a store on a read-only
// file system is read (info, export, a pipeline that only exports) and writing to it says the
// file system is read-only; exports onto a full file system fail and leave no file behind. The
// file systems are mounted by the test (root only; skipped otherwise).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

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

// Every writer onto a full file system: an error naming the file, and no file (nor a temporary
// one, nor an .aux.xml) left behind.
TEST(FileSystems, ExportsOntoAFullFileSystemFailAndLeaveNothing) {
  const std::string dir = temp_dir(), full = dir + "/full";
  const std::string store = dir + "/s.mqt";
  ASSERT_EQ(run_maquette("-q ingest " + store + " --layer d --as dem " + dem(dir)).exit_code, 0);
  const auto mount = Mount::make("mount -t tmpfs -o size=1m tmpfs " + full, full);
  if (!mount) GTEST_SKIP() << "cannot mount a tmpfs here (root needed)";
  // Filled but for 4 kB: every export below needs more.
  sh("dd if=/dev/zero of=" + full + "/filler bs=4k count=255");
  const std::string s = store + " --layer d ";
  std::string cell = run_maquette("cells from-point 7.5 45.5 --level 8").out;
  cell.erase(cell.find_last_not_of("\n") + 1);
  for (const std::string& args :
       {"export gtiff " + s + full + "/d.tif",
        "export gtiff " + s + full + "/d.tif --crs EPSG:4326", "export png " + s + full + "/d.png",
        "export tiles3d " + store + " " + full + "/t --dem d",
        "export glb " + store + " " + full + "/d.glb --dem d --cells " + cell,
        "export drc " + store + " " + full + "/drc --dem d --cells " + cell}) {
    const CliResult r = run_maquette(args);
    EXPECT_EQ(r.exit_code, 1) << args << "\n" << r.err;
    EXPECT_NE(r.err.find(full), std::string::npos) << args << "\n" << r.err;
    for (const auto& e : fs::recursive_directory_iterator(full))
      EXPECT_TRUE(e.is_directory() || e.path().filename() == "filler") << args << ": " << e.path();
  }
}

}  // namespace
}  // namespace maquette::test
