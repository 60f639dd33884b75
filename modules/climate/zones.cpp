#include "zones.h"

#include <bit>
#include <cstring>

#include "core/error.h"

namespace maquette::climate {
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

bool ring_crossings(const std::vector<LonLat>& ring, LonLat p) {
  bool inside = false;
  for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    const LonLat a = ring[i], b = ring[j];
    if ((a.lat > p.lat) != (b.lat > p.lat) &&
        p.lon < (b.lon - a.lon) * (p.lat - a.lat) / (b.lat - a.lat) + a.lon)
      inside = !inside;
  }
  return inside;
}

}  // namespace

std::vector<PolygonRings> wkb_polygons(std::span<const std::byte> wkb, const std::string& where) {
  return WkbReader(wkb, where).geometry();
}

bool zone_contains(const Zone& zone, LonLat p) {
  if (!zone.fid) return true;
  if (p.lon < zone.bbox[0] || p.lat < zone.bbox[1] || p.lon > zone.bbox[2] || p.lat > zone.bbox[3])
    return false;
  for (const PolygonRings& poly : zone.polygons) {
    bool inside = false;
    for (const auto& ring : poly)
      if (!ring.empty() && ring_crossings(ring, p)) inside = !inside;
    if (inside) return true;
  }
  return false;
}

int zone_of(const std::vector<Zone>& zones, LonLat p) {
  for (size_t i = 0; i < zones.size(); ++i)
    if (zone_contains(zones[i], p)) return int(i);
  return -1;
}

nlohmann::json zone_to_json(const Zone& zone) {
  nlohmann::json polygons = nlohmann::json::array();
  for (const PolygonRings& poly : zone.polygons) {
    nlohmann::json rings = nlohmann::json::array();
    for (const auto& ring : poly) {
      nlohmann::json points = nlohmann::json::array();
      for (const LonLat& p : ring) points.push_back({p.lon, p.lat});
      rings.push_back(std::move(points));
    }
    polygons.push_back(std::move(rings));
  }
  return {{"fid", zone.fid ? nlohmann::json(*zone.fid) : nlohmann::json(nullptr)},
          {"name", zone.name},
          {"bbox", zone.bbox},
          {"polygons", std::move(polygons)}};
}

Zone zone_from_json(const nlohmann::json& j) {
  Zone z;
  if (!j.at("fid").is_null()) z.fid = j.at("fid").get<int64_t>();
  z.name = j.at("name").get<std::string>();
  z.bbox = j.at("bbox").get<std::array<double, 4>>();
  for (const auto& rings : j.at("polygons")) {
    PolygonRings poly;
    for (const auto& ring : rings) {
      std::vector<LonLat> points;
      for (const auto& p : ring) points.push_back({p[0].get<double>(), p[1].get<double>()});
      poly.push_back(std::move(points));
    }
    z.polygons.push_back(std::move(poly));
  }
  return z;
}

}  // namespace maquette::climate
