// Terrain Bender's progressive bending (formats/render/progressive_bend.h) against the geometry it
// states: the base plane beyond the start rolled onto the circle tangent to it there (each point at
// its arc length from the tangent point), raised points kept at their height along the circle's
// normal, nearer points and an infinite radius left bit for bit; and its effect on a flat plain
// rasterized from a camera: the horizon (the first terrain row from the top in each column) rises
// as the radius shrinks, never falls.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "core/error.h"
#include "render/progressive_bend.h"
#include "render/rasterizer.h"

namespace maquette {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(ProgressiveBend, RollsTheBasePlaneOntoItsCircle) {
  const ProgressiveBend bend{20000, 5000, -1200};
  const double heading = 0.7;  // radians from north: any direction from the eye
  const double ce = std::sin(heading), cn = std::cos(heading);
  for (const double d : {5000.5, 6000.0, 15000.0, 30000.0, 45000.0, 60000.0})
    for (const double h : {0.0, 350.0}) {
      std::vector<double> p{d * ce, d * cn, bend.base + h};
      bend_positions(p, bend);
      // Still in the vertical plane through the eye and the original point.
      EXPECT_NEAR(p[0] * cn - p[1] * ce, 0, 1e-9 * d);
      // In that plane: s along the ground from the eye, z above the base plane; the circle's
      // centre is radius above the tangent point at s = start.
      const double s = p[0] * ce + p[1] * cn, z = p[2] - bend.base;
      const double ds = s - bend.start, dz = z - bend.radius;
      EXPECT_NEAR(std::hypot(ds, dz), bend.radius - h, 1e-6) << d << " " << h;
      // The angle swept from the tangent point (straight below the centre) is the arc length
      // on the circle over its radius.
      const double swept = std::atan2(ds, -dz);
      EXPECT_NEAR(swept * bend.radius, d - bend.start, 1e-6) << d << " " << h;
    }
  // Within the start, and anywhere with an infinite radius: untouched, bit for bit.
  const std::vector<double> near{3000, 4000, -1200, -100, 20, 300};
  std::vector<double> p = near;
  bend_positions(p, bend);
  EXPECT_EQ(p, near);
  const std::vector<double> far{30000, 40000, -1200, -100000, 20, 300};
  p = far;
  bend_positions(p, ProgressiveBend{kInf, 5000, -1200});
  EXPECT_EQ(p, far);
}

TEST(ProgressiveBend, OutOfRangeIsNamed) {
  EXPECT_NO_THROW(check_bend({kInf, 0, 0}));
  for (const double radius : {0.0, -5.0, std::nan("")})
    EXPECT_THROW(check_bend({radius, 0, 0}), Error);
  for (const double start : {-1.0, kInf, std::nan("")})
    EXPECT_THROW(check_bend({1000, start, 0}), Error);
  try {
    check_bend({-5, 0, 0});
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("--bend-radius -5"), std::string::npos) << e.what();
  }
}

// A flat plain 1000 m below the eye, 80 km ahead by 100 km wide, in 500 m squares.
RenderMesh plain() {
  RenderMesh m;
  const int nx = 200, ny = 162;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i)
      m.positions.insert(m.positions.end(), {-50000 + 500.0 * i, -1000 + 500.0 * j, -1000});
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const auto a = uint32_t(j * (nx + 1) + i), b = a + 1, c = a + uint32_t(nx + 1), d = c + 1;
      m.indices.insert(m.indices.end(), {a, b, d, a, d, c});
    }
  return m;
}

// The first terrain row from the top in each column (height where a column is all sky).
std::vector<int> horizon(const Fragments& f) {
  std::vector<int> rows(size_t(f.width), f.height);
  for (int col = 0; col < f.width; ++col)
    for (int row = 0; row < f.height; ++row)
      if (f.triangle[size_t(row) * size_t(f.width) + size_t(col)] != Fragments::kSky) {
        rows[size_t(col)] = row;
        break;
      }
  return rows;
}

TEST(ProgressiveBend, HorizonRisesAsTheRadiusShrinks) {
  CameraSpec spec;
  spec.eye = {8.5, 46.5, 3000};
  spec.pitch = -4;
  spec.fov = 50;
  spec.width = 240;
  spec.height = 160;
  const PinholeCamera camera(spec);
  std::vector<int> before;
  double mean_before = 0;
  for (const double radius : {kInf, 1e6, 400000.0, 200000.0, 150000.0}) {
    RenderMesh mesh = plain();
    bend_positions(mesh.positions, {radius, 4000, -1000});
    const std::vector<int> rows = horizon(rasterize(mesh, camera));
    double mean = 0;
    for (const int r : rows) {
      EXPECT_LT(r, spec.height) << radius;  // the plain reaches every column
      mean += r / double(rows.size());
    }
    if (!before.empty()) {
      for (size_t c = 0; c < rows.size(); ++c) EXPECT_LE(rows[c], before[c]) << radius << " " << c;
      EXPECT_LT(mean, mean_before - 2) << radius;  // and it does rise
    }
    before = rows;
    mean_before = mean;
  }
}

}  // namespace
}  // namespace maquette
