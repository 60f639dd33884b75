// Crash safety: a child process writing small batches is SIGKILLed at random moments; every
// time, the store must open, pass integrity_check, and hold every batch the child reported
// committed, completely, with tiles (or content blobs) equal to what was written. Both for a
// store written through the WAL and for new stores filled in bulk (Mode::CreateBulk: a rollback
// journal, which a read-only open must roll back first). Its own executable, so that fork() happens
// in a process without other threads.
#include <fcntl.h>
#include <signal.h>
#include <sqlite3.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <map>
#include <random>
#include <set>
#include <thread>

#include "content/instances_codec.h"
#include "store/store.h"
#include "store_test_util.h"

namespace maquette {
namespace {

constexpr int kTilesPerBatch = 4;
constexpr int kTileSize = 64;
constexpr int kLevel = 10;

CellId cell_of(int64_t k) {
  return CellId::FromFaceColRow(int(k % 6), kLevel, uint32_t((k / 6) % 1024),
                                uint32_t((k / 6) / 1024));
}

constexpr int64_t kOpened = -1;  // reported once the store is open, before any batch

// What the writer puts: raster tiles in layer "dem", or instances content in layer "trees".
enum class Writes { Tiles, Content };

// The content blob of cell k: 1 to 40 instances whose values depend on k.
std::string content_blob(int64_t k) {
  InstancesContent c;
  c.origin = {double(k % 360) - 180, 0.5, 100};
  c.prototypes = {"builtin:shrub"};
  for (int64_t i = 0; i <= k % 40; ++i) {
    c.prototype.push_back(0);
    c.position.insert(c.position.end(), {float(i), float(k % 1000), 0.25f});
    c.rotation.insert(c.rotation.end(), {0, 0, 0, 1});
    c.scale.insert(c.scale.end(), {1, 1, float(1 + i % 3)});
    c.colour.push_back(uint32_t(k * 2654435761u));
  }
  return wrap_instances(c);
}

// Writes batches first_batch, first_batch + 1, ... forever, reporting each after its commit.
[[noreturn]] void write_until_killed(const std::string& path, Store::Mode mode, int64_t first_batch,
                                     int report_fd, Writes writes) {
  try {
    auto store = Store::open(path, mode);
    LayerInfo l;
    l.name = writes == Writes::Tiles ? "dem" : "trees";
    l.kind = writes == Writes::Tiles ? LayerKind::Raster : LayerKind::Instances;
    l.tile_size = kTileSize;
    l.level = kLevel;
    store->create_layer(l);
    if (::write(report_fd, &kOpened, sizeof kOpened) != sizeof kOpened) ::_exit(3);
    for (int64_t b = first_batch;; ++b) {
      Store::Batch batch(*store);
      for (int i = 0; i < kTilesPerBatch; ++i) {
        const int64_t k = b * kTilesPerBatch + i;
        if (writes == Writes::Tiles)
          batch.put_tile("dem", cell_of(k), test::smooth_tile(kTileSize, float(k)));
        else
          batch.put_content("trees", cell_of(k), content_blob(k));
      }
      batch.commit();
      if (::write(report_fd, &b, sizeof b) != sizeof b) ::_exit(3);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "writer: %s\n", e.what());
    ::_exit(2);
  }
}

// Six rounds of writing and killing: CreateBulk fills a new store each round, Create goes on
// writing the same one.
void kill_writers_and_check(Store::Mode mode, Writes writes = Writes::Tiles) {
  test::TempDir dir;
  const bool bulk = mode == Store::Mode::CreateBulk;
  std::mt19937 rng(20240607);
  std::set<int64_t> reported;  // batches committed to the store of this round
  for (int round = 0; round < 6; ++round) {
    const std::string path = dir.file("crash" + std::to_string(bulk ? round : 0) + ".mqs");
    if (bulk) reported.clear();
    int fds[2];
    ASSERT_EQ(::pipe(fds), 0);
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      ::close(fds[0]);
      write_until_killed(path, mode, int64_t(round) * 100000, fds[1], writes);
    }
    ::close(fds[1]);
    // The kill lands anywhere after the open (which creates the store in the bulk rounds).
    int64_t opened = 0;
    ASSERT_EQ(::read(fds[0], &opened, sizeof opened), ssize_t(sizeof opened)) << "writer failed";
    ASSERT_EQ(opened, kOpened);
    // Round r waits for r commits before its random delay, so that the rounds kill stores holding
    // batches however slow the writer runs (a sanitizer's, on a loaded machine): 15 at least in
    // all; round 0 may kill before the first commit.
    for (int i = 0; i < round; ++i) {
      int64_t b = 0;
      ASSERT_EQ(::read(fds[0], &b, sizeof b), ssize_t(sizeof b)) << "writer failed";
      reported.insert(b);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(30 + rng() % 150));
    ASSERT_EQ(::kill(child, SIGKILL), 0);
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFSIGNALED(status)) << "child exited with " << WEXITSTATUS(status);
    int64_t b;
    while (::read(fds[0], &b, sizeof b) == sizeof b) {
      reported.insert(b);
    }
    ::close(fds[0]);

    auto store = Store::open(path, Store::Mode::ReadOnly);
    ASSERT_TRUE(store->integrity_ok()) << "round " << round;
    std::map<int64_t, int> tiles_per_batch;
    const auto cells =
        writes == Writes::Tiles ? store->tile_cells("dem") : store->content_cells("trees");
    std::set<CellId> present(cells.begin(), cells.end());
    for (int64_t batch : reported)
      for (int i = 0; i < kTilesPerBatch; ++i)
        ASSERT_TRUE(present.count(cell_of(batch * kTilesPerBatch + i)))
            << "committed batch " << batch << " lost in round " << round;
    const auto key_of = [](CellId c) {
      const int64_t k = int64_t(c.face()) + 6 * (int64_t(c.row()) * 1024 + c.col());
      EXPECT_EQ(cell_of(k), c);
      return k;
    };
    // Every stored tile or blob is what was written; batches are all or nothing.
    if (writes == Writes::Tiles)
      store->scan("dem", CellId(0), CellId(uint64_t(INT64_MAX)), [&](CellId c, const RawTile& t) {
        const int64_t k = key_of(c);
        EXPECT_EQ(t.bytes, test::smooth_tile(kTileSize, float(k)).bytes) << c.ToText();
        ++tiles_per_batch[k / kTilesPerBatch];
      });
    else
      for (CellId c : cells) {
        const int64_t k = key_of(c);
        EXPECT_EQ(store->get_content("trees", c), content_blob(k)) << c.ToText();
        ++tiles_per_batch[k / kTilesPerBatch];
      }
    for (const auto& [batch, count] : tiles_per_batch)
      EXPECT_EQ(count, kTilesPerBatch) << "batch " << batch << " is partial";
    testing::Test::RecordProperty("round" + std::to_string(round) + "_batches",
                                  int(tiles_per_batch.size()));
  }
}

// A writer killed in the middle of a commit to a store being filled in bulk leaves a hot
// rollback journal, made here for sure: a second connection spills a transaction that blanks
// every tile into the file, then the process kills itself. Read-only connections cannot roll it
// back themselves; both a store opened read-only before the kill and one opened after must
// still give the tiles as they were committed.
TEST(StoreCrash, ReadOnlyStoresRollBackAKilledBulkCommit) {
  test::TempDir dir;
  const std::string path = dir.file("hot.mqs");
  constexpr int kTiles = 40;
  int filled[2], opened[2];  // child -> parent: tiles committed; parent -> child: store opened
  ASSERT_EQ(::pipe(filled), 0);
  ASSERT_EQ(::pipe(opened), 0);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    auto store = Store::open(path, Store::Mode::CreateBulk);
    LayerInfo l;
    l.name = "dem";
    l.tile_size = kTileSize;
    l.level = kLevel;
    store->create_layer(l);
    for (int k = 0; k < kTiles; ++k)
      store->put_tile("dem", cell_of(k), test::smooth_tile(kTileSize, float(k)));
    char go = 0;
    if (::write(filled[1], &go, 1) != 1 || ::read(opened[0], &go, 1) != 1) ::_exit(3);
    sqlite3* db = nullptr;
    if (sqlite3_open(path.c_str(), &db) != SQLITE_OK ||
        sqlite3_exec(db,
                     "PRAGMA cache_size = 1; BEGIN; "
                     "UPDATE tiles SET blob = zeroblob(length(blob));",
                     nullptr, nullptr, nullptr) != SQLITE_OK)
      ::_exit(2);
    ::kill(::getpid(), SIGKILL);
  }
  char go = 0;
  ASSERT_EQ(::read(filled[0], &go, 1), 1) << "writer failed";
  const auto before = Store::open(path, Store::Mode::ReadOnly);
  ASSERT_EQ(before->tile_cells("dem").size(), size_t(kTiles));
  ASSERT_EQ(::write(opened[1], &go, 1), 1);
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status)) << "child exited with " << WEXITSTATUS(status);
  struct stat journal {};
  ASSERT_EQ(::stat((path + "-journal").c_str(), &journal), 0);
  ASSERT_GT(journal.st_size, 0);

  const auto after = Store::open(path, Store::Mode::ReadOnly);
  for (const Store* store : {before.get(), after.get()}) {
    EXPECT_TRUE(store->integrity_ok());
    ASSERT_EQ(store->tile_cells("dem").size(), size_t(kTiles));
    for (int k = 0; k < kTiles; ++k)
      EXPECT_EQ(store->get_tile("dem", cell_of(k))->bytes,
                test::smooth_tile(kTileSize, float(k)).bytes);
  }
}

TEST(StoreCrash, KilledWriterLeavesAValidStore) { kill_writers_and_check(Store::Mode::Create); }

TEST(StoreCrash, KilledContentWriterLeavesAValidStore) {
  kill_writers_and_check(Store::Mode::Create, Writes::Content);
}

TEST(StoreCrash, KilledBulkFillLeavesAValidStore) {
  kill_writers_and_check(Store::Mode::CreateBulk);
}

}  // namespace
}  // namespace maquette
