// Cast shadows (render/cast_shadow.h, render/terrain_shadow.h) against an analytic cone and GRASS
// r.sunmask (run as a separate process by rsunmask.sh on the same GeoTIFF, in a GRASS location in
// its CRS, UTM zone 12, where r.sunmask works; skipped when GRASS is absent). The cone's shadow
// under a sun lower than its flanks is known exactly: the kite between its axis, the two points
// of its foot where the flank's slope towards the sun equals the sun's (cos = R tan(alt) / H),
// and the apex's shadow H / tan(alt) away from the sun. Checked:
// - the march reading the nearest node, as r.sunmask does, agrees with r.sunmask on >= 99 % of
//   cells of a cone, a ridge and the Zion SRTM canyon warped to UTM (60 m) by gdalwarp;
// - the bilinear march (the renderer's) agrees with the cone's exact shadow on >= 99 % of cells,
//   r.sunmask less well (it shadows ~16 % too much where rays graze the flanks: printed, with
//   the bilinear march's agreement with r.sunmask); on the ridge across the grid lit along its
//   rows the shadow ends H / tan(alt) beyond the crest;
// - `maquette render panorama --shadows` of the cone ingested into a store: the cast_shadow guide
//   (> 0.5) agrees with the exact shadow at each terrain pixel's lon/lat on >= 99 % of them, and
//   1 and 2 threads write the same bytes; a sun at or below the horizon is refused.
// The cone stands on UTM 12's central meridian, so grid north is true north there.
#include <gdal_priv.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

#include "cone_dem.h"
#include "render/cast_shadow.h"
#include "run_cli.h"
#include "synthetic_raster.h"

namespace maquette {
namespace {

using test::run_maquette;

constexpr double kDegree = std::numbers::pi / 180;
using test::cone_axis;
using test::kConeHeight;
using test::kConeRadius;
constexpr double kAzimuth = 250, kAltitude = 15;  // the sun, degrees

bool have_grass() { return std::system("command -v grass >/dev/null 2>&1") == 0; }

struct Raster {
  int width = 0, height = 0;
  std::array<double, 6> geotransform{};
  std::vector<float> values;
  double x(int col) const { return geotransform[0] + (col + 0.5) * geotransform[1]; }
  double y(int row) const { return geotransform[3] + (row + 0.5) * geotransform[5]; }
};

Raster read_raster(const std::string& path) {
  GDALAllRegister();
  const std::unique_ptr<GDALDataset> ds(GDALDataset::Open(path.c_str(), GDAL_OF_RASTER));
  if (!ds) throw std::runtime_error("cannot open " + path);
  Raster r;
  r.width = ds->GetRasterXSize();
  r.height = ds->GetRasterYSize();
  ds->GetGeoTransform(r.geotransform.data());
  r.values.resize(size_t(r.width) * size_t(r.height));
  if (ds->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, r.width, r.height, r.values.data(), r.width,
                                     r.height, GDT_Float32, 0, 0) != CE_None)
    throw std::runtime_error("cannot read " + path);
  return r;
}

// r.sunmask's mask of `dem` (1 in shadow) under the sun (azimuth, altitude).
Raster rsunmask(const std::string& dem, double azimuth) {
  const std::string out = dem + ".rsunmask.tif";
  const std::string command = std::string(MAQUETTE_SOURCE_DIR) + "/tests/render/rsunmask.sh " +
                              dem + " " + out + " " + std::to_string(azimuth) + " " +
                              std::to_string(kAltitude);
  if (std::system(command.c_str()) != 0) throw std::runtime_error("r.sunmask failed");
  return read_raster(out);
}

// Whether (e, n) metres from the cone's axis lies in its exact shadow (the kite of the header).
bool in_cone_shadow(double e, double n) {
  const double away = (kAzimuth + 180) * kDegree,
               reach = kConeHeight / std::tan(kAltitude * kDegree);
  const double half = std::acos(kConeRadius / reach);  // from the axis, either side of `away`
  auto point = [](double azimuth, double r) {
    return std::array<double, 2>{r * std::sin(azimuth), r * std::cos(azimuth)};
  };
  const std::array<std::array<double, 2>, 4> kite = {point(0, 0), point(away - half, kConeRadius),
                                                     point(away, reach),
                                                     point(away + half, kConeRadius)};
  // Inside a convex polygon: on the same side of every edge (the corners go clockwise).
  for (size_t k = 0; k < 4; ++k) {
    const auto& a = kite[k];
    const auto& b = kite[(k + 1) % 4];
    if ((b[0] - a[0]) * (n - a[1]) - (b[1] - a[1]) * (e - a[0]) > 0) return false;
  }
  return true;
}

// Our march's mask of `dem` under the sun (azimuth, kAltitude).
std::vector<uint8_t> our_mask(const Raster& dem, double azimuth,
                              ShadowSampling sampling = ShadowSampling::Bilinear) {
  HeightGrid grid;
  grid.width = dem.width;
  grid.height = dem.height;
  grid.spacing = dem.geotransform[1];
  grid.x0 = dem.x(0);
  grid.y0 = dem.y(0);
  grid.z = dem.values;
  return CastShadow(grid, azimuth, kAltitude, sampling).node_mask();
}

// The share of `dem`'s cells with data where the two masks agree, and the numbers in shadow.
struct Agreement {
  double share = 0;
  size_t first = 0, second = 0;
};
Agreement agreement(const Raster& dem, const std::function<bool(size_t)>& first,
                    const std::function<bool(size_t)>& second) {
  Agreement a;
  size_t cells = 0, same = 0;
  for (size_t i = 0; i < dem.values.size(); ++i) {
    if (std::isnan(dem.values[i])) continue;
    ++cells;
    same += first(i) == second(i);
    a.first += first(i);
    a.second += second(i);
  }
  a.share = double(same) / double(cells);
  return a;
}

TEST(CastShadow, ConeAgreesWithItsExactShadowAndRsunmask) {
  const std::string dir = test::temp_dir();
  const std::string path = test::write_utm_dem(dir + "/cone.tif", 200, 60, test::cone_height);
  const Raster dem = read_raster(path);
  const auto [x, y] = cone_axis();
  const std::vector<uint8_t> ours = our_mask(dem, kAzimuth);
  auto exact = [&, x = x, y = y](size_t i) {
    return in_cone_shadow(dem.x(int(i % 200)) - x, dem.y(int(i / 200)) - y);
  };
  const Agreement vs_exact = agreement(
      dem, [&](size_t i) { return ours[i] != 0; }, exact);
  std::cout << "cone: ours and the exact shadow agree on " << vs_exact.share * 100
            << " % of cells; in shadow: ours " << vs_exact.first << ", exact " << vs_exact.second
            << "\n";
  RecordProperty("agreement_exact", std::to_string(vs_exact.share));
  EXPECT_GE(vs_exact.share, 0.99);
  EXPECT_GT(vs_exact.second, 3000u);

  if (!have_grass()) GTEST_SKIP() << "no GRASS (scripts/setup.sh installs grass-core)";
  const Raster theirs = rsunmask(path, kAzimuth);
  auto grass = [&](size_t i) { return theirs.values[i] > 0.5; };
  const Agreement vs_grass = agreement(
      dem, [&](size_t i) { return ours[i] != 0; }, grass);
  const Agreement grass_exact = agreement(dem, grass, exact);
  const std::vector<uint8_t> nearest = our_mask(dem, kAzimuth, ShadowSampling::Nearest);
  const Agreement as_grass = agreement(
      dem, [&](size_t i) { return nearest[i] != 0; }, grass);
  std::cout << "cone: r.sunmask and our nearest-node march agree on " << as_grass.share * 100
            << " % of cells, r.sunmask and our bilinear march on " << vs_grass.share * 100
            << " %, r.sunmask and the exact shadow on " << grass_exact.share * 100
            << " % (r.sunmask " << grass_exact.first << " in shadow)\n";
  RecordProperty("agreement_rsunmask_nearest", std::to_string(as_grass.share));
  RecordProperty("agreement_rsunmask_bilinear", std::to_string(vs_grass.share));
  EXPECT_GE(as_grass.share, 0.99);
  EXPECT_GT(vs_exact.share, grass_exact.share);  // the exact shadow is nearer ours
}

TEST(CastShadow, RidgeAgreesWithRsunmask) {
  // A ridge 1 km high across the grid, its crest 1.5 km west of the centre, flanks of slope 0.5;
  // a sun from the west at 15 degrees shadows 1000 / tan(15) = 3732 m east of the crest.
  const std::string dir = test::temp_dir();
  auto ridge = [](double e, double) {
    return test::kConeBase + std::max(0.0, 1000 - 0.5 * std::abs(e + 1500));
  };
  const std::string path = test::write_utm_dem(dir + "/ridge.tif", 200, 60, ridge);
  const Raster dem = read_raster(path);
  const std::vector<uint8_t> ours = our_mask(dem, 270);
  const auto [x, y] = cone_axis();
  const double crest = -1500, reach = 1000 / std::tan(kAltitude * kDegree);
  size_t off = 0;  // cells of ours more than a cell away from the exact shadow's ends
  for (size_t i = 0; i < ours.size(); ++i) {
    const double e = dem.x(int(i % 200)) - x;
    const bool exact = e > crest && e < crest + reach;
    off += ours[i] != exact && std::abs(e - crest) > 60 && std::abs(e - crest - reach) > 60;
  }
  EXPECT_EQ(off, 0u);
  if (!have_grass()) GTEST_SKIP() << "no GRASS (scripts/setup.sh installs grass-core)";
  const Raster theirs = rsunmask(path, 270);
  auto grass = [&](size_t i) { return theirs.values[i] > 0.5; };
  const std::vector<uint8_t> nearest = our_mask(dem, 270, ShadowSampling::Nearest);
  for (const auto* mask : {&ours, &nearest}) {
    const Agreement a = agreement(
        dem, [&](size_t i) { return (*mask)[i] != 0; }, grass);
    std::cout << "ridge: our " << (mask == &ours ? "bilinear" : "nearest-node")
              << " march and r.sunmask agree on " << a.share * 100
              << " % of cells; in shadow: " << a.first << " and " << a.second << "\n";
    EXPECT_GE(a.share, 0.99);
  }
}

TEST(CastShadow, ZionAgreesWithRsunmask) {
  const std::string zion = std::string(MAQUETTE_SHARED_DIR) + "/data/zion/srtm.tif";
  if (!std::filesystem::exists(zion)) GTEST_SKIP() << "no " << zion;
  if (!have_grass()) GTEST_SKIP() << "no GRASS (scripts/setup.sh installs grass-core)";
  const std::string dir = test::temp_dir(), path = dir + "/zion-utm.tif";
  // Zion Canyon, ~11 x 13 km.
  const std::string warp =
      "gdalwarp -q -t_srs EPSG:32612 -te_srs EPSG:4326 -te -113.1 37.2 "
      "-112.98 37.32 -tr 60 60 -r bilinear -dstnodata nan " +
      zion + " " + path;
  ASSERT_EQ(std::system(warp.c_str()), 0);
  const Raster dem = read_raster(path);
  const Raster theirs = rsunmask(path, kAzimuth);
  auto grass = [&](size_t i) { return theirs.values[i] > 0.5; };
  const std::vector<uint8_t> nearest = our_mask(dem, kAzimuth, ShadowSampling::Nearest);
  const std::vector<uint8_t> ours = our_mask(dem, kAzimuth);
  const Agreement a = agreement(
      dem, [&](size_t i) { return nearest[i] != 0; }, grass);
  const Agreement b = agreement(
      dem, [&](size_t i) { return ours[i] != 0; }, grass);
  std::cout << "zion: r.sunmask and our nearest-node march agree on " << a.share * 100
            << " % of cells (in shadow: " << a.first << " and " << a.second
            << "), and our bilinear march on " << b.share * 100 << " % (" << b.first
            << " in shadow)\n";
  RecordProperty("agreement_rsunmask_nearest", std::to_string(a.share));
  RecordProperty("agreement_rsunmask_bilinear", std::to_string(b.share));
  EXPECT_GE(a.share, 0.99);
  EXPECT_GT(a.second, 2000u);
  EXPECT_LT(b.first, a.second);  // the bilinear march shadows less where rays graze
}

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(CastShadow, PanoramaShadowsAreTheConesExactShadow) {
  const std::string dir = test::temp_dir(), store = dir + "/s.mqt";
  const std::string dem = test::write_utm_dem(dir + "/cone.tif", 400, 30, test::cone_height);
  auto r =
      run_maquette("ingest " + store + " --layer dem --as dem --vertical-datum ellipsoid " + dem);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto render = [&](const std::string& out, const std::string& options) {
    return run_maquette("render panorama " + store + " " + out +
                        " --dem dem --camera -111.0 37.21 6000 --look-at -111.0 37.3 1500 " +
                        "--fov 50 --size 400 300 " + options);
  };
  const std::string sun =
      "--shadows --sun " + std::to_string(kAzimuth) + " " + std::to_string(kAltitude);
  r = render(dir + "/one.png", sun + " -t 1");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = render(dir + "/two.png", sun + " -t 2");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const std::string file : {".png", "-guides.tif"})
    EXPECT_EQ(slurp(dir + "/one" + file), slurp(dir + "/two" + file)) << file;

  GDALAllRegister();
  const std::unique_ptr<GDALDataset> guides(
      GDALDataset::Open((dir + "/one-guides.tif").c_str(), GDAL_OF_RASTER));
  ASSERT_TRUE(guides);
  ASSERT_EQ(guides->GetRasterCount(), 6);
  ASSERT_STREQ(guides->GetRasterBand(5)->GetDescription(), "cast_shadow");
  ASSERT_STREQ(guides->GetRasterBand(6)->GetDescription(), "shading");
  auto band = [&](int b) {
    std::vector<double> v(400 * 300);
    EXPECT_EQ(guides->GetRasterBand(b)->RasterIO(GF_Read, 0, 0, 400, 300, v.data(), 400, 300,
                                                 GDT_Float64, 0, 0),
              CE_None);
    return v;
  };
  const auto lon = band(3), lat = band(4), shadow = band(5), shading = band(6);
  // The shading guide is the factor the colour was shaded by: the ambient 0.3 alone in full
  // shadow, at most 1 in the sun, NaN exactly where the sky is.
  size_t dark = 0;
  for (size_t i = 0; i < shading.size(); ++i) {
    ASSERT_EQ(std::isnan(shading[i]), std::isnan(lon[i])) << i;
    if (std::isnan(shading[i])) continue;
    EXPECT_GE(shading[i], 0.3 - 1e-6);
    EXPECT_LE(shading[i], 1.0 + 1e-6);
    if (shadow[i] == 1) {
      EXPECT_NEAR(shading[i], 0.3, 1e-6) << i;
      ++dark;
    }
  }
  EXPECT_GT(dark, 1000u);
  const test::Projector utm("EPSG:4326", "EPSG:32612");
  const auto [x, y] = cone_axis();
  size_t seen = 0, same = 0, in_shadow = 0;
  for (size_t i = 0; i < shadow.size(); ++i) {
    if (std::isnan(shadow[i])) continue;
    const auto [e, n] = utm(lon[i], lat[i]);
    ++seen;
    const bool ours = shadow[i] > 0.5;
    same += ours == in_cone_shadow(e - x, n - y);
    in_shadow += ours;
  }
  const double share = double(same) / double(seen);
  std::cout << "panorama: " << seen << " terrain pixels, " << in_shadow << " in shadow, "
            << share * 100 << " % agree with the exact shadow\n";
  RecordProperty("agreement_exact", std::to_string(share));
  EXPECT_GT(seen, 60000u);
  EXPECT_GT(in_shadow, 5000u);
  EXPECT_GE(share, 0.99);

  r = render(dir + "/bad.png", "--shadows --sun 250 0");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("--sun altitude"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace maquette
