#include "core/wkb_polygons.h"

#include <bit>
#include <cstdint>
#include <cstring>

#include "core/error.h"

namespace maquette {
namespace {

class WkbReader {
 public:
  WkbReader(std::span<const std::byte> data, const std::string& where)
      : data_(data), where_(where) {}

  std::vector<PolygonRings> geometry() {
    little_ = byte() == std::byte{1};
    const uint32_t raw = u32();
    // ISO (1000s: Z, 2000s: M, 3000s: ZM) and EWKB (high bits) dimension flags.
    uint32_t type = raw & 0x0FFFFFFF;
    int dims = 2 + ((raw & 0x80000000u) ? 1 : 0) + ((raw & 0x40000000u) ? 1 : 0);
    if (type >= 1000) {
      dims = type >= 3000 ? 4 : 3;
      type %= 1000;
    }
    if (type == 3) return {polygon(dims)};
    if (type == 6) {
      std::vector<PolygonRings> out;
      for (uint32_t n = u32(), i = 0; i < n; ++i) {
        auto part = geometry();
        if (part.size() != 1) fail("has a MultiPolygon part that is not a polygon");
        out.push_back(std::move(part.front()));
      }
      return out;
    }
    static const char* const names[] = {
        "Geometry",   "Point",           "LineString",   "Polygon",
        "MultiPoint", "MultiLineString", "MultiPolygon", "GeometryCollection"};
    fail(std::string("is a ") +
         (type < 8 ? names[type] : "geometry of WKB type " + std::to_string(type)) +
         ", not a polygon");
    return {};
  }

 private:
  PolygonRings polygon(int dims) {
    PolygonRings rings(u32());
    for (auto& ring : rings) {
      ring.resize(u32());
      for (LonLat& p : ring) {
        p.lon = f64();
        p.lat = f64();
        for (int d = 2; d < dims; ++d) f64();
      }
    }
    return rings;
  }

  std::byte byte() {
    need(1);
    return data_[pos_++];
  }
  uint32_t u32() {
    need(4);
    uint32_t v;
    std::memcpy(&v, data_.data() + pos_, 4);
    pos_ += 4;
    return little_ == (std::endian::native == std::endian::little) ? v : __builtin_bswap32(v);
  }
  double f64() {
    need(8);
    uint64_t v;
    std::memcpy(&v, data_.data() + pos_, 8);
    pos_ += 8;
    if (little_ != (std::endian::native == std::endian::little)) v = __builtin_bswap64(v);
    return std::bit_cast<double>(v);
  }
  void need(size_t n) const {
    if (pos_ + n > data_.size()) fail("has truncated WKB");
  }
  [[noreturn]] void fail(const std::string& what) const { throw Error(where_ + " " + what); }

  std::span<const std::byte> data_;
  std::string where_;
  size_t pos_ = 0;
  bool little_ = true;
};

}  // namespace

std::vector<PolygonRings> wkb_polygons(std::span<const std::byte> wkb, const std::string& where) {
  return WkbReader(wkb, where).geometry();
}

}  // namespace maquette
