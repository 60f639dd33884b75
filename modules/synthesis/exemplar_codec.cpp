#include "exemplar_codec.h"

#include <zstd.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <memory>
#include <string>
#include <type_traits>

#include "core/error.h"

namespace maquette::synthesis {
namespace {

constexpr std::array<char, 8> kMagic{'M', 'Q', 'E', 'X', 'E', 'M', 'P', 'L'};
// zstd's level: the payload (floats and indices) compresses little more at higher levels, and
// the file is written once per exemplar.
constexpr int kZstdLevel = 1;
constexpr uint64_t kMostLevels = 64;

#if defined(__GLIBCXX__) && UINTPTR_MAX == UINT64_MAX
// A field added to ExemplarLevel must be added to level_fields below, and the version bumped.
static_assert(sizeof(ExemplarLevel) == 7368, "ExemplarLevel changed: update level_fields");
#endif

// Appends fields to `out`.
struct Writer {
  std::vector<std::byte>& out;

  void bytes(const void* p, size_t n) {
    const auto* b = static_cast<const std::byte*>(p);
    out.insert(out.end(), b, b + n);
  }
  template <class T>
  requires std::is_trivially_copyable_v<T>
  void operator()(const T& v) { bytes(&v, sizeof v); }
  template <class T>
  void operator()(const std::vector<T>& v) {
    (*this)(uint64_t(v.size()));
    bytes(v.data(), v.size() * sizeof(T));
  }
  template <class T>
  void count(const std::vector<T>& v) {
    (*this)(uint64_t(v.size()));
  }
};

// Reads fields back from `in`, throwing when it ends early.
struct Reader {
  std::span<const std::byte> in;
  size_t at = 0;

  void bytes(void* p, size_t n) {
    if (n > in.size() - at) throw Error("truncated");
    if (n > 0) std::memcpy(p, in.data() + at, n);
    at += n;
  }
  template <class T>
  requires std::is_trivially_copyable_v<T>
  void operator()(T& v) { bytes(&v, sizeof v); }
  template <class T>
  void operator()(std::vector<T>& v) {
    uint64_t n = 0;
    (*this)(n);
    if (n > (in.size() - at) / sizeof(T)) throw Error("truncated");
    v.resize(n);
    bytes(v.data(), n * sizeof(T));
  }
  template <class T>
  void count(std::vector<T>& v) {
    uint64_t n = 0;
    (*this)(n);
    if (n > kMostLevels) throw Error(std::to_string(n) + " levels");
    v.resize(n);
  }
};

// Every field of a level, in the file's order (written or read by `a`).
template <class Archive, class Level>
void level_fields(Archive& a, Level& l) {
  a(l.width);
  a(l.height);
  a(l.rgb);
  a(l.labels);
  a(l.altitude);
  a(l.distance);
  a(l.excluded);
  a(l.basis);
  a(l.features);
  a(l.similar);
  a(l.allowed);
  for (auto& pixels : l.by_label) a(pixels);
  a(l.usage);
  a(l.colour_excess);
}

template <class Archive, class Exemplar>
void exemplar_fields(Archive& a, Exemplar& t) {
  a(t.scale);
  a(t.parts);
  a(t.pyramid.k);
  a.count(t.pyramid.levels);
  for (auto& level : t.pyramid.levels) level_fields(a, level);
}

// Throws unless the decoded fields have their levels' sizes (the synthesis indexes them so).
void check_sizes(const TransferExemplar& t) {
  const auto fail = [](const std::string& what) { return Error("inconsistent sizes: " + what); };
  if (t.scale < 1 || t.parts.empty() || t.pyramid.k < 1 || t.pyramid.levels.empty())
    throw fail("scale, paintings, k or levels");
  for (const ExemplarLevel& l : t.pyramid.levels) {
    if (l.width < 1 || l.height < 1 || l.width > 65535 || l.height > 65535)
      throw fail("a level's width or height");
    const size_t n = size_t(l.width) * size_t(l.height);
    const auto per_pixel = [&](size_t size, size_t each, bool optional) {
      return size == n * each || (optional && size == 0);
    };
    size_t labelled = 0;
    for (const auto& pixels : l.by_label) labelled += pixels.size();
    if (!per_pixel(l.rgb.size(), 3, false) || !per_pixel(l.labels.size(), 1, false) ||
        !per_pixel(l.altitude.size(), 1, true) || !per_pixel(l.distance.size(), 1, true) ||
        !per_pixel(l.excluded.size(), 1, false) ||
        !per_pixel(l.features.size(), kFeatureDims, false) ||
        !per_pixel(l.similar.size(), size_t(t.pyramid.k), false) || l.allowed.size() > n ||
        labelled != l.allowed.size() || !per_pixel(l.usage.size(), 1, true) ||
        !per_pixel(l.colour_excess.size(), 1, true))
      throw fail("a level's fields");
  }
}

struct Header {
  std::array<char, 8> magic = kMagic;
  uint32_t version = kExemplarCacheVersion;
  uint32_t key_size = 0;
};

}  // namespace

std::vector<std::byte> encode_exemplar(const TransferExemplar& exemplar, std::string_view key) {
  std::vector<std::byte> payload;
  Writer fields{payload};
  exemplar_fields(fields, exemplar);

  std::vector<std::byte> file;
  Writer head{file};
  head(Header{kMagic, kExemplarCacheVersion, uint32_t(key.size())});
  head.bytes(key.data(), key.size());
  const size_t at = file.size();
  file.resize(at + ZSTD_compressBound(payload.size()));
  const std::unique_ptr<ZSTD_CCtx, decltype(&ZSTD_freeCCtx)> cctx(ZSTD_createCCtx(),
                                                                  &ZSTD_freeCCtx);
  ZSTD_CCtx_setParameter(cctx.get(), ZSTD_c_compressionLevel, kZstdLevel);
  ZSTD_CCtx_setParameter(cctx.get(), ZSTD_c_checksumFlag, 1);
  const size_t n = ZSTD_compress2(cctx.get(), file.data() + at, file.size() - at, payload.data(),
                                  payload.size());
  if (ZSTD_isError(n)) throw Error(std::string("zstd compression failed: ") + ZSTD_getErrorName(n));
  file.resize(at + n);
  return file;
}

TransferExemplar decode_exemplar(std::span<const std::byte> file, std::string_view key) {
  Reader head{file};
  Header header;
  head(header);
  if (header.magic != kMagic) throw Error("not an exemplar cache file");
  if (header.version != kExemplarCacheVersion)
    throw Error("format version " + std::to_string(header.version) + ", expected " +
                std::to_string(kExemplarCacheVersion));
  std::string stored(header.key_size, '\0');
  head.bytes(stored.data(), stored.size());
  if (stored != key) throw Error("stored under another key");
  const auto frame = file.subspan(head.at);
  const unsigned long long size = ZSTD_getFrameContentSize(frame.data(), frame.size());
  if (size == ZSTD_CONTENTSIZE_ERROR || size == ZSTD_CONTENTSIZE_UNKNOWN)
    throw Error("no zstd frame with its size");
  if (ZSTD_findFrameCompressedSize(frame.data(), frame.size()) != frame.size())
    throw Error("truncated or trailing bytes");
  std::vector<std::byte> payload(size);
  const size_t n = ZSTD_decompress(payload.data(), payload.size(), frame.data(), frame.size());
  if (ZSTD_isError(n)) throw Error(std::string("zstd: ") + ZSTD_getErrorName(n));
  if (n != size) throw Error("truncated");
  TransferExemplar out;
  Reader fields{payload};
  exemplar_fields(fields, out);
  if (fields.at != payload.size()) throw Error("trailing bytes");
  check_sizes(out);
  return out;
}

}  // namespace maquette::synthesis
