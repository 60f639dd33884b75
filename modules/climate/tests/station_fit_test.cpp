// The station regression on synthetic stations from known gradients (recovered exactly), zones,
// missing values, degenerate inputs, WKB zones and the artifact's JSON round trip.
#include "../station_fit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "climate_module.h"

namespace maquette::climate {
namespace {

using climate_test::error_of;

constexpr double kKmPerDegree = 6371.0088 * M_PI / 180;

// Deterministic pseudo-random numbers in [0, 1).
struct Lcg {
  uint64_t s = 12345;
  double operator()() {
    s = s * 6364136223846793005ULL + 1442695040888963407ULL;
    return double(s >> 11) / double(1ULL << 53);
  }
};

struct Truth {
  double intercept, per_km_elevation, per_km_east, per_km_north;
};

// Stations in a lon/lat box, valued by `truth` about the stations' mean position.
std::vector<Station> synthetic(int n, double west, double east, const Truth& t, uint64_t seed) {
  Lcg rng{seed};
  std::vector<Station> out;
  double lon0 = 0, lat0 = 0;
  for (int i = 0; i < n; ++i) {
    Station s;
    s.id = "s" + std::to_string(i);
    s.lon = west + (east - west) * rng();
    s.lat = 37 + 4 * rng();
    s.elevation = 1000 + 3000 * rng();
    lon0 += s.lon / n;
    lat0 += s.lat / n;
    out.push_back(s);
  }
  for (Station& s : out) {
    const double x = (s.lon - lon0) * std::cos(lat0 * M_PI / 180) * kKmPerDegree;
    const double y = (s.lat - lat0) * kKmPerDegree;
    s.values["t"] = t.intercept + t.per_km_elevation * *s.elevation / 1000 + t.per_km_east * x +
                    t.per_km_north * y;
  }
  return out;
}

Zone everything() { return {std::nullopt, "all", {}, {-180, -90, 180, 90}}; }

Zone box(int64_t fid, double w, double s, double e, double n) {
  return {fid, std::to_string(fid), {{{{w, s}, {e, s}, {e, n}, {w, n}, {w, s}}}}, {w, s, e, n}};
}

TEST(StationFit, RecoversKnownGradientsExactly) {
  const Truth t{14.5, -6.5, 0.012, -0.021};
  const auto stations = synthetic(40, -109, -102, t, 1);
  for (const Horizontal h :
       {Horizontal::None, Horizontal::WestEast, Horizontal::SouthNorth, Horizontal::Both}) {
    SCOPED_TRACE(horizontal_name(h));
    const Truth used{t.intercept, t.per_km_elevation,
                     h == Horizontal::WestEast || h == Horizontal::Both ? t.per_km_east : 0,
                     h == Horizontal::SouthNorth || h == Horizontal::Both ? t.per_km_north : 0};
    const auto exact = synthetic(40, -109, -102, used, 1);
    const StationFit fit = fit_stations(exact, {everything()}, {"t"}, h, "test");
    const ColumnFit& f = fit.fits[0].at("t");
    EXPECT_EQ(f.stations, 40);
    EXPECT_NEAR(f.per_km_elevation, used.per_km_elevation, 1e-9);
    EXPECT_NEAR(f.per_km_east, used.per_km_east, 1e-9);
    EXPECT_NEAR(f.per_km_north, used.per_km_north, 1e-9);
    EXPECT_NEAR(f.intercept, used.intercept, 1e-9);
    EXPECT_LT(f.rmse, 1e-9);
    for (const Station& s : exact)
      EXPECT_NEAR(f.predict(s.lon, s.lat, *s.elevation), s.values["t"].get<double>(), 1e-9);
  }
  // Without the horizontal terms, a field with them is fitted with residuals.
  const StationFit rough = fit_stations(stations, {everything()}, {"t"}, Horizontal::None, "t");
  EXPECT_GT(rough.fits[0].at("t").rmse, 0.1);
}

TEST(StationFit, EachZoneItsOwnRegression) {
  auto west = synthetic(30, -109, -106, {10, -5, 0, 0}, 2);
  const auto east = synthetic(30, -105.5, -102, {20, -7, 0, 0}, 3);
  west.insert(west.end(), east.begin(), east.end());
  Station far;
  far.id = "far";
  far.lon = 10;
  far.lat = 50;
  far.elevation = 100;
  far.values["t"] = 1000.0;
  west.push_back(far);
  const StationFit fit =
      fit_stations(west, {box(1, -110, 36, -105.7, 42), box(2, -105.7, 36, -101, 42)}, {"t"},
                   Horizontal::None, "test");
  EXPECT_EQ(fit.outside_zones, 1);
  EXPECT_NEAR(fit.fits[0].at("t").per_km_elevation, -5, 1e-9);
  EXPECT_NEAR(fit.fits[1].at("t").per_km_elevation, -7, 1e-9);
  EXPECT_NEAR(fit.fits[1].at("t").predict(-104, 38, 2000), 20 - 14, 1e-9);
}

TEST(StationFit, MissingValuesAreSkippedAndCounted) {
  auto stations = synthetic(20, -109, -102, {10, -6, 0, 0}, 4);
  stations[3].values["t"] = nullptr;
  stations[5].elevation.reset();
  stations[7].values.erase("t");
  const StationFit fit = fit_stations(stations, {everything()}, {"t"}, Horizontal::None, "test");
  EXPECT_EQ(fit.fits[0].at("t").stations, 17);
  EXPECT_EQ(fit.fits[0].at("t").missing, 3);
  EXPECT_NEAR(fit.fits[0].at("t").per_km_elevation, -6, 1e-9);
}

TEST(StationFit, DegenerateInputsAreErrors) {
  const auto few = synthetic(4, -109, -102, {10, -6, 0, 0}, 5);
  EXPECT_EQ(error_of([&] { fit_stations(few, {everything()}, {"t"}, Horizontal::Both, "op"); }),
            "op: zone 'all': column 't': 4 stations with a value and an elevation, the "
            "regression needs at least 5");
  auto flat = synthetic(10, -109, -102, {10, -6, 0, 0}, 6);
  for (Station& s : flat) s.elevation = 1500;
  EXPECT_NE(error_of([&] {
              fit_stations(flat, {everything()}, {"t"}, Horizontal::None, "op");
            }).find("do not determine the regression"),
            std::string::npos);
}

// Zones are fitted separately: one zone with too few stations fails the fit, naming the zone.
TEST(StationFit, ZoneWithTooFewStationsIsAnError) {
  auto stations = synthetic(20, -109, -106, {10, -6, 0, 0}, 8);
  const auto east = synthetic(2, -104, -103, {10, -6, 0, 0}, 9);
  stations.insert(stations.end(), east.begin(), east.end());
  EXPECT_EQ(error_of([&] {
              fit_stations(stations, {box(1, -110, 36, -105, 42), box(2, -105, 36, -101, 42)},
                           {"t"}, Horizontal::None, "op");
            }),
            "op: zone '2': column 't': 2 stations with a value and an elevation, the regression "
            "needs at least 3");
}

// The stations artifact as stored: null or absent values and elevations are missing; anything
// else that is not a finite number, or a position off the globe, is an error naming the station.
TEST(StationFit, StationsArtifactValues) {
  const json good = {
      {"stations",
       {{{"id", "a"}, {"lon", -105}, {"lat", 39}, {"elevation", 1500}, {"values", {{"t", 10.5}}}},
        {{"lon", -104}, {"lat", 38}, {"elevation", nullptr}, {"values", {{"t", nullptr}}}},
        {{"lon", -103}, {"lat", 37}}}}};
  const auto stations = parse_stations(good, "s");
  ASSERT_EQ(stations.size(), 3u);
  EXPECT_EQ(stations[0].id, "a");
  EXPECT_EQ(stations[1].id, "2");
  EXPECT_EQ(*station_value(stations[0], "t"), 10.5);
  EXPECT_FALSE(stations[1].elevation);
  EXPECT_FALSE(station_value(stations[1], "t"));
  EXPECT_FALSE(station_value(stations[2], "t"));

  const auto error = [&](const char* field, const json& value, int index = 0) {
    json bad = good;
    if (std::string(field) == "t")
      bad["stations"][index]["values"]["t"] = value;
    else
      bad["stations"][index][field] = value;
    return error_of([&] { parse_stations(bad, "s"); });
  };
  EXPECT_EQ(error("lat", 95), "s: station 1 ('a'): lat 95 is outside [-90, 90]");
  EXPECT_EQ(error("lon", -200.5, 1), "s: station 2: lon -200.5 is outside [-180, 180]");
  EXPECT_EQ(error("lon", "x"), "s: station 1 ('a'): no numeric 'lon'");
  EXPECT_EQ(error("elevation", "high"),
            "s: station 1 ('a'): elevation \"high\" is not a finite number or null");
  EXPECT_EQ(error("t", "NA"),
            "s: station 1 ('a'): column 't': \"NA\" is not a finite number or null");
  EXPECT_EQ(error("t", std::numeric_limits<double>::infinity()),
            "s: station 1 ('a'): column 't': inf is not a finite number or null");
}

TEST(StationFit, JsonRoundTrip) {
  const auto stations = synthetic(20, -109, -102, {10, -6, 0.01, 0.02}, 7);
  const StationFit fit =
      fit_stations(stations, {box(3, -110, 36, -101, 42)}, {"t"}, Horizontal::Both, "test");
  const StationFit back = StationFit::from_json(fit.to_json(), "fit");
  EXPECT_EQ(back.to_json(), fit.to_json());
  json wrong = fit.to_json();
  wrong["version"] = 9;
  EXPECT_EQ(error_of([&] { StationFit::from_json(wrong, "fit"); }),
            "fit: station fit version 9, this module reads version 1");
}

// WKB writer for the tests: little or big endian polygons.
struct Wkb {
  bool little = true;
  std::vector<std::byte> out;
  void byte_order() { out.push_back(std::byte(little ? 1 : 0)); }
  void put(const void* p, size_t n) {
    const auto* b = static_cast<const std::byte*>(p);
    const bool swap = little != (std::endian::native == std::endian::little);
    for (size_t i = 0; i < n; ++i) out.push_back(b[swap ? n - 1 - i : i]);
  }
  void u32(uint32_t v) { put(&v, 4); }
  void f64(double v) { put(&v, 8); }
  void polygon(const PolygonRings& rings) {
    byte_order();
    u32(3);
    u32(uint32_t(rings.size()));
    for (const auto& ring : rings) {
      u32(uint32_t(ring.size()));
      for (const LonLat& p : ring) {
        f64(p.lon);
        f64(p.lat);
      }
    }
  }
};

TEST(Zones, WkbPolygonsWithHolesAndByteOrders) {
  const PolygonRings square = {{{0, 0}, {10, 0}, {10, 10}, {0, 10}, {0, 0}},
                               {{4, 4}, {6, 4}, {6, 6}, {4, 6}, {4, 4}}};
  for (const bool little : {true, false}) {
    Wkb w{little, {}};
    w.byte_order();
    w.u32(6);
    w.u32(2);
    w.polygon(square);
    w.polygon({{{20, 0}, {30, 0}, {30, 10}, {20, 0}}});
    Zone z{7, "z", wkb_polygons(w.out, "f"), {0, 0, 30, 10}};
    ASSERT_EQ(z.polygons.size(), 2u);
    EXPECT_TRUE(zone_contains(z, {2, 2}));
    EXPECT_FALSE(zone_contains(z, {5, 5}));  // in the hole
    EXPECT_TRUE(zone_contains(z, {29, 1}));
    EXPECT_FALSE(zone_contains(z, {21, 9}));
  }
  Wkb point;
  point.byte_order();
  point.u32(1);
  point.f64(1);
  point.f64(2);
  EXPECT_EQ(error_of([&] { wkb_polygons(point.out, "zones: feature 3"); }),
            "zones: feature 3 is a Point, not a polygon");
  point.out.resize(3);
  EXPECT_EQ(error_of([&] { wkb_polygons(point.out, "f"); }), "f has truncated WKB");
}

}  // namespace
}  // namespace maquette::climate
