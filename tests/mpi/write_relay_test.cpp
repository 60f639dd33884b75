// WriteRelay (`maquette run --store-copies`) between the 3 ranks of one mpirun, each with its own
// store: every rank relays its share of 1024 cells' batches (one raw 64 KiB tile each, above
// MPI's eager limit, so a send completes only once its receiver takes it) while the writer
// commits and passes on every batch; each rank's store ends holding every tile with the bytes
// its rank made, and no rank ever held more than WriteRelay::kMaxHeld batches (queued, being
// sent, being committed), however far its sends ran ahead of the writer. The messages go in
// pieces of 65521 bytes (MAQUETTE_MPI_PIECE_BYTES), so each batch is split and reassembled.
#include "runtime/write_relay.h"

#include <gtest/gtest.h>
#include <stdlib.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <new>

#include "runtime/message_pieces.h"
#include "runtime/ranks.h"
#include "store/store.h"

namespace maquette {
namespace {

namespace fs = std::filesystem;

Ranks* the_ranks = nullptr;  // this job's, from main()

constexpr int kTileSize = 128;

LayerInfo noise_layer() {
  LayerInfo l;
  l.name = "noise";
  l.tile_size = kTileSize;
  l.level = 6;
  l.codec = "raw";  // the batches keep their 64 KiB
  return l;
}

// The 1024 cells of Q2 at level 6, in id order.
std::vector<CellId> cells() {
  std::vector<CellId> level = {*CellId::FromText("Q2")};
  for (int l = 1; l < 6; ++l) {
    std::vector<CellId> finer;
    for (const CellId c : level)
      for (int k = 0; k < 4; ++k) finer.push_back(c.child(k));
    level = std::move(finer);
  }
  return level;
}

// A tile of values that depend on the cell and the sample (an LCG from the cell id).
RawTile tile_of(CellId cell) {
  RawTile t{DType::F32, kTileSize, 1, std::vector<std::byte>(kTileSize * kTileSize * 4)};
  uint64_t state = cell.id();
  for (size_t i = 0; i < t.sample_count(); ++i) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    const float v = float(state >> 40);
    std::memcpy(t.bytes.data() + 4 * i, &v, 4);
  }
  return t;
}

// Relays this rank's share of `cells` (every ranks.size()-th from its rank), a batch of one tile
// each, committed to `store` and handed to `relay`, to the copies too.
void relay_tiles(Ranks& ranks, Store& store, WriteRelay& relay, const std::vector<CellId>& cells) {
  relay.run(
      [&] {
        for (size_t i = size_t(ranks.rank()); i < cells.size(); i += size_t(ranks.size())) {
          Store::Batch batch(store);
          batch.put_tile("noise", cells[i], tile_of(cells[i]));
          std::string bytes = batch.serialize();
          batch.commit();
          relay.relay(std::move(bytes));
        }
      },
      true);
}

TEST(MpiWriteRelay, MemoryIsBoundedAndEveryStoreGetsEveryBatch) {
  Ranks& ranks = *the_ranks;
  ASSERT_EQ(ranks.size(), 3) << "run under mpirun -np 3";
  // Rank 0's temporary directory, for every rank's store.
  std::string dir = ranks.root() ? fs::temp_directory_path() / "maquette-relay-XXXXXX" : "";
  if (ranks.root()) {
    ASSERT_NE(mkdtemp(dir.data()), nullptr);
  }
  dir = ranks.all_gather(dir).front();
  const std::string path = dir + "/rank" + std::to_string(ranks.rank()) + ".mqt";
  {
    auto store = Store::open(path, Store::Mode::Create);
    store->create_layer(noise_layer());
    WriteRelay relay(ranks, *store);
    const std::vector<CellId> all = cells();
    relay_tiles(ranks, *store, relay, all);
    std::printf("rank %d held at most %zu batches (bound %zu)\n", ranks.rank(), relay.most_held(),
                WriteRelay::kMaxHeld);
    EXPECT_LE(relay.most_held(), WriteRelay::kMaxHeld);
    EXPECT_GT(relay.most_held(), 0u);
    EXPECT_EQ(store->stats("noise").tile_count, int64_t(all.size()));
    for (const CellId c : all) {
      const auto tile = store->get_tile("noise", c);
      ASSERT_TRUE(tile) << c.ToText();
      ASSERT_EQ(tile->bytes, tile_of(c).bytes) << c.ToText();
    }
  }
  ranks.all_gather("");  // every rank is done with its store
  if (ranks.root()) fs::remove_all(dir);
}

// This job's ranks, except that rank 1's poll() fails as if out of memory receiving a batch.
class FailingPollOnRank1 final : public Ranks {
 public:
  explicit FailingPollOnRank1(Ranks& ranks) : ranks_(ranks) {}
  int rank() const override { return ranks_.rank(); }
  int size() const override { return ranks_.size(); }
  std::vector<std::string> all_gather(const std::string& bytes) override {
    return ranks_.all_gather(bytes);
  }
  void post(const std::vector<int>& to, std::string bytes) override {
    ranks_.post(to, std::move(bytes));
  }
  std::optional<Message> poll() override {
    if (ranks_.rank() == 1) throw std::bad_alloc();
    return ranks_.poll();
  }
  size_t sending() override { return ranks_.sending(); }
  [[noreturn]] void abort(const std::string& message) override {
    ranks_.abort(message);
    std::abort();  // not reached; gcc does not take [[noreturn]] through a virtual call
  }

 private:
  Ranks& ranks_;
};

// Run as a test of its own (CMakeLists.txt): the job must end within its timeout, its output
// naming the failing rank and the error; before, the other ranks waited for rank 1 forever.
TEST(MpiWriteRelayFailure, AFailurePassingMessagesEndsTheJobNamingTheRank) {
  FailingPollOnRank1 ranks(*the_ranks);
  ASSERT_EQ(ranks.size(), 3) << "run under mpirun -np 3";
  // In the test's working directory, which the job ends without cleaning.
  const std::string path = "relay-failure-rank" + std::to_string(ranks.rank()) + ".mqt";
  fs::remove(path);
  auto store = Store::open(path, Store::Mode::Create);
  store->create_layer(noise_layer());
  WriteRelay relay(ranks, *store);
  const std::vector<CellId> all = cells();
  relay_tiles(ranks, *store, relay, std::vector<CellId>(all.begin(), all.begin() + 64));
  ADD_FAILURE() << "rank " << ranks.rank() << " returned from a relay that failed on rank 1";
}

}  // namespace
}  // namespace maquette

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  setenv(maquette::kPieceLimitVariable, "65521", 1);  // read by every rank's MPI plug-in
  const std::unique_ptr<maquette::Ranks> ranks = maquette::launched_ranks();
  maquette::the_ranks = ranks.get();
  return RUN_ALL_TESTS();
}
