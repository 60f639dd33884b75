// Tile blob encoding. A blob is a 16-byte header followed by the payload:
//
//   0  magic "MQTL"      4  format version (1)   5  codec (0 raw, 1 zstd, 2 normal_oct)
//   6  dtype (DType)     7  reserved (0)         8  tile size (u32 LE)   12  channels (u32 LE)
//
// raw: the samples as stored in memory (little endian). zstd: the samples byte-shuffled (all
// first bytes of every sample, then all second bytes, ... as Blosc and HDF5 do, so that the
// slowly varying high bytes of smooth data form long runs) and compressed as one zstd frame
// with its content size and checksum. normal_oct (float32 layers of 3 channels holding unit
// normals; lossy): each normal as two 12-bit octahedral integers (normal_oct.h), predicted from
// their neighbours, the differences zigzag-mapped into uint16 and compressed as zstd's are. The
// header names the tile as decoded: float32, 3 channels.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/tile.h"

namespace maquette {

// A layer's codec string names the blob format only: decoding is the same whatever level a tile
// was compressed at, so the level is the encoder's choice and may differ between tiles of a
// layer (a layer written at one level can be resumed or appended to at another).
struct Codec {
  enum class Kind : uint8_t { Raw = 0, Zstd = 1, NormalOct = 2 };
  // zstd's first "fast" level: on shuffled tiles ~1.7-3x faster to encode than level 3 (and
  // faster to decode) for ~5 % more bytes (benchmarks/README.md, "Store").
  static constexpr int kDefaultLevel = -1;
  static constexpr int kMinLevel = -7;  // faster levels only lose compression
  // normal_oct's default: its small prediction differences take ~20 % fewer bytes at level 3
  // than at -1 (benchmarks/README.md, "Normals"), and octahedral encoding dominates its time.
  static constexpr int kNormalOctLevel = 3;
  Kind kind = Kind::Zstd;
  int level = kDefaultLevel;  // zstd compression level: kMinLevel..-1 or 1..22

  // Whether decoding gives back the tile encoded bit for bit (raw, zstd) or an approximation
  // (normal_oct: the nearest of its directions, unit length).
  bool lossless() const { return kind != Kind::NormalOct; }
};

// Parses "raw", "zstd", "zstd:LEVEL", "normal_oct" or "normal_oct:LEVEL"; throws maquette::Error.
Codec parse_codec(std::string_view text);

// Throws maquette::Error for a tile the codec cannot hold (normal_oct: other than float32 x 3, or a
// normal without a direction).
std::vector<std::byte> encode_tile(const RawTile& tile, const Codec& codec);
// Throws maquette::Error unless the codec can hold tiles of `dtype` with `channels` channels.
void check_codec_holds(const Codec& codec, DType dtype, int channels);
// Throws maquette::Error describing what is wrong with the blob (the caller adds which tile).
RawTile decode_tile(std::span<const std::byte> blob);

// Byte shuffle of samples `width` bytes wide: out[b * n + i] = in[i * width + b].
void shuffle_bytes(std::span<const std::byte> in, size_t width, std::span<std::byte> out);
void unshuffle_bytes(std::span<const std::byte> in, size_t width, std::span<std::byte> out);

}  // namespace maquette
