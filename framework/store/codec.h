// Tile blob encoding. A blob is a 16-byte header followed by the payload:
//
//   0  magic "MQTL"      4  format version (1)   5  codec (0 raw, 1 zstd)
//   6  dtype (DType)     7  reserved (0)         8  tile size (u32 LE)   12  channels (u32 LE)
//
// raw: the samples as stored in memory (little endian). zstd: the samples byte-shuffled (all
// first bytes of every sample, then all second bytes, ... as Blosc and HDF5 do, so that the
// slowly varying high bytes of smooth data form long runs) and compressed as one zstd frame
// with its content size and checksum.
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
  enum class Kind : uint8_t { Raw = 0, Zstd = 1 };
  // zstd's first "fast" level: on shuffled tiles ~1.7-3x faster to encode than level 3 (and
  // faster to decode) for ~5 % more bytes (benchmarks/README.md, "Store").
  static constexpr int kDefaultLevel = -1;
  static constexpr int kMinLevel = -7;  // faster levels only lose compression
  Kind kind = Kind::Zstd;
  int level = kDefaultLevel;  // zstd compression level: kMinLevel..-1 or 1..22
};

// Parses "raw", "zstd" or "zstd:LEVEL"; throws maquette::Error.
Codec parse_codec(std::string_view text);

std::vector<std::byte> encode_tile(const RawTile& tile, const Codec& codec);
// Throws maquette::Error describing what is wrong with the blob (the caller adds which tile).
RawTile decode_tile(std::span<const std::byte> blob);

// Byte shuffle of samples `width` bytes wide: out[b * n + i] = in[i * width + b].
void shuffle_bytes(std::span<const std::byte> in, size_t width, std::span<std::byte> out);
void unshuffle_bytes(std::span<const std::byte> in, size_t width, std::span<std::byte> out);

}  // namespace maquette
