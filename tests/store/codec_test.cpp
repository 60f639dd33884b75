// Tile blob encoding: bit-exact round trips, the byte shuffle, compression, corruption.
#include "store/codec.h"

#include <bit>
#include <limits>
#include <random>

#include "core/error.h"
#include "store_test_util.h"

namespace maquette {
namespace {

using test::raw_tile;
using test::smooth_tile;

// Random bytes for every sample: for float types this includes NaNs with arbitrary payloads,
// infinities and denormals, which must all come back bit for bit.
RawTile random_tile(DType dtype, int size, int channels, uint32_t seed) {
  RawTile t{dtype, size, channels, {}};
  t.bytes.resize(t.sample_count() * dtype_size(dtype));
  std::mt19937 rng(seed);
  for (auto& b : t.bytes) b = std::byte(rng() & 0xff);
  return t;
}

TEST(Codec, RoundTripsEveryDTypeBitExact) {
  for (DType dtype :
       {DType::U8, DType::U16, DType::I16, DType::U32, DType::I32, DType::F32, DType::F64})
    for (const char* codec : {"raw", "zstd", "zstd:3", "zstd:9", "zstd:-5"})
      for (int channels : {1, 3}) {
        const RawTile in = random_tile(dtype, 16, channels, uint32_t(dtype) * 7 + channels);
        const RawTile out = decode_tile(encode_tile(in, parse_codec(codec)));
        EXPECT_EQ(out.dtype, in.dtype);
        EXPECT_EQ(out.size, 16);
        EXPECT_EQ(out.channels, channels);
        EXPECT_EQ(out.bytes, in.bytes) << dtype_name(dtype) << ' ' << codec;
      }
}

TEST(Codec, KeepsNaNPayloads) {
  const std::vector<uint32_t> bits = {0x7fc00000, 0x7fa12345, 0xffc00001, 0x7f800001,
                                      0x7f800000, 0x00000001, 0x80000000, 0x3f800000};
  std::vector<float> values;
  for (uint32_t b : bits) values.push_back(std::bit_cast<float>(b));
  std::vector<float> tile_values;
  for (int i = 0; i < 2; ++i) tile_values.insert(tile_values.end(), values.begin(), values.end());
  const RawTile in = raw_tile<float>(4, 1, tile_values);
  const RawTile out = decode_tile(encode_tile(in, parse_codec("zstd")));
  const auto back = test::values_of<float>(out);
  for (size_t i = 0; i < back.size(); ++i)
    EXPECT_EQ(std::bit_cast<uint32_t>(back[i]), bits[i % bits.size()]) << i;
}

TEST(Codec, ShuffleGroupsBytesByPosition) {
  // Three 4-byte samples: the first bytes of all samples, then the second bytes, ...
  const std::vector<uint8_t> in = {0x00, 0x01, 0x02, 0x03, 0x10, 0x11,
                                   0x12, 0x13, 0x20, 0x21, 0x22, 0x23};
  const std::vector<uint8_t> expected = {0x00, 0x10, 0x20, 0x01, 0x11, 0x21,
                                         0x02, 0x12, 0x22, 0x03, 0x13, 0x23};
  std::vector<std::byte> shuffled(12), back(12);
  shuffle_bytes(std::as_bytes(std::span(in)), 4, shuffled);
  EXPECT_EQ(std::memcmp(shuffled.data(), expected.data(), 12), 0);
  unshuffle_bytes(shuffled, 4, back);
  EXPECT_EQ(std::memcmp(back.data(), in.data(), 12), 0);
}

TEST(Codec, ZstdShrinksASmoothFloatTile) {
  const RawTile tile = smooth_tile(256);
  const size_t raw = encode_tile(tile, parse_codec("raw")).size();
  const size_t zstd = encode_tile(tile, parse_codec("zstd")).size();
  EXPECT_EQ(raw, 16 + 256 * 256 * 4);
  EXPECT_LT(zstd, raw * 8 / 10) << "zstd " << zstd << " raw " << raw;
}

TEST(Codec, ParsesCodecNames) {
  EXPECT_EQ(parse_codec("raw").kind, Codec::Kind::Raw);
  EXPECT_EQ(parse_codec("zstd").level, -1);
  EXPECT_EQ(parse_codec("zstd:19").level, 19);
  EXPECT_EQ(parse_codec("zstd:-7").level, -7);
  for (const char* bad : {"", "lz4", "zstd:", "zstd:0", "zstd:99", "zstd:3x", "zstd:-8"})
    EXPECT_THROW(parse_codec(bad), Error) << bad;
}

TEST(Codec, RejectsCorruptBlobs) {
  const auto good = encode_tile(smooth_tile(32), parse_codec("zstd"));
  auto expect_bad = [](std::vector<std::byte> blob, const char* what) {
    try {
      decode_tile(blob);
      ADD_FAILURE() << "accepted " << what;
    } catch (const Error& e) {
      SUCCEED() << e.what();
    }
  };
  expect_bad({good.begin(), good.begin() + 10}, "a truncated header");
  expect_bad({good.begin(), good.end() - 5}, "a truncated payload");
  auto flipped = good;
  flipped[0] = std::byte{'X'};
  expect_bad(flipped, "a bad magic");
  flipped = good;
  flipped[good.size() / 2] ^= std::byte{0x5a};
  expect_bad(flipped, "a flipped payload byte");
  flipped = good;
  flipped[8] = std::byte{33};  // tile size 33
  expect_bad(flipped, "a size that is not a power of two");
  flipped = good;
  flipped[6] = std::byte{9};
  expect_bad(flipped, "an unknown dtype");
  auto longer = good;
  longer.push_back(std::byte{0});
  expect_bad(longer, "trailing bytes");
  const auto raw = encode_tile(smooth_tile(32), parse_codec("raw"));
  expect_bad({raw.begin(), raw.end() - 4}, "a short raw payload");
}

// A header naming the largest tile (4096 x 4096 x 1024 float64: 128 GiB) is refused from the frame
// before anything is allocated for it (fuzz/corpus/tile_blob/regress-*: std::bad_alloc before).
TEST(Codec, RefusesAHugeTileBeforeAllocatingIt) {
  const uint64_t huge = uint64_t(4096) * 4096 * 1024 * 8;
  auto header = encode_tile(smooth_tile(32), parse_codec("zstd"));
  header[6] = std::byte(DType::F64);
  const std::byte size_and_channels[8] = {std::byte{0}, std::byte{0x10}, std::byte{0},
                                          std::byte{0}, std::byte{0},    std::byte{0x04},
                                          std::byte{0}, std::byte{0}};
  std::copy(std::begin(size_and_channels), std::end(size_and_channels), header.begin() + 8);
  const std::string message = "zstd frame does not hold " + std::to_string(huge) + " bytes";
  // The 32 x 32 tile's frame, then a frame whose header claims the 128 GiB: one 128 KiB RLE block.
  std::vector<std::byte> claiming = {std::byte{0x28}, std::byte{0xb5}, std::byte{0x2f},
                                     std::byte{0xfd}, std::byte{0xc0}, std::byte{0x58}};
  for (int i = 0; i < 8; ++i) claiming.push_back(std::byte((huge >> (8 * i)) & 0xff));
  for (const uint8_t b : {0x03, 0x00, 0x10, 0x07}) claiming.push_back(std::byte{b});
  for (const auto& frame : {std::vector<std::byte>(header.begin() + 16, header.end()), claiming}) {
    std::vector<std::byte> blob(header.begin(), header.begin() + 16);
    blob.insert(blob.end(), frame.begin(), frame.end());
    try {
      decode_tile(blob);
      ADD_FAILURE() << "accepted a 128 GiB tile of " << blob.size() << " bytes";
    } catch (const Error& e) {
      EXPECT_EQ(e.what(), message);
    }
  }
}

}  // namespace
}  // namespace maquette
