// core/enu_frame.h against PROJ's east-north-up coordinates (tests/support/proj_enu.h: cart +
// topocentric), an independent implementation: points up to 20 km from origins at the equator,
// mid latitudes, near a pole, across the antimeridian, above and below the ellipsoid.
#include "core/enu_frame.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "proj_enu.h"

namespace maquette {
namespace {

const std::vector<GeodeticPoint> kOrigins = {
    {0, 0, 0}, {-0.134, 51.513, 35.5}, {7.6, 89.7, -20}, {179.95, -16.8, 1200}};

// Points around `o`: up to ~0.18 degree of latitude (20 km) away, across the antimeridian from an
// origin near it, heights from 50 m below the ellipsoid to 3 km above.
std::vector<GeodeticPoint> around(const GeodeticPoint& o) {
  std::vector<GeodeticPoint> out;
  for (const double dlon : {-0.18, -0.01, 0.0, 0.07, 0.18})
    for (const double dlat : {-0.18, 0.0, 0.05, 0.18})
      for (const double h : {-50.0, 0.0, 3000.0})
        if (std::abs(o.lat + dlat) <= 90) out.push_back({o.lon + dlon, o.lat + dlat, h});
  return out;
}

TEST(EnuFrame, MatchesProjsTopocentricCoordinates) {
  for (const GeodeticPoint& o : kOrigins) {
    const EnuFrame frame(o);
    const test::ProjEnu proj(o.lon, o.lat, o.height);
    for (const GeodeticPoint& p : around(o)) {
      const std::array<double, 3> got = frame.to_enu(p.lon, p.lat, p.height);
      const std::array<double, 3> expected = proj({p.lon, p.lat}, p.height);
      for (int i = 0; i < 3; ++i)
        EXPECT_NEAR(got[i], expected[i], 1e-6)
            << "origin " << o.lon << " " << o.lat << ", point " << p.lon << " " << p.lat << " "
            << p.height << ", axis " << i;
    }
  }
}

TEST(EnuFrame, GeodeticCoordinatesAreTheForwardsInverse) {
  for (const GeodeticPoint& o : kOrigins) {
    const EnuFrame frame(o);
    const test::ProjEnu proj(o.lon, o.lat, o.height);
    for (const GeodeticPoint& p : around(o)) {
      // From PROJ's coordinates of p, so a mistake shared by both ways would not cancel.
      const std::array<double, 3> xyz = proj({p.lon, p.lat}, p.height);
      const GeodeticPoint back = frame.to_geodetic(xyz[0], xyz[1], xyz[2]);
      EXPECT_NEAR(std::remainder(back.lon - p.lon, 360.0), 0, 1e-10) << p.lon << " " << p.lat;
      EXPECT_NEAR(back.lat, p.lat, 1e-10) << p.lon << " " << p.lat;
      EXPECT_NEAR(back.height, p.height, 1e-6) << p.lon << " " << p.lat;
    }
  }
}

TEST(EnuFrame, AxesAreThePointsOwnEastNorthUpInTheFrame) {
  // Column j of the axes: the frame's displacement of a small step along the point's axis j, by
  // PROJ (1 m up; 1e-5 degree east and north, scaled to a unit vector).
  for (const GeodeticPoint& o : kOrigins) {
    const EnuFrame frame(o);
    const test::ProjEnu proj(o.lon, o.lat, o.height);
    for (const GeodeticPoint& p : around(o)) {
      if (std::abs(p.lat) > 89.9) continue;  // east and north steps degenerate near the pole
      std::array<double, 9> axes{};
      const std::array<double, 3> at = frame.to_enu(p.lon, p.lat, p.height, axes);
      EXPECT_EQ(at, frame.to_enu(p.lon, p.lat, p.height));
      const std::array<double, 3> base = proj({p.lon, p.lat}, p.height);
      const std::array<std::array<double, 3>, 3> moved = {proj({p.lon + 1e-5, p.lat}, p.height),
                                                          proj({p.lon, p.lat + 1e-5}, p.height),
                                                          proj({p.lon, p.lat}, p.height + 1)};
      for (int j = 0; j < 3; ++j) {
        const std::array<double, 3> d = {moved[j][0] - base[0], moved[j][1] - base[1],
                                         moved[j][2] - base[2]};
        const double length = std::hypot(d[0], d[1], d[2]);
        for (int i = 0; i < 3; ++i)
          EXPECT_NEAR(axes[3 * i + j], d[i] / length, 1e-5)
              << "point " << p.lon << " " << p.lat << ", axis " << j << ", row " << i;
      }
    }
  }
}

// Copies share the frame: a copy outlives its source and gives the bits of a frame set up anew.
TEST(EnuFrame, CopyOutlivesItsSource) {
  const GeodeticPoint origin{-0.134, 51.513, 35.5};
  auto source = std::make_unique<EnuFrame>(origin);
  const EnuFrame copy = *source;
  source.reset();
  const EnuFrame fresh(origin);
  EXPECT_EQ(copy.to_enu(-0.13, 51.52, 40), fresh.to_enu(-0.13, 51.52, 40));
  EXPECT_EQ(copy.to_geodetic(100, -250, 3), fresh.to_geodetic(100, -250, 3));
}

}  // namespace
}  // namespace maquette
