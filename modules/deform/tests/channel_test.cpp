// deform.features on a region mosaic of the real grid (rHEALPix, 256 samples of ~1.2 m near
// Zion): a straight trapezoidal channel cut into a plane and into a sinusoidal surface, compared
// with its closed form (control curve: surface - depth along the line; cross section: that
// elevation plus the trapezoid's dz at the offset), heights outside the field of influence
// bit-identical to the input, the same bits on two tilings of the region, and the errors of
// strokes that leave the DEM, cross nodata or cross themselves.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <numbers>

#include "../mosaic_frame.h"
#include "core/error.h"
#include "core/halo.h"
#include "run_features.h"
#include "sample_surface.h"
#include "tangent_plane.h"

namespace maquette::deform {
namespace {

constexpr int kCellLevel = 15, kTile = 256, kPixelLevel = kCellLevel + 8;
const CellId kCell = default_grid().cell_from_point({-113.0, 37.2}, kCellLevel);
const LonLat kSite = default_grid().centre(kCell);  // the tangent plane's origin
constexpr double kDepth = 5, kBottom = 6, kTop = 20, kLength = 150;
constexpr double kHeading = 30 * std::numbers::pi / 180;  // of the channel, from east

using Surface = std::function<double(double east, double north)>;

struct Fixture : TangentPlane {
  Fixture() : TangentPlane(kSite) {}

  Surface surface;
  double e0 = -40, n0 = -30;  // the channel's start (m from the site)

  double curve_z(double s) const {
    return surface(e0 + s * std::cos(kHeading), n0 + s * std::sin(kHeading)) - kDepth;
  }
  static double trapezoid(double o) {
    const double a = std::abs(o);
    return a <= kBottom ? 0 : kDepth * std::min(1.0, (a - kBottom) / (kTop - kBottom));
  }
  // The mosaic of `extra` samples more on each side than the site's cell.
  Mosaic dem(int extra) const {
    const CellId cell = kCell;
    Mosaic m;
    m.face = cell.face();
    m.level = kPixelLevel;
    m.origin_col = int64_t(cell.col()) * kTile - extra;
    m.origin_row = int64_t(cell.row()) * kTile - extra;
    const int size = kTile + 2 * extra;
    Tile<float> t(size, 1);
    for (int r = 0; r < size; ++r)
      for (int c = 0; c < size; ++c) {
        const auto p = local(pixel_centre(
            default_grid(), {m.face, m.origin_col + c, m.origin_row + r}, kPixelLevel));
        t.at(c, r) = float(surface(p[0], p[1]));
      }
    m.layers.emplace("dem", std::move(t));
    return m;
  }
  VectorFeature channel() const {
    VectorFeature f;
    f.id = 1;
    f.geometry.type = GeometryType::LineString;
    const LonLat a = lonlat(e0, n0);
    const LonLat b = lonlat(e0 + kLength * std::cos(kHeading), n0 + kLength * std::sin(kHeading));
    f.geometry.lines = {{{a.lon, a.lat}, {b.lon, b.lat}}};
    nlohmann::json profile = nlohmann::json::array();
    for (double s = 0; s <= kLength + 0.25; s += 0.5) profile.push_back({s, curve_z(s)});
    f.attributes = {
        {"tool", "feature"},
        {"profile", profile},
        {"cross_section", {{-kTop, kDepth}, {-kBottom, 0}, {kBottom, 0}, {kTop, kDepth}}}};
    return f;
  }
};

struct Errors {
  double control_rms = 0, section_rms = 0;
};

// A base sample and a half (samples of ~1.2 m).
constexpr double kEdgeM = 1.8;

// The deformed surface against the closed form, at points other than the constraints'.
Errors compare(const Fixture& fx, const Mosaic& input, const Tile<float>& out) {
  const SampleSurface surface(
      [&](int c, int r) {
        return fx.local(pixel_centre(
            default_grid(), {input.face, input.origin_col + c, input.origin_row + r}, input.level));
      },
      out);
  auto height = [&](double e, double n) { return surface.height(e, n); };
  const double ce = std::cos(kHeading), sn = std::sin(kHeading);
  double sum = 0;
  int count = 0;
  for (double s = 0.13; s < kLength; s += 0.37, ++count) {
    const double d = height(fx.e0 + s * ce, fx.n0 + s * sn) - fx.curve_z(s);
    sum += d * d;
  }
  Errors e;
  e.control_rms = std::sqrt(sum / count);
  sum = 0;
  count = 0;
  // The section up to a base sample and a half inside its edge: there the surface must step from
  // the section's heights (relative to the curve point's) to the unchanged terrain beyond the
  // field of influence (on a slope they differ), within the triangles astride the edge.
  for (double s = 0.4; s < kLength; s += 1.3)
    for (double o = -kTop + kEdgeM; o < kTop - kEdgeM; o += 0.7, ++count) {
      // Positive offsets on the right of the direction of travel.
      const double d = height(fx.e0 + s * ce + o * sn, fx.n0 + s * sn - o * ce) -
                       (fx.curve_z(s) + Fixture::trapezoid(o));
      sum += d * d;
    }
  e.section_rms = std::sqrt(sum / count);
  return e;
}

// Samples farther than `margin` metres beyond the field of influence keep their input bits.
int changed_outside(const Fixture& fx, const Mosaic& input, const Tile<float>& out, double margin) {
  const Tile<float>& dem = input.layers.at("dem");
  const double ce = std::cos(kHeading), sn = std::sin(kHeading);
  int changed = 0;
  for (int r = 0; r < dem.size(); ++r)
    for (int c = 0; c < dem.size(); ++c) {
      const auto p = fx.local(pixel_centre(
          default_grid(), {input.face, input.origin_col + c, input.origin_row + r}, kPixelLevel));
      const double de = p[0] - fx.e0, dn = p[1] - fx.n0;
      const double s = std::clamp(de * ce + dn * sn, 0.0, kLength);
      const double dist = std::hypot(de - s * ce, dn - s * sn);
      if (dist > kTop + margin && std::memcmp(&dem.at(c, r), &out.at(c, r), sizeof(float)) != 0)
        ++changed;
    }
  return changed;
}

// Cuts the channel into `surface` `refine` levels finer and checks it against the closed form
// within the limits at that level.
void expect_finer_channel(const char* name, const Surface& surface, int refine,
                          double control_limit) {
  Fixture fx;
  fx.surface = surface;
  const Mosaic input = fx.dem(0);
  const VectorFeature channel = fx.channel();
  const Tile<float> out = deform_run(input, {&channel}, refine);
  const Errors e = compare(fx, finer(input, refine), out);
  std::printf(
      "%s, %d level(s) finer: control-curve RMS %.3f mm, cross-section RMS %.3f %% of the "
      "depth\n",
      name, refine, e.control_rms * 1000, 100 * e.section_rms / kDepth);
  EXPECT_LE(e.control_rms, control_limit);
  EXPECT_LE(e.section_rms, 0.02 * kDepth);
}

// Cuts the channel into `surface` and checks it against the closed form; returns the output.
Tile<float> expect_channel(const char* name, const Surface& surface) {
  Fixture fx;
  fx.surface = surface;
  const Mosaic input = fx.dem(0);
  const VectorFeature channel = fx.channel();
  const Tile<float> out = deform_run(input, {&channel});
  const Errors e = compare(fx, input, out);
  std::printf("%s: control-curve RMS %.2f mm, cross-section RMS %.3f %% of the depth\n", name,
              e.control_rms * 1000, 100 * e.section_rms / kDepth);
  EXPECT_LE(e.control_rms, 0.010);
  EXPECT_LE(e.section_rms, 0.02 * kDepth);
  EXPECT_EQ(changed_outside(fx, input, out, 0), 0);
  return out;
}

double sinusoid(double e, double n) {
  return 1500 +
         3 * std::sin(2 * std::numbers::pi * e / 80) * std::cos(2 * std::numbers::pi * n / 110);
}

TEST(DeformFeatures, TrapezoidalChannelInAPlane) {
  expect_channel("plane", [](double e, double n) { return 1500 + 0.05 * e - 0.03 * n; });
}

TEST(DeformFeatures, TrapezoidalChannelInASinusoidalSurface) {
  const Tile<float> out = expect_channel("sinusoid", sinusoid);
  Fixture fx;
  fx.surface = sinusoid;
  const VectorFeature channel = fx.channel();

  // Another tiling: the same samples inside a mosaic 64 samples larger on every side.
  const Mosaic wide = fx.dem(64);
  const Tile<float> wide_out = deform_run(wide, {&channel});
  int differ = 0;
  for (int r = 0; r < kTile; ++r)
    for (int c = 0; c < kTile; ++c)
      differ += std::memcmp(&out.at(c, r), &wide_out.at(c + 64, r + 64), sizeof(float)) != 0;
  EXPECT_EQ(differ, 0);
}

TEST(DeformFeatures, TrapezoidalChannelAtFinerLevels) {
  const Surface plane = [](double e, double n) { return 1500 + 0.05 * e - 0.03 * n; };
  expect_finer_channel("plane", plane, 1, 0.002);
  expect_finer_channel("sinusoid", sinusoid, 1, 0.002);
  expect_finer_channel("plane", plane, 2, 0.0005);
  expect_finer_channel("sinusoid", sinusoid, 2, 0.0005);
}

TEST(DeformFeatures, AdaptiveEqualsUniformInsideTheRefinedZone) {
  Fixture fx;
  fx.surface = sinusoid;
  const Mosaic input = fx.dem(0);
  const VectorFeature channel = fx.channel();
  constexpr int kRefine = 2;
  const Tile<float> adaptive = deform_run(input, {&channel}, kRefine);
  const Tile<float> uniform =
      deform_run(input, {&channel}, kRefine, {{"energy_weight", 0.01}, {"subdivision", "uniform"}});
  const Mosaic fine = finer(input, kRefine);
  const double ce = std::cos(kHeading), sn = std::sin(kHeading);
  int inside = 0;
  double inside_max = 0, outside_max = 0;
  for (int r = 0; r < adaptive.size(); ++r)
    for (int c = 0; c < adaptive.size(); ++c) {
      const auto p = fx.local(pixel_centre(
          default_grid(), {fine.face, fine.origin_col + c, fine.origin_row + r}, fine.level));
      const double de = p[0] - fx.e0, dn = p[1] - fx.n0;
      const double s = de * ce + dn * sn, o = de * sn - dn * ce;
      const double d = std::abs(double(adaptive.at(c, r)) - double(uniform.at(c, r)));
      // Within the field of influence and one base sample beyond it (refined in both; the
      // cross sections end with the curve).
      if (s >= 0 && s <= kLength && std::abs(o) <= kTop + 1.2) {
        ++inside;
        inside_max = std::max(inside_max, d);
      } else {
        outside_max = std::max(outside_max, d);
      }
    }
  std::printf(
      "%d finer samples in the refined zone: adaptive - uniform at most %.2g m; "
      "outside, where uniform Loop smooths the terrain: %.3f m\n",
      inside, inside_max, outside_max);
  EXPECT_GT(inside, 80000);       // 150 m by 42.4 m of 0.3 m samples: 84,800
  EXPECT_LE(inside_max, 2.5e-4);  // two float32 steps at 1500 m: the solves' rounding only
  EXPECT_GT(outside_max, 1e-3);   // the comparison sees subdivision differences
}

std::string error_of(const Mosaic& input, const VectorFeature& f, int refine = 0) {
  try {
    deform_run(input, {&f}, refine);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(DeformFeatures, StrokesLeavingTheDemCrossingNodataOrThemselvesAreErrors) {
  Fixture fx;
  fx.surface = [](double e, double n) { return 1500 + 0.05 * e - 0.03 * n; };
  Mosaic input = fx.dem(0);
  VectorFeature f = fx.channel();
  f.attributes.erase("profile");  // draped

  VectorFeature away = f;
  const LonLat far = fx.lonlat(400, 0);
  away.geometry.lines[0][1] = {far.lon, far.lat};
  EXPECT_NE(error_of(input, away)
                .find("inputs.strokes: feature 1: its control curve leaves the DEM (the step's "
                      "region) at lon"),
            std::string::npos)
      << error_of(input, away);

  VectorFeature crossing = f;
  for (const auto& [e, n] : std::vector<std::array<double, 2>>{{40, -30}, {0, 20}, {0, -30}}) {
    const LonLat p = fx.lonlat(e, n);
    crossing.geometry.lines[0].push_back({p.lon, p.lat});
  }
  EXPECT_EQ(error_of(input, crossing),
            "inputs.strokes: feature 1: the control curve crosses itself (segments 1 and 3)");

  const MosaicFrame frame(default_grid(), input.face, input.level, input.origin_col,
                          input.origin_row, kSite);
  const auto hole =
      frame.sample(fx.lonlat(fx.e0 + 50 * std::cos(kHeading), fx.n0 + 50 * std::sin(kHeading)));
  input.layers.at("dem").at(int((*hole)[0]), int((*hole)[1])) = NAN;
  EXPECT_NE(
      error_of(input, f).find("inputs.strokes: feature 1: its control curve crosses nodata at lon"),
      std::string::npos)
      << error_of(input, f);
}

TEST(DeformFeatures, RefinedStrokeNearNodataIsAnError) {
  Fixture fx;
  fx.surface = sinusoid;
  Mosaic input = fx.dem(0);
  const VectorFeature channel = fx.channel();
  const MosaicFrame frame(default_grid(), input.face, input.level, input.origin_col,
                          input.origin_row, kSite);
  // A nodata sample 4.2 m (3.5 samples) beyond the channel's bank, half way along.
  const double ce = std::cos(kHeading), sn = std::sin(kHeading);
  const auto hole =
      frame.sample(fx.lonlat(fx.e0 + 75 * ce + 24.2 * sn, fx.n0 + 75 * sn - 24.2 * ce));
  input.layers.at("dem").at(int(std::lround((*hole)[0])), int(std::lround((*hole)[1]))) = NAN;
  // The base level does not read it: the nodata sample stays, every other sample is finite.
  const Tile<float> base = deform_run(input, {&channel});
  EXPECT_EQ(
      std::count_if(base.data().begin(), base.data().end(), [](float v) { return std::isnan(v); }),
      1);
  for (const int refine : {1, 2}) {
    const std::string error = error_of(input, channel, refine);
    EXPECT_NE(error.find("inputs.strokes: feature 1: nodata at lon "), std::string::npos) << error;
    EXPECT_NE(error.find("samples or less from its constraints: refined " + std::to_string(refine) +
                         " level(s), it needs the DEM's heights there"),
              std::string::npos)
        << error;
  }
}

// A refined level reads the DEM 3 + k samples around the constrained triangles; nearer the
// region's edge, Loop's border masks would make another surface than the interior's. The channel
// moved east until its easternmost constraint (the last cross section's right end) lies two
// samples and a half inside the region's last sample: the base level runs, one and two levels
// finer fail naming the feature and the place. (Before, they ran with the border masks.)
TEST(DeformFeatures, RefinedStrokeNearTheRegionsEdgeIsAnError) {
  Fixture fx;
  fx.surface = [](double e, double n) { return 1500 + 0.05 * e - 0.03 * n; };
  const Mosaic input = fx.dem(0);
  const MosaicFrame frame(default_grid(), input.face, input.level, input.origin_col,
                          input.origin_row, kSite);
  const double ce = std::cos(kHeading), sn = std::sin(kHeading);
  // The mosaic column of the last cross section's right end for a start at (e0, n0).
  const auto east_end = [&](double e0) {
    return (*frame.sample(
        fx.lonlat(e0 + kLength * ce + kTop * sn, fx.n0 + kLength * sn - kTop * ce)))[0];
  };
  // The region's last column is the mosaic's 254 (its outer sample is the runner's halo).
  const double target = 254 - 2.5;
  const double per_metre = east_end(fx.e0 + 1) - east_end(fx.e0);
  fx.e0 += (target - east_end(fx.e0)) / per_metre;
  ASSERT_NEAR(east_end(fx.e0), target, 0.05);
  const VectorFeature channel = fx.channel();
  EXPECT_NO_THROW(deform_run(input, {&channel}));
  for (const int refine : {1, 2}) {
    const std::string error = error_of(input, channel, refine);
    EXPECT_NE(error.find("inputs.strokes: feature 1: its constraints come within "),
              std::string::npos)
        << error;
    EXPECT_NE(error.find(" samples of the region's edge at lon "), std::string::npos) << error;
    EXPECT_NE(error.find(": refined " + std::to_string(refine) +
                         " level(s), it needs the DEM's heights " + std::to_string(3 + refine) +
                         " samples around them, inside the region"),
              std::string::npos)
        << error;
  }
}

}  // namespace
}  // namespace maquette::deform
