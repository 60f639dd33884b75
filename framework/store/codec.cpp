#include "store/codec.h"

#include <zstd.h>

#include <bit>
#include <charconv>
#include <cstring>
#include <memory>
#include <string>
#include <type_traits>

#include "core/error.h"
#include "store/normal_oct.h"

namespace maquette {
namespace {

static_assert(std::endian::native == std::endian::little,
              "tile blobs hold little-endian samples in native order");

constexpr char kMagic[4] = {'M', 'Q', 'T', 'L'};
constexpr uint8_t kFormatVersion = 1;
constexpr size_t kHeaderSize = 16;
constexpr uint32_t kMaxChannels = 1024;

// One compression and one decompression context per thread: creating them per tile costs more
// than compressing a small tile. Likewise the shuffled samples and the compressed frame go
// through buffers kept per thread (grown to the largest tile seen): fresh 64-256 KiB vectors
// would be zeroed and page-faulted in for every tile.
struct ZstdContexts {
  std::unique_ptr<ZSTD_CCtx, decltype(&ZSTD_freeCCtx)> c{ZSTD_createCCtx(), &ZSTD_freeCCtx};
  std::unique_ptr<ZSTD_DCtx, decltype(&ZSTD_freeDCtx)> d{ZSTD_createDCtx(), &ZSTD_freeDCtx};
  std::vector<std::byte> shuffled, frame;
  std::vector<float> normals;   // normal_oct: a tile's normals
  std::vector<uint16_t> codes;  // normal_oct: their predicted, zigzag-mapped codes
};
ZstdContexts& zstd_contexts() {
  thread_local ZstdContexts contexts;
  return contexts;
}

void put_u32(std::byte* p, uint32_t v) { std::memcpy(p, &v, 4); }
uint32_t get_u32(const std::byte* p) {
  uint32_t v;
  std::memcpy(&v, p, 4);
  return v;
}

}  // namespace

Codec parse_codec(std::string_view text) {
  if (text == "raw") return {Codec::Kind::Raw, 0};
  if (text == "zstd") return {};
  if (text == "normal_oct") return {Codec::Kind::NormalOct, Codec::kNormalOctLevel};
  for (const auto& [prefix, kind] :
       {std::pair{std::string_view("zstd:"), Codec::Kind::Zstd},
        std::pair{std::string_view("normal_oct:"), Codec::Kind::NormalOct}}) {
    if (!text.starts_with(prefix)) continue;
    const std::string_view digits = text.substr(prefix.size());
    int level = 0;
    auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), level);
    if (ec == std::errc() && end == digits.data() + digits.size() && level != 0 &&
        level >= Codec::kMinLevel && level <= ZSTD_maxCLevel())
      return {kind, level};
  }
  throw Error("unknown codec '" + std::string(text) + "' (expected raw, zstd, zstd:LEVEL, " +
              "normal_oct or normal_oct:LEVEL with LEVEL in " + std::to_string(Codec::kMinLevel) +
              "..-1 or 1.." + std::to_string(ZSTD_maxCLevel()) + ")");
}

void check_codec_holds(const Codec& codec, DType dtype, int channels) {
  if (codec.kind == Codec::Kind::NormalOct && (dtype != DType::F32 || channels != 3))
    throw Error("codec normal_oct holds unit normals, float32 with 3 channels, not " +
                std::string(dtype_name(dtype)) + " with " + std::to_string(channels));
}

namespace {

// Calls f(std::integral_constant<size_t, width>): with the sample width known at compile time,
// the (un)shuffle loops unroll into `width` sequential streams, several times faster.
template <typename F>
void with_width(size_t width, F&& f) {
  switch (width) {
    case 1:
      return f(std::integral_constant<size_t, 1>{});
    case 2:
      return f(std::integral_constant<size_t, 2>{});
    case 4:
      return f(std::integral_constant<size_t, 4>{});
    case 8:
      return f(std::integral_constant<size_t, 8>{});
  }
  throw Error("cannot shuffle samples of " + std::to_string(width) + " bytes");
}

}  // namespace

void shuffle_bytes(std::span<const std::byte> in, size_t width, std::span<std::byte> out) {
  with_width(width, [&](auto w) {
    const size_t n = in.size() / w;
    for (size_t i = 0; i < n; ++i)
      for (size_t b = 0; b < w; ++b) out[b * n + i] = in[i * w + b];
  });
}

void unshuffle_bytes(std::span<const std::byte> in, size_t width, std::span<std::byte> out) {
  with_width(width, [&](auto w) {
    const size_t n = in.size() / w;
    for (size_t i = 0; i < n; ++i)
      for (size_t b = 0; b < w; ++b) out[i * w + b] = in[b * n + i];
  });
}

namespace {

// Appends `samples` (each `width` bytes) to `blob`, byte shuffled and compressed as one zstd frame
// with its content size and a checksum.
void append_zstd(std::span<const std::byte> samples, size_t width, int level,
                 std::vector<std::byte>& blob) {
  ZstdContexts& z = zstd_contexts();
  if (z.shuffled.size() < samples.size()) z.shuffled.resize(samples.size());
  const std::span<std::byte> shuffled(z.shuffled.data(), samples.size());
  shuffle_bytes(samples, width, shuffled);
  ZSTD_CCtx* cctx = z.c.get();
  ZSTD_CCtx_reset(cctx, ZSTD_reset_session_and_parameters);
  ZSTD_CCtx_setParameter(cctx, ZSTD_c_compressionLevel, level);
  ZSTD_CCtx_setParameter(cctx, ZSTD_c_checksumFlag, 1);
  const size_t bound = ZSTD_compressBound(samples.size());
  if (z.frame.size() < bound) z.frame.resize(bound);
  const size_t n =
      ZSTD_compress2(cctx, z.frame.data(), z.frame.size(), shuffled.data(), shuffled.size());
  if (ZSTD_isError(n)) throw Error(std::string("zstd compression failed: ") + ZSTD_getErrorName(n));
  blob.insert(blob.end(), z.frame.begin(), z.frame.begin() + std::ptrdiff_t(n));
}

// zstd's format: a block decodes to at most 128 KiB and takes at least its 3-byte header, so a
// frame decodes to at most this many bytes per byte of it.
constexpr size_t kZstdMaxBytesPerByte = (size_t(128) << 10) / 3;

// Throws unless `payload` is one zstd frame (nothing after it) whose content is `bytes` long and
// which is long enough to hold that many. Checked before anything is allocated for the content: a
// blob's header may name any tile size, and a frame's header any content size.
void check_zstd_frame(std::span<const std::byte> payload, size_t bytes) {
  if (ZSTD_getFrameContentSize(payload.data(), payload.size()) != bytes ||
      ZSTD_findFrameCompressedSize(payload.data(), payload.size()) != payload.size() ||
      bytes / kZstdMaxBytesPerByte > payload.size())
    throw Error("zstd frame does not hold " + std::to_string(bytes) + " bytes");
}

// The samples (each `width` bytes) of a frame append_zstd wrote, into `out`, which the frame must
// fill exactly (check_zstd_frame(payload, out.size()) passed).
void read_zstd(std::span<const std::byte> payload, size_t width, std::span<std::byte> out) {
  ZstdContexts& z = zstd_contexts();
  if (z.shuffled.size() < out.size()) z.shuffled.resize(out.size());
  const std::span<std::byte> shuffled(z.shuffled.data(), out.size());
  const size_t n =
      ZSTD_decompressDCtx(z.d.get(), shuffled.data(), out.size(), payload.data(), payload.size());
  if (ZSTD_isError(n)) throw Error(std::string("zstd: ") + ZSTD_getErrorName(n));
  if (n != out.size()) throw Error("zstd frame decoded to " + std::to_string(n) + " bytes");
  unshuffle_bytes(shuffled, width, out);
}

}  // namespace

std::vector<std::byte> encode_tile(const RawTile& tile, const Codec& codec) {
  const size_t width = dtype_size(tile.dtype);
  const size_t raw_size = tile.sample_count() * width;
  if (tile.bytes.size() != raw_size)
    throw Error("tile holds " + std::to_string(tile.bytes.size()) + " bytes, expected " +
                std::to_string(raw_size));
  check_codec_holds(codec, tile.dtype, tile.channels);

  std::vector<std::byte> blob(kHeaderSize);
  std::memcpy(blob.data(), kMagic, 4);
  blob[4] = std::byte{kFormatVersion};
  blob[5] = std::byte(codec.kind);
  blob[6] = std::byte(tile.dtype);
  blob[7] = std::byte{0};
  put_u32(blob.data() + 8, uint32_t(tile.size));
  put_u32(blob.data() + 12, uint32_t(tile.channels));

  switch (codec.kind) {
    case Codec::Kind::Raw:
      blob.resize(kHeaderSize + raw_size);
      std::memcpy(blob.data() + kHeaderSize, tile.bytes.data(), raw_size);
      break;
    case Codec::Kind::Zstd:
      append_zstd(tile.bytes, width, codec.level, blob);
      break;
    case Codec::Kind::NormalOct: {
      ZstdContexts& z = zstd_contexts();
      z.normals.resize(tile.sample_count());
      std::memcpy(z.normals.data(), tile.bytes.data(), raw_size);
      z.codes.resize(2 * size_t(tile.size) * size_t(tile.size));
      oct_encode_tile(z.normals, tile.size, z.codes);
      append_zstd(std::as_bytes(std::span(z.codes)), sizeof(uint16_t), codec.level, blob);
      break;
    }
  }
  return blob;
}

RawTile decode_tile(std::span<const std::byte> blob) {
  if (blob.size() < kHeaderSize)
    throw Error("blob of " + std::to_string(blob.size()) + " bytes is shorter than its header");
  if (std::memcmp(blob.data(), kMagic, 4) != 0) throw Error("blob does not start with MQTL");
  if (blob[4] != std::byte{kFormatVersion})
    throw Error("blob format version " + std::to_string(int(blob[4])) + " (expected 1)");
  const auto codec = uint8_t(blob[5]);
  const auto dtype = uint8_t(blob[6]);
  if (codec > uint8_t(Codec::Kind::NormalOct))
    throw Error("unknown codec " + std::to_string(codec));
  if (dtype > uint8_t(DType::F64)) throw Error("unknown dtype " + std::to_string(dtype));
  if (blob[7] != std::byte{0}) throw Error("reserved header byte is not 0");
  const uint32_t size = get_u32(blob.data() + 8);
  const uint32_t channels = get_u32(blob.data() + 12);
  if (size == 0 || size > 4096 || (size & (size - 1)) != 0)
    throw Error("tile size " + std::to_string(size) + " is not a power of two in [1, 4096]");
  if (channels == 0 || channels > kMaxChannels)
    throw Error("channel count " + std::to_string(channels) + " out of range");
  const Codec::Kind kind = Codec::Kind(codec);
  check_codec_holds({kind, 0}, DType(dtype), int(channels));

  RawTile tile{DType(dtype), int(size), int(channels), {}};
  const size_t width = dtype_size(tile.dtype);
  const size_t raw_size = tile.sample_count() * width;
  const auto payload = blob.subspan(kHeaderSize);
  switch (kind) {
    case Codec::Kind::Raw:
      if (payload.size() != raw_size)
        throw Error("raw payload of " + std::to_string(payload.size()) + " bytes, expected " +
                    std::to_string(raw_size));
      tile.bytes.assign(payload.begin(), payload.end());
      break;
    case Codec::Kind::Zstd:
      check_zstd_frame(payload, raw_size);
      tile.bytes.resize(raw_size);
      read_zstd(payload, width, tile.bytes);
      break;
    case Codec::Kind::NormalOct: {
      ZstdContexts& z = zstd_contexts();
      const size_t codes = 2 * size_t(size) * size_t(size);
      check_zstd_frame(payload, codes * sizeof(uint16_t));
      z.codes.resize(codes);
      read_zstd(payload, sizeof(uint16_t), std::as_writable_bytes(std::span(z.codes)));
      z.normals.resize(tile.sample_count());
      oct_decode_tile(z.codes, tile.size, z.normals);
      tile.bytes.resize(raw_size);
      std::memcpy(tile.bytes.data(), z.normals.data(), raw_size);
      break;
    }
  }
  return tile;
}

}  // namespace maquette
