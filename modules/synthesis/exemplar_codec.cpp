#include "exemplar_codec.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>

#include "class_edges.h"
#include "core/error.h"
#include "core/zstd_frame.h"

namespace maquette::synthesis {
namespace {

constexpr std::array<char, 8> kMagic{'M', 'Q', 'E', 'X', 'E', 'M', 'P', 'L'};
// zstd's level: the payload (floats and indices) compresses little more at higher levels, and
// the file is written once per exemplar.
constexpr int kZstdLevel = 1;
constexpr uint64_t kMostLevels = 64;

#if defined(__GLIBCXX__) && UINTPTR_MAX == UINT64_MAX
// A field added to ExemplarLevel must be added to level_fields below, and the format bumped.
static_assert(sizeof(ExemplarLevel) == 7440, "ExemplarLevel changed: update level_fields");
#endif

// Appends fields to `out`.
struct Writer {
  std::string& out;

  void bytes(const void* p, size_t n) { out.append(static_cast<const char*>(p), n); }
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
  std::string_view in;
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
  a(l.light);
  a(l.excluded);
  a(l.basis);
  a(l.features);
  a(l.similar);
  a(l.allowed);
  for (auto& pixels : l.by_label) a(pixels);
  a(l.usage);
  a(l.colour_excess);
  a(l.class_edges);
  a(l.region_quantile);
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
        !per_pixel(l.light.size(), 1, true) || !per_pixel(l.excluded.size(), 1, false) ||
        !per_pixel(l.features.size(), kFeatureDims, false) ||
        !per_pixel(l.similar.size(), size_t(t.pyramid.k), false) || l.allowed.size() > n ||
        labelled != l.allowed.size() || !per_pixel(l.usage.size(), 1, true) ||
        !per_pixel(l.colour_excess.size(), 1, true) ||
        !per_pixel(l.region_quantile.size(), 1, true))
      throw fail("a level's fields");
    // The passes read the pixels the class edges name.
    if (std::any_of(l.class_edges.begin(), l.class_edges.end(),
                    [n](uint64_t entry) { return size_t(class_edge_pixel(entry)) >= n; }))
      throw fail("a level's class edges");
  }
}

struct Header {
  std::array<char, 8> magic = kMagic;
  uint32_t version = kExemplarCacheVersion;
  uint32_t key_size = 0;
};

}  // namespace

std::string encode_exemplar(const TransferExemplar& exemplar, std::string_view key) {
  std::string payload;
  Writer fields{payload};
  exemplar_fields(fields, exemplar);

  std::string file;
  Writer head{file};
  head(Header{kMagic, kExemplarCacheVersion, uint32_t(key.size())});
  head.bytes(key.data(), key.size());
  append_zstd_frame(payload, kZstdLevel, file);
  return file;
}

TransferExemplar decode_exemplar(std::string_view file, std::string_view key) {
  Reader head{file};
  Header header;
  head(header);
  if (header.magic != kMagic) throw Error("not an exemplar cache file");
  if (header.version != kExemplarCacheVersion)
    throw Error("format version " + std::to_string(header.version) + ", expected " +
                std::to_string(kExemplarCacheVersion));
  std::string stored(key.size(), '\0');
  if (header.key_size == key.size()) head.bytes(stored.data(), stored.size());
  if (header.key_size != key.size() || stored != key) throw Error("stored under another key");
  const std::string payload = zstd_frame_content(file.substr(head.at));
  TransferExemplar out;
  Reader fields{payload};
  exemplar_fields(fields, out);
  if (fields.at != payload.size()) throw Error("trailing bytes");
  check_sizes(out);
  return out;
}

}  // namespace maquette::synthesis
