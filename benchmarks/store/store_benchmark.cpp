// Store throughput with 256x256 float32 tiles of smooth, terrain-like data (a sum of sines):
// codec alone, batched writes, point reads, range scans and overview rebuilds; and the codec alone
// on the unit normals of those surfaces (float32 x 3). Bytes processed are raw tile bytes (256 KiB
// per tile, 768 KiB for normals), so MB/s compares directly with the raw data rate.
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>

#include "store/codec.h"
#include "store/store.h"

namespace maquette {
namespace {

constexpr int kSize = 256;
constexpr int kLevel = 8;
constexpr int64_t kTileBytes = int64_t(kSize) * kSize * 4;

RawTile smooth_tile(int64_t seed) {
  std::vector<float> v(size_t(kSize) * kSize);
  const float s = float(seed % 1000) * 0.37f;
  for (int r = 0; r < kSize; ++r)
    for (int c = 0; c < kSize; ++c)
      v[size_t(r) * kSize + c] = 1200.0f + 400.0f * std::sin(0.013f * c + s) +
                                 250.0f * std::cos(0.021f * r - s) +
                                 40.0f * std::sin(0.09f * (c + 2 * r) + s) +
                                 6.0f * std::sin(0.41f * c) * std::cos(0.37f * r);
  RawTile t{DType::F32, kSize, 1, std::vector<std::byte>(v.size() * 4)};
  std::memcpy(t.bytes.data(), v.data(), t.bytes.size());
  return t;
}

CellId cell_of(int64_t k) {
  return CellId::FromFaceColRow(int(k % 6), kLevel, uint32_t((k / 6) % 256),
                                uint32_t((k / 6) / 256 % 256));
}

// A store file in the temp directory, deleted (with its WAL) afterwards.
struct TempStore {
  explicit TempStore(const std::string& codec) {
    path = (std::filesystem::temp_directory_path() /
            ("maquette-bench-" + std::to_string(::getpid()) + ".mqs"))
               .string();
    std::filesystem::remove(path);
    store = Store::open(path, Store::Mode::Create);
    LayerInfo l;
    l.name = "dem";
    l.tile_size = kSize;
    l.level = kLevel;
    l.codec = codec;
    store->create_layer(l);
  }
  ~TempStore() {
    store.reset();
    for (const char* suffix : {"", "-wal", "-shm"}) std::filesystem::remove(path + suffix);
  }
  std::string path;
  std::unique_ptr<Store> store;
};

// The unit normals (east, north, up) of smooth_tile(seed) as a surface of 30 m pixels:
// float32 x 3, what terrain.derive writes.
RawTile normal_tile(int64_t seed) {
  const RawTile dem = smooth_tile(seed);
  std::vector<float> h(size_t(kSize) * kSize), n(3 * h.size());
  std::memcpy(h.data(), dem.bytes.data(), dem.bytes.size());
  const auto at = [&](int c, int r) {
    return h[size_t(std::clamp(r, 0, kSize - 1)) * kSize + size_t(std::clamp(c, 0, kSize - 1))];
  };
  for (int r = 0; r < kSize; ++r)
    for (int c = 0; c < kSize; ++c) {
      const double ge = (at(c + 1, r) - at(c - 1, r)) / 60.0;
      const double gn = (at(c, r - 1) - at(c, r + 1)) / 60.0;
      const double k = 1 / std::sqrt(1 + ge * ge + gn * gn);
      float* p = &n[3 * (size_t(r) * kSize + size_t(c))];
      p[0] = float(-ge * k);
      p[1] = float(-gn * k);
      p[2] = float(k);
    }
  RawTile t{DType::F32, kSize, 3, std::vector<std::byte>(n.size() * 4)};
  std::memcpy(t.bytes.data(), n.data(), t.bytes.size());
  return t;
}

// A few distinct tiles, so that compression does not see the same bytes every time.
template <RawTile (*make)(int64_t)>
const std::vector<RawTile>& distinct_tiles() {
  static const std::vector<RawTile> tiles = [] {
    std::vector<RawTile> out;
    for (int i = 0; i < 16; ++i) out.push_back(make(i));
    return out;
  }();
  return tiles;
}
const std::vector<RawTile>& sample_tiles() { return distinct_tiles<smooth_tile>(); }
const std::vector<RawTile>& sample_normal_tiles() { return distinct_tiles<normal_tile>(); }
using TileSet = const std::vector<RawTile>& (*)();

void report(benchmark::State& state, int64_t tiles, const TempStore* store = nullptr,
            int64_t tile_bytes = kTileBytes) {
  state.SetBytesProcessed(tiles * tile_bytes);
  state.SetItemsProcessed(tiles);
  if (store)
    state.counters["ratio"] = double(store->store->stats("dem").bytes) /
                              double(store->store->stats("dem").tile_count * kTileBytes);
}

void BM_Encode(benchmark::State& state, const char* codec_name, TileSet tiles = sample_tiles) {
  const Codec codec = parse_codec(codec_name);
  const int64_t tile_bytes = int64_t(tiles()[0].bytes.size());
  int64_t n = 0, bytes = 0;
  for (auto _ : state) {
    auto blob = encode_tile(tiles()[n % 16], codec);
    bytes += int64_t(blob.size());
    benchmark::DoNotOptimize(blob.data());
    ++n;
  }
  report(state, n, nullptr, tile_bytes);
  state.counters["ratio"] = double(bytes) / double(n * tile_bytes);
}

void BM_Decode(benchmark::State& state, const char* codec_name, TileSet tiles = sample_tiles) {
  std::vector<std::vector<std::byte>> blobs;
  for (const auto& t : tiles()) blobs.push_back(encode_tile(t, parse_codec(codec_name)));
  int64_t n = 0;
  for (auto _ : state) {
    auto tile = decode_tile(blobs[n % 16]);
    benchmark::DoNotOptimize(tile.bytes.data());
    ++n;
  }
  report(state, n, nullptr, int64_t(tiles()[0].bytes.size()));
}

// Writes batches of state.range(0) tiles, each batch one transaction, to fresh cells.
void BM_Write(benchmark::State& state, const char* codec) {
  TempStore s(codec);
  const int batch_size = int(state.range(0));
  int64_t k = 0;
  for (auto _ : state) {
    Store::Batch batch(*s.store);
    for (int i = 0; i < batch_size; ++i, ++k)
      batch.put_tile("dem", cell_of(k), sample_tiles()[k % 16]);
    batch.commit();
  }
  report(state, k, &s);
}

// Point reads (get_tile, decoded) of 256 stored tiles in random order.
void BM_Read(benchmark::State& state, const char* codec) {
  TempStore s(codec);
  constexpr int kTiles = 256;
  {
    Store::Batch batch(*s.store);
    for (int k = 0; k < kTiles; ++k) batch.put_tile("dem", cell_of(k), sample_tiles()[k % 16]);
    batch.commit();
  }
  int64_t n = 0;
  for (auto _ : state) {
    const int64_t k = (n * 97) % kTiles;
    auto tile = s.store->get_tile("dem", cell_of(k));
    benchmark::DoNotOptimize(tile->bytes.data());
    ++n;
  }
  report(state, n, &s);
}

// Range scan (id order) over all 256 stored tiles.
void BM_Scan(benchmark::State& state) {
  TempStore s("zstd");
  constexpr int kTiles = 256;
  {
    Store::Batch batch(*s.store);
    for (int k = 0; k < kTiles; ++k) batch.put_tile("dem", cell_of(k), sample_tiles()[k % 16]);
    batch.commit();
  }
  int64_t n = 0;
  for (auto _ : state)
    s.store->scan("dem", CellId(0), CellId(uint64_t(INT64_MAX)), [&](CellId, const RawTile& t) {
      benchmark::DoNotOptimize(t.bytes.data());
      ++n;
    });
  report(state, n);
}

// Rebuilding all overview levels above 256 base tiles (64 + 16 + 4 + ... overview tiles).
void BM_UpdateOverviews(benchmark::State& state) {
  TempStore s("zstd");
  constexpr int kTiles = 256;
  int64_t n = 0;
  for (auto _ : state) {
    state.PauseTiming();
    {
      Store::Batch batch(*s.store);
      // 256 cells forming a 16x16 block of face O at kLevel.
      for (int k = 0; k < kTiles; ++k)
        batch.put_tile("dem", CellId::FromFaceColRow(1, kLevel, k % 16, k / 16),
                       sample_tiles()[k % 16]);
      batch.commit();
    }
    state.ResumeTiming();
    s.store->update_overviews("dem");
    n += kTiles;
  }
  report(state, n);
}

BENCHMARK_CAPTURE(BM_Encode, zstd, "zstd");
BENCHMARK_CAPTURE(BM_Encode, zstd3, "zstd:3");  // the level stores were written at before
BENCHMARK_CAPTURE(BM_Encode, raw, "raw");
BENCHMARK_CAPTURE(BM_Decode, zstd, "zstd");
BENCHMARK_CAPTURE(BM_Decode, zstd3, "zstd:3");
// Normals (float32 x 3, 768 KiB per tile): zstd against normal_oct at its default level and -1.
BENCHMARK_CAPTURE(BM_Encode, normals_zstd, "zstd", sample_normal_tiles);
BENCHMARK_CAPTURE(BM_Encode, normals_oct, "normal_oct", sample_normal_tiles);
BENCHMARK_CAPTURE(BM_Encode, normals_oct_fast, "normal_oct:-1", sample_normal_tiles);
BENCHMARK_CAPTURE(BM_Decode, normals_zstd, "zstd", sample_normal_tiles);
BENCHMARK_CAPTURE(BM_Decode, normals_oct, "normal_oct", sample_normal_tiles);
BENCHMARK_CAPTURE(BM_Write, zstd, "zstd")->Arg(1)->Arg(16)->Arg(64)->UseRealTime();
BENCHMARK_CAPTURE(BM_Write, raw, "raw")->Arg(16)->UseRealTime();
BENCHMARK_CAPTURE(BM_Read, zstd, "zstd")->UseRealTime();
BENCHMARK_CAPTURE(BM_Read, raw, "raw")->UseRealTime();
BENCHMARK(BM_Scan)->UseRealTime();
BENCHMARK(BM_UpdateOverviews)->UseRealTime()->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace maquette

BENCHMARK_MAIN();
