// Peak memory of `maquette export tiles3d` is bounded by the tiles in flight (one per worker
// thread), not by the number of tiles: the real program, pinned to the same CPUs, exports 4 and
// 64 tiles of 256 x 256 samples; its peak resident size (wait4's ru_maxrss) may grow with the
// tile count by much less than the meshes it wrote (the GLB bytes of the 64 tiles), which an
// export holding every mesh of a level at once would add (plus the store pages it maps).
#include <gtest/gtest.h>
#include <sched.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>

#include "run_cli.h"
#include "test_tiles.h"

namespace maquette::test {
namespace {

namespace fs = std::filesystem;

constexpr int kSize = 256;
constexpr int kLevel = 9;

// A store whose `dem` holds the side x side block of level-9 cells at the middle of face P
// (heights: a smooth pattern of the sample's position, 0..2000 m).
std::string block_store(int side) {
  const std::string path = temp_dir() + "/block.maquette";
  auto store = Store::open(path, Store::Mode::Create);
  store->create_layer(layer_info("dem", DType::F32, 1, kSize, kLevel));
  Store::Batch batch(*store);
  const uint32_t first = (1u << (kLevel - 1)) - uint32_t(side / 2);
  for (uint32_t r = 0; r < uint32_t(side); ++r)
    for (uint32_t c = 0; c < uint32_t(side); ++c) {
      std::vector<float> v(size_t(kSize) * kSize);
      for (size_t i = 0; i < v.size(); ++i)
        v[i] = float(1000 + 1000 * std::sin(double(i % kSize + c * kSize) / 40) *
                                std::cos(double(i / kSize + r * kSize) / 55));
      RawTile t{DType::F32, kSize, 1, std::vector<std::byte>(v.size() * sizeof(float))};
      std::memcpy(t.bytes.data(), v.data(), t.bytes.size());
      batch.put_tile("dem", CellId::FromFaceColRow(2, kLevel, first + c, first + r), t);
    }
  batch.commit();
  return path;
}

// The first `n` CPUs this process may run on.
cpu_set_t first_cpus(int n) {
  cpu_set_t all, some;
  CPU_ZERO(&some);
  if (sched_getaffinity(0, sizeof all, &all) != 0) throw std::runtime_error("sched_getaffinity");
  for (int cpu = 0; cpu < CPU_SETSIZE && n > 0; ++cpu)
    if (CPU_ISSET(cpu, &all)) {
      CPU_SET(cpu, &some);
      --n;
    }
  return some;
}

// Runs `maquette ARGS...` on `cpus` (so its thread pool has that many workers) and returns its
// peak resident size in bytes; -1 when it fails.
int64_t peak_rss(const std::vector<std::string>& args, const cpu_set_t& cpus) {
  const std::string program = std::string(MAQUETTE_BIN_DIR) + "/maquette";
  std::vector<char*> argv{const_cast<char*>(program.c_str())};
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  const pid_t pid = fork();
  if (pid == 0) {  // only async-signal-safe calls until exec
    sched_setaffinity(0, sizeof cpus, &cpus);
    execv(program.c_str(), argv.data());
    _exit(127);
  }
  int status = 0;
  rusage usage{};
  if (pid < 0 || wait4(pid, &status, 0, &usage) != pid || !WIFEXITED(status) ||
      WEXITSTATUS(status) != 0)
    return -1;
  return int64_t(usage.ru_maxrss) * 1024;
}

int64_t glb_bytes(const fs::path& dir) {
  int64_t total = 0;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.path().extension() == ".glb") total += int64_t(e.file_size());
  return total;
}

struct ExportRun {
  int64_t peak = -1;  // bytes resident at most
  int64_t glb = 0;    // bytes of the GLB files written
  int64_t store = 0;  // bytes of the store file
};

// `maquette export tiles3d` (no Draco, the faster path; both share the meshing) of a side x side
// block on two CPUs (one if the machine has one).
ExportRun export_block(int side) {
  const std::string store = block_store(side), out = temp_dir() + "/out";
  ExportRun run;
  run.peak = peak_rss(
      {"-q", "export", "tiles3d", store, out, "--dem", "dem", "--levels", "9..9", "--no-draco"},
      first_cpus(2));
  run.glb = glb_bytes(out);
  run.store = int64_t(fs::file_size(store));
  return run;
}

TEST(Tiles3d, PeakMemoryDoesNotGrowWithTileCount) {
  if (const std::string why = resident_memory_unmeasurable(); !why.empty()) GTEST_SKIP() << why;
  const ExportRun small = export_block(2), large = export_block(8);
  ASSERT_GT(small.peak, 0);
  ASSERT_GT(large.peak, 0);
  // 16 times the tiles: the meshes of 64 tiles (~3.7 MB each) would add ~240 MB.
  EXPECT_NEAR(double(large.glb) / double(small.glb), 16, 0.5);
  RecordProperty("peak_rss_4_tiles_mib", int(small.peak >> 20));
  RecordProperty("peak_rss_64_tiles_mib", int(large.peak >> 20));
  // The store is read through SQLite's memory map, whose pages count as resident: the peak may
  // also grow by the store's size.
  EXPECT_LT(large.peak - small.peak, large.store - small.store + large.glb / 8)
      << "peak RSS " << (small.peak >> 20) << " MiB for 4 tiles, " << (large.peak >> 20)
      << " MiB for 64 tiles (" << (large.glb >> 20) << " MiB of meshes written, stores "
      << (small.store >> 20) << " and " << (large.store >> 20) << " MiB)";
}

}  // namespace
}  // namespace maquette::test
