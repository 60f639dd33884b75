// The rasterizer (formats/render/rasterizer.h) on a box standing on a plane, seen obliquely:
// the box's top corners where OpenCV's projectPoints puts them, every pixel's surface point the
// one a ray caster written here finds, the same bits for 1 and 2 threads.
#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <opencv2/calib3d.hpp>

#include "core/error.h"
#include "render/rasterizer.h"
#include "test_camera.h"

namespace maquette {
namespace {

using V3 = std::array<double, 3>;

// A 300 x 300 x 200 m box whose top is 100 m below the eye, on a 4 x 4 km plane 300 m below it
// that reaches behind the eye (its triangles cut by the near plane); triangles 0-1 the plane, 2-3
// the box's top, then its four sides.
RenderMesh box_on_plane() {
  RenderMesh m;
  auto vertex = [&m](double x, double y, double z) {
    m.positions.insert(m.positions.end(), {x, y, z});
    return uint32_t(m.positions.size() / 3 - 1);
  };
  auto quad = [&m](uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
    m.indices.insert(m.indices.end(), {a, b, c, a, c, d});
  };
  quad(vertex(-2000, -500, -300), vertex(2000, -500, -300), vertex(2000, 3500, -300),
       vertex(-2000, 3500, -300));
  const double x0 = -50, x1 = 250, y0 = 800, y1 = 1100, z0 = -300, z1 = -100;
  uint32_t top[4] = {vertex(x0, y0, z1), vertex(x1, y0, z1), vertex(x1, y1, z1),
                     vertex(x0, y1, z1)};
  uint32_t bottom[4] = {vertex(x0, y0, z0), vertex(x1, y0, z0), vertex(x1, y1, z0),
                        vertex(x0, y1, z0)};
  quad(top[0], top[1], top[2], top[3]);
  for (int k = 0; k < 4; ++k) quad(bottom[k], bottom[(k + 1) % 4], top[(k + 1) % 4], top[k]);
  return m;
}

struct Scene {
  CameraSpec spec;
  test::TestCamera oracle;
  RenderMesh mesh = box_on_plane();
  Scene() {
    spec.eye = {-112.95, 37.25, 2000};
    spec.heading = 20;
    spec.pitch = -12;
    spec.fov = 55;
    spec.width = 400;
    spec.height = 300;
    oracle = {spec.heading, spec.pitch, spec.fov, spec.width, spec.height};
  }
  V3 vertex(uint32_t i) const {
    return {mesh.positions[3 * i], mesh.positions[3 * i + 1], mesh.positions[3 * i + 2]};
  }
  // The point a fragment names on its triangle.
  V3 surface_point(const Fragments& f, size_t i) const {
    const uint32_t* v = &mesh.indices[3 * size_t(f.triangle[i])];
    const double b[3] = {1.0 - f.b1[i] - f.b2[i], f.b1[i], f.b2[i]};
    V3 p{};
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) p[k] += b[j] * vertex(v[j])[k];
    return p;
  }
};

// The nearest intersection of the ray from the origin along `d` with the mesh (Moller-Trumbore),
// or nullopt.
std::optional<V3> cast(const RenderMesh& m, const V3& d) {
  auto sub = [](const V3& a, const V3& b) { return V3{a[0] - b[0], a[1] - b[1], a[2] - b[2]}; };
  auto cross = [](const V3& a, const V3& b) {
    return V3{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  };
  auto dot = [](const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
  double best = std::numeric_limits<double>::infinity();
  for (size_t t = 0; t < m.triangle_count(); ++t) {
    V3 p[3];
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) p[j][k] = m.positions[3 * m.indices[3 * t + j] + k];
    const V3 e1 = sub(p[1], p[0]), e2 = sub(p[2], p[0]), q = cross(d, e2);
    const double det = dot(e1, q);
    if (std::abs(det) < 1e-12) continue;
    const V3 s = sub({0, 0, 0}, p[0]);
    const double u = dot(s, q) / det;
    const V3 r = cross(s, e1);
    const double v = dot(d, r) / det, t_hit = dot(e2, r) / det;
    if (u < 0 || v < 0 || u + v > 1 || t_hit <= 0) continue;
    best = std::min(best, t_hit);
  }
  if (std::isinf(best)) return std::nullopt;
  return V3{d[0] * best, d[1] * best, d[2] * best};
}

TEST(Rasterize, BoxTopWhereOpenCvProjectsItsCorners) {
  const Scene s;
  const Fragments f = rasterize(s.mesh, PinholeCamera(s.spec));
  std::vector<cv::Point3d> corners;
  for (uint32_t v = 4; v < 8; ++v)
    corners.emplace_back(s.vertex(v)[0], s.vertex(v)[1], s.vertex(v)[2]);
  const auto rot = s.oracle.rotation();
  cv::Mat r(3, 3, CV_64F), rvec;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r.at<double>(i, j) = rot[i][j];
  cv::Rodrigues(r, rvec);
  const cv::Matx33d k(s.oracle.focal(), 0, s.oracle.cx(), 0, s.oracle.focal(), s.oracle.cy(), 0, 0,
                      1);
  std::vector<cv::Point2d> quad;
  cv::projectPoints(corners, rvec, cv::Vec3d(0, 0, 0), k, cv::noArray(), quad);
  // The top face (triangles 2, 3) is wholly visible: on every row, its pixels run between the
  // projected quadrilateral's edges (pixel centres at integers, OpenCV's convention).
  int rows = 0;
  for (int row = 0; row < f.height; ++row) {
    double left = 1e9, right = -1e9;
    for (size_t e = 0; e < 4; ++e) {
      const cv::Point2d a = quad[e], b = quad[(e + 1) % 4];
      if ((a.y - row) * (b.y - row) > 0 || a.y == b.y) continue;
      const double x = a.x + (b.x - a.x) * (row - a.y) / (b.y - a.y);
      left = std::min(left, x), right = std::max(right, x);
    }
    int first = -1, last = -1;
    for (int col = 0; col < f.width; ++col) {
      const uint32_t t = f.triangle[size_t(row) * size_t(f.width) + size_t(col)];
      if (t != 2 && t != 3) continue;
      if (first < 0) first = col;
      last = col;
    }
    if (right - left < 2) continue;  // thinner rows may hold no pixel centre
    ASSERT_GE(first, 0) << "row " << row << " spans " << left << " .. " << right;
    EXPECT_NEAR(first, left, 1.0) << "row " << row;
    EXPECT_NEAR(last, right, 1.0) << "row " << row;
    ++rows;
  }
  EXPECT_GT(rows, 10);  // the box is large enough for the check to mean something
}

TEST(Rasterize, EveryPixelSeesWhatARayCasterSees) {
  const Scene s;
  const Fragments f = rasterize(s.mesh, PinholeCamera(s.spec));
  size_t same = 0, sky = 0, box = 0;
  for (int r = 0; r < f.height; ++r)
    for (int c = 0; c < f.width; ++c) {
      const size_t i = size_t(r) * size_t(f.width) + size_t(c);
      const auto hit = cast(s.mesh, s.oracle.ray(c, r));
      if (!hit || f.triangle[i] == Fragments::kSky) {
        same += !hit && f.triangle[i] == Fragments::kSky;
        sky += !hit;
        continue;
      }
      box += f.triangle[i] >= 2;
      const V3 p = s.surface_point(f, i);
      const double range =
          std::sqrt((*hit)[0] * (*hit)[0] + (*hit)[1] * (*hit)[1] + (*hit)[2] * (*hit)[2]);
      const double error = std::hypot(p[0] - (*hit)[0], p[1] - (*hit)[1], p[2] - (*hit)[2]);
      same += error <= 1e-3 * range;
    }
  const size_t n = f.triangle.size();
  EXPECT_GE(double(same) / double(n), 0.995) << same << " of " << n;
  EXPECT_GT(sky, n / 10);  // the sky above the plane's far edge, the box and the plane all seen
  EXPECT_GT(box, n / 100);
}

TEST(Rasterize, SameBitsForOneAndTwoThreads) {
  const Scene s;
  const PinholeCamera camera(s.spec);
  Fragments one, two;
  tbb::task_arena(1).execute([&] { one = rasterize(s.mesh, camera); });
  tbb::task_arena(2).execute([&] { two = rasterize(s.mesh, camera); });
  EXPECT_EQ(one.triangle, two.triangle);
  EXPECT_EQ(0, std::memcmp(one.depth.data(), two.depth.data(), one.depth.size() * sizeof(double)));
  EXPECT_EQ(one.b1, two.b1);
  EXPECT_EQ(one.b2, two.b2);
}

TEST(Rasterize, StripsIntoOneReusedFragmentsAreTheWholePicturesRows) {
  // A picture's strips drawn one after the other into the same Fragments (render_strips): each
  // the whole picture's rows, though the arrays hold the previous strip's values (here
  // overwritten with values no pixel gets, so a pixel left unwritten shows; the sky is in the top
  // rows, drawn after the bottom ones), and the largest strip, drawn first, sizes the arrays for
  // the others (no allocation after it).
  const Scene s;
  const PinholeCamera camera(s.spec);
  const Fragments whole = rasterize(s.mesh, camera);
  const int h = s.spec.height, w = s.spec.width;
  const RasterPlan plan(s.mesh, camera);
  Fragments f;
  const uint32_t* storage = nullptr;
  for (const auto& [first, rows] : {std::pair{150, 150}, std::pair{0, 150}, std::pair{60, 100}}) {
    std::fill(f.triangle.begin(), f.triangle.end(), 7u);
    std::fill(f.depth.begin(), f.depth.end(), -1.0);
    std::fill(f.b1.begin(), f.b1.end(), 2.0f);
    std::fill(f.b2.begin(), f.b2.end(), 2.0f);
    rasterize(plan, first, rows, f);
    if (!storage) storage = f.triangle.data();
    EXPECT_EQ(storage, f.triangle.data()) << "rows from " << first;
    ASSERT_EQ(f.first_row, first);
    ASSERT_EQ(f.height, std::min(rows, h - first));
    const size_t skip = size_t(first) * size_t(w), m = size_t(f.height) * size_t(w);
    ASSERT_EQ(f.triangle.size(), m);
    EXPECT_TRUE(std::equal(f.triangle.begin(), f.triangle.end(), whole.triangle.begin() + skip))
        << "rows from " << first;
    EXPECT_EQ(0, std::memcmp(f.depth.data(), &whole.depth[skip], m * sizeof(double)));
    EXPECT_EQ(0, std::memcmp(f.b1.data(), &whole.b1[skip], m * sizeof(float)));
    EXPECT_EQ(0, std::memcmp(f.b2.data(), &whole.b2[skip], m * sizeof(float)));
  }
}

TEST(Rasterize, SharedEdgesDrawNoPixelTwice) {
  // A fan of 16 thin triangles around a point in the picture: the top-left rule gives each pixel
  // centre inside the fan to exactly one triangle, so their pixel counts add up to the fan's.
  Scene s;
  RenderMesh fan;
  fan.positions = {0, 1000, 0};
  for (int k = 0; k < 16; ++k) {
    const double a = k * std::numbers::pi / 8;
    fan.positions.insert(fan.positions.end(), {300 * std::cos(a), 1000, 300 * std::sin(a)});
    fan.indices.insert(fan.indices.end(), {0, uint32_t(1 + k), uint32_t(1 + (k + 1) % 16)});
  }
  s.spec.pitch = 0;
  s.spec.heading = 0;
  const PinholeCamera camera(s.spec);
  const Fragments all = rasterize(fan, camera);
  size_t drawn = 0;
  for (const uint32_t t : all.triangle) drawn += t != Fragments::kSky;
  size_t sum = 0;
  for (int k = 0; k < 16; ++k) {
    RenderMesh one = fan;
    one.indices.assign(fan.indices.begin() + 3 * k, fan.indices.begin() + 3 * k + 3);
    for (const uint32_t t : rasterize(one, camera).triangle) sum += t != Fragments::kSky;
  }
  EXPECT_EQ(sum, drawn);
  EXPECT_GT(drawn, 1000u);
  // And at least one: every pixel centre strictly inside the fan's rim (its corners projected and
  // snapped to 1/16 px as the rasterizer snaps them) is drawn, none outside it (a centre on the
  // rim may go either way).
  std::vector<std::array<double, 2>> rim;
  for (int k = 1; k <= 16; ++k) {
    const auto px = camera.to_pixel(
        camera.to_view({fan.positions[3 * size_t(k)], fan.positions[3 * size_t(k) + 1],
                        fan.positions[3 * size_t(k) + 2]}));
    rim.push_back({std::round(px[0] * 16) / 16, std::round(px[1] * 16) / 16});
  }
  // Pixel centres whose signed distance to every rim edge (positive on the side `sign` says)
  // exceeds `margin`.
  const auto centres = [&](double sign, double margin) {
    size_t count = 0;
    for (int row = 0; row < s.spec.height; ++row)
      for (int col = 0; col < s.spec.width; ++col) {
        double least = INFINITY;
        for (size_t k = 0; k < rim.size(); ++k) {
          const auto& a = rim[k];
          const auto& b = rim[(k + 1) % rim.size()];
          const double ex = b[0] - a[0], ey = b[1] - a[1];
          const double cross = ex * (row + 0.5 - a[1]) - ey * (col + 0.5 - a[0]);
          least = std::min(least, sign * cross / std::hypot(ex, ey));
        }
        count += least > margin;
      }
    return count;
  };
  // The rim's winding as projected decides which side is inside.
  const double sign = centres(1, 1e-9) > 0 ? 1 : -1;
  const size_t inside = centres(sign, 1e-9), on_or_inside = centres(sign, -1e-9);
  EXPECT_GT(inside, 1000u);
  EXPECT_GE(drawn, inside);
  EXPECT_LE(drawn, on_or_inside);
}

TEST(Camera, OutOfRangeFieldsAreNamed) {
  CameraSpec spec;
  for (const double fov : {0.0, -5.0, 171.0, std::nan("")}) {
    spec.fov = fov;
    try {
      PinholeCamera camera(spec);
      ADD_FAILURE() << "fov " << fov << " accepted";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("fov"), std::string::npos) << e.what();
    }
  }
  spec.fov = 60;
  spec.pitch = -91;
  EXPECT_THROW(PinholeCamera{spec}, Error);
  spec.pitch = 0;
  spec.width = 0;
  EXPECT_THROW(PinholeCamera{spec}, Error);
}

}  // namespace
}  // namespace maquette
