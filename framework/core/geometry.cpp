#include "core/geometry.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "core/error.h"

namespace maquette {
namespace {

// WKB type codes 1..7.
constexpr const char* kWkbTypeNames[] = {
    "Geometry",   "Point",           "LineString",   "Polygon",
    "MultiPoint", "MultiLineString", "MultiPolygon", "GeometryCollection"};

class WkbReader {
 public:
  WkbReader(std::span<const std::byte> data, const std::string& where)
      : data_(data), where_(where) {}

  Geometry read() {
    const Header h = header();
    Geometry g;
    g.has_z = h.has_z;
    if (h.type >= 1 && h.type <= 3) {
      g.type = GeometryType(h.type - 1);
      append(g, h);
      return g;
    }
    if (h.type >= 4 && h.type <= 6) {
      g.type = GeometryType(h.type - 1);
      for (uint32_t n = u32(), i = 0; i < n; ++i) {
        const Header part = header();
        if (part.type != h.type - 3)
          fail("has a " + std::string(kWkbTypeNames[h.type]) + " part that is a " +
               type_name(part.type));
        append(g, part);
      }
      return g;
    }
    fail("is a " + type_name(h.type) +
         ", not a Point, LineString, Polygon or one of their Multi* forms");
  }

 private:
  struct Header {
    uint32_t type = 0;  // 1..7
    int dims = 2;
    bool has_z = false;
  };

  Header header() {
    little_ = byte() == std::byte{1};
    const uint32_t raw = u32();
    // ISO (1000s: Z, 2000s: M, 3000s: ZM) and EWKB (high bits: Z 0x80000000, M 0x40000000).
    Header h;
    h.type = raw & 0x0FFFFFFF;
    h.has_z = (raw & 0x80000000u) != 0;
    const bool has_m = (raw & 0x40000000u) != 0;
    if (h.type >= 1000) {
      h.has_z = h.type / 1000 == 1 || h.type / 1000 == 3;
      h.dims = h.type / 1000 == 3 ? 4 : 3;
      h.type %= 1000;
    } else {
      h.dims = 2 + (h.has_z ? 1 : 0) + (has_m ? 1 : 0);
    }
    return h;
  }

  void append(Geometry& g, const Header& h) {
    if (h.type == 1) g.points.push_back(point(h));
    if (h.type == 2) g.lines.push_back(path(h));
    if (h.type == 3) {
      GeoPolygon polygon;
      const uint32_t rings = u32();
      need(size_t(rings) * 4);  // each ring's count at least: no allocation from a claimed size
      polygon.rings.resize(rings);
      for (GeoPath& ring : polygon.rings) ring = path(h);
      g.polygons.push_back(std::move(polygon));
    }
  }

  GeoPath path(const Header& h) {
    const uint32_t points = u32();
    need(size_t(points) * 8 * size_t(h.dims));  // the points' bytes, before allocating for them
    GeoPath p(points);
    for (GeoPoint& q : p) q = point(h);
    return p;
  }

  GeoPoint point(const Header& h) {
    GeoPoint p;
    p.lon = f64();
    p.lat = f64();
    if (h.dims >= 3) {
      const double third = f64();
      if (h.has_z) p.z = third;  // XYM: the third is M
    }
    if (h.dims == 4) f64();  // M
    // Ingest stores finite coordinates only; NaN would reach the callers' arithmetic unchecked.
    if (!std::isfinite(p.lon) || !std::isfinite(p.lat) || (h.has_z && !std::isfinite(p.z)))
      fail("has a coordinate that is not finite");
    // Stored geometries are lon/lat (ingest transforms them to WGS84); callers' geodesy turns a
    // latitude beyond a pole into NaN.
    if (std::abs(p.lat) > 90) fail("has a latitude of " + std::to_string(p.lat) + " degrees");
    return p;
  }

  std::string type_name(uint32_t type) const {
    return type < 8 ? kWkbTypeNames[type] : "geometry of WKB type " + std::to_string(type);
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

std::string_view geometry_type_name(GeometryType type) { return kWkbTypeNames[int(type) + 1]; }

Geometry parse_wkb(std::span<const std::byte> wkb, const std::string& where) {
  return WkbReader(wkb, where).read();
}

}  // namespace maquette
