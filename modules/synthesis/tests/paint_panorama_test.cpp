// The transfer in the picture (paint_panorama.h, maquette-paint) on panorama_scene.h's scene
// without relief (a flat plateau on a flat plain). Checked: terrain sources keep the target's
// class (>= 0.97), none is excluded, the sky stays the render's unless a sky class is asked for
// (then it is painted from that class); the program's files are byte-identical for 1 and 2
// threads and tiles of 64 and 256 pixels (with the light guide too); raising w_distance lowers
// the distance mismatch; no coherent copy across a depth break with silhouettes on (counted,
// against the same run without); the shading blend as stated; the skyline blended by the
// render's coverage as stated; the haze by distance as stated; bad input named.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <tuple>
#include <utility>

#include "core/error.h"
#include "core/srgb.h"
#include "panorama_scene.h"

namespace maquette::synthesis {
namespace {

const Scene& scene() {
  static const Scene s;
  return s;
}

// Linear light in 8-bit sRGB, not rounded (IEC 61966-2-1's encoding, written here).
double srgb_code(double linear) {
  return 255 * (linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1 / 2.4) - 0.055);
}

TEST(PaintPanorama, TheSkyIsAClassOfItsOwn) {
  nlohmann::json params = scene().params();
  params["sky_class"] = 2;
  params["landcover_classes"] = {{"41", 1}, {"52", 0}};
  EXPECT_EQ(int(*paint_params(params, "p.json").sky_class), 2);
  for (const nlohmann::json& value : {nlohmann::json{1, 2}, nlohmann::json(2)}) {
    params["landcover_classes"] = {{"41", value}, {"52", 0}};
    try {
      paint_params(params, "p.json");
      ADD_FAILURE() << value.dump() << ": the sky's class paints land cover, and it ran";
    } catch (const Error& e) {
      EXPECT_EQ(std::string(e.what()),
                "p.json.sky_class: class 2 also paints land-cover class 41 (landcover_classes): "
                "the sky must be a class of its own");
    }
  }
}

TEST(PaintPanorama, TerrainKeepsItsClassesNoExcludedSourceAndTheSkyStays) {
  const PanoramaPicture picture = read_panorama(scene().picture, true);
  const PaintedPanorama p = paint(scene(), scene().params());
  size_t terrain = 0, kept = 0, sky = 0, excluded = 0;
  for (size_t i = 0; i < picture.distance.size(); ++i) {
    const auto [x, y] = source_of(p, i);
    if (std::isnan(picture.distance[i])) {
      ++sky;
      EXPECT_EQ(x, -1) << i;  // not painted: the render's sky, byte for byte
      for (size_t k = 0; k < 3; ++k) EXPECT_EQ(p.rgb[3 * i + k], picture.rgb[3 * i + k]);
      continue;
    }
    ASSERT_GE(x, 0) << i;
    ++terrain;
    excluded += excluded_at(x, y);
    kept += painting_label(x, y) == (picture.land_cover[i] == 41 ? 1 : 0);
  }
  std::printf(
      "%zu terrain pixels, %zu of their sources of the target's class, %zu excluded; %zu "
      "sky pixels kept\n",
      terrain, kept, excluded, sky);
  ASSERT_GT(sky, 5000u);
  ASSERT_GT(terrain, 30000u);
  EXPECT_EQ(excluded, 0u);
  EXPECT_GE(double(kept) / double(terrain), 0.97) << kept << " of " << terrain;
}

TEST(PaintPanorama, TheSkyIsPaintedFromTheSkyClassWhenAskedFor) {
  const PanoramaPicture picture = read_panorama(scene().picture, true);
  nlohmann::json params = scene().params();
  params["sky_class"] = 2;
  const PaintedPanorama p = paint(scene(), params);
  size_t sky = 0, from_sky = 0, terrain_from_sky = 0;
  for (size_t i = 0; i < picture.distance.size(); ++i) {
    const auto [x, y] = source_of(p, i);
    ASSERT_GE(x, 0) << i;
    if (std::isnan(picture.distance[i]))
      ++sky, from_sky += painting_label(x, y) == 2;
    else
      terrain_from_sky += painting_label(x, y) == 2;
  }
  std::printf("%zu of %zu sky pixels from the sky class, %zu terrain pixels\n", from_sky, sky,
              terrain_from_sky);
  EXPECT_GE(double(from_sky) / double(sky), 0.97) << from_sky << " of " << sky;
  EXPECT_LE(terrain_from_sky, 50u);
}

// Mean |target distance guide - the painting's distance at the source| over the terrain.
double distance_mismatch(const PaintedPanorama& p, const PanoramaPicture& picture) {
  double sum = 0;
  size_t n = 0;
  for (size_t i = 0; i < picture.distance.size(); ++i) {
    if (std::isnan(picture.distance[i])) continue;
    const double target = distance_guide(picture.distance[i], {2000, 30000});
    const double source = 1.0 - double(source_of(p, i)[1]) / double(kPaintingHeight - 1);
    sum += std::abs(target - source), ++n;
  }
  return sum / double(n);
}

TEST(PaintPanorama, RaisingTheDistanceWeightLowersTheDistanceMismatch) {
  const PanoramaPicture picture = read_panorama(scene().picture, true);
  double previous = INFINITY;
  for (const double w : {0.0, 2.0, 8.0}) {
    nlohmann::json params = scene().params();
    params["w_distance"] = w;
    const double mismatch = distance_mismatch(paint(scene(), params), picture);
    std::printf("w_distance %g: mean distance mismatch %.4f\n", w, mismatch);
    EXPECT_LT(mismatch, previous) << "w_distance " << w;
    previous = mismatch;
  }
}

// 4-neighbour pairs of painted pixels across a depth break (one sky, or one farther than 1.05
// times the other) whose sources are the same offset apart in the painting: coherent copies.
size_t coherent_across_breaks(const PaintedPanorama& p, const PanoramaPicture& picture,
                              size_t& pairs) {
  size_t coherent = 0;
  pairs = 0;
  for (int r = 0; r < picture.height; ++r)
    for (int c = 0; c < picture.width; ++c)
      for (const auto [dc, dr] : {std::array{1, 0}, std::array{0, 1}}) {
        if (c + dc >= picture.width || r + dr >= picture.height) continue;
        const size_t a = size_t(r) * size_t(picture.width) + size_t(c),
                     b = size_t(r + dr) * size_t(picture.width) + size_t(c + dc);
        const float da = picture.distance[a], db = picture.distance[b];
        const bool broken = std::isnan(da) != std::isnan(db) ||
                            (!std::isnan(da) && std::max(da, db) > 1.05f * std::min(da, db));
        if (!broken) continue;
        ++pairs;
        const auto sa = source_of(p, a), sb = source_of(p, b);
        coherent += sb[0] - sa[0] == dc && sb[1] - sa[1] == dr;
      }
  return coherent;
}

TEST(PaintPanorama, NoCoherentCopyAcrossASilhouette) {
  const PanoramaPicture picture = read_panorama(scene().picture, true);
  nlohmann::json params = scene().params();
  params["sky_class"] = 2;
  size_t pairs = 0;
  const size_t with = coherent_across_breaks(paint(scene(), params), picture, pairs);
  params["silhouettes"] = false;
  const size_t without = coherent_across_breaks(paint(scene(), params), picture, pairs);
  std::printf(
      "%zu pixel pairs across a depth break: %zu coherent copies with silhouettes, %zu "
      "without\n",
      pairs, with, without);
  ASSERT_GT(pairs, 300u);
  EXPECT_GT(without, pairs / 10);
  EXPECT_EQ(with, 0u);
}

TEST(PaintPanorama, ShadingBlendsAsStated) {
  const PanoramaPicture picture = read_panorama(scene().picture, true);
  nlohmann::json params = scene().params();
  params["shading"] = 0;
  const PaintedPanorama flat = paint(scene(), params);
  params["shading"] = 0.7;
  const PaintedPanorama shaded = paint(scene(), params);
  ASSERT_EQ(std::memcmp(flat.source.data(), shaded.source.data(), 4 * flat.source.size()), 0);
  std::vector<float> lit;
  for (size_t i = 0; i < picture.shading.size(); ++i)
    if (!std::isnan(picture.distance[i])) lit.push_back(picture.shading[i]);
  std::nth_element(lit.begin(), lit.begin() + ptrdiff_t(lit.size() / 2), lit.end());
  const double median = lit[lit.size() / 2];
  size_t checked = 0;
  for (size_t i = 0; i < picture.shading.size(); ++i) {
    if (std::isnan(picture.distance[i])) continue;
    const double factor = 0.3 + 0.7 * picture.shading[i] / median;
    for (size_t k = 0; k < 3; ++k)
      EXPECT_NEAR(shaded.rgb[3 * i + k], std::clamp(flat.rgb[3 * i + k] * factor, 0.0, 255.0),
                  1.0 + 0.5 * factor)
          << i;  // flat is rounded already: half a level times the factor, and the rounding
    ++checked;
  }
  EXPECT_GT(checked, 30000u);
}

// A picture rendered with --antialias 3 (its coverage guide): the painted skyline's pixels
// (coverage strictly between 0 and 1) are their terrain's and sky's painted colours mixed in linear
// light by the coverage (skyline_blend.h, worked here from the same picture painted without the
// coverage), every other pixel and every source unchanged; with the sky painted and with the
// render's sky kept.
TEST(PaintPanorama, TheSkylineBlendsByCoverage) {
  const Scene& s = scene();
  const std::string aa = s.dir + "/aa.png";
  const auto r = test::run_maquette("render panorama " + s.dir + "/s.mqt " + aa +
                                    " --dem dem --land-cover lc --camera 10.15 45.02 1500 "
                                    "--heading 0 --pitch -6 --fov 50 --size 320 200 --antialias 3");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const PanoramaPicture picture = read_panorama(aa, true);
  ASSERT_EQ(picture.coverage.size(), picture.distance.size());
  PanoramaPicture without = picture;
  without.coverage.clear();
  auto linear = [](uint8_t b) { return srgb_to_linear(b / 255.0); };
  for (const bool sky_painted : {false, true}) {
    SCOPED_TRACE(sky_painted ? "sky painted" : "the render's sky");
    nlohmann::json raw = s.params();
    if (sky_painted) raw["sky_class"] = 2;
    const PaintParams params = paint_params(raw, "params.json");
    const auto exemplar = transfer_exemplar(params.exemplar);
    const PaintedPanorama plain = paint_panorama(without, *exemplar, params);
    const PaintedPanorama blended = paint_panorama(picture, *exemplar, params);
    ASSERT_EQ(std::memcmp(plain.source.data(), blended.source.data(), 4 * plain.source.size()), 0);
    const int w = picture.width;
    auto sky = [&](size_t i) { return std::isnan(picture.distance[i]); };
    size_t edge = 0, mixed = 0;
    for (int row = 0; row < picture.height; ++row)
      for (int col = 0; col < w; ++col) {
        const size_t i = size_t(row) * size_t(w) + size_t(col);
        const float c = picture.coverage[i];
        if (c == 0 || c == 1) {
          for (size_t k = 0; k < 3; ++k) ASSERT_EQ(blended.rgb[3 * i + k], plain.rgb[3 * i + k]);
          continue;
        }
        ++edge;
        // The terrain's and the sky's colours: its own, or its first neighbour's (above, left,
        // right, below, diagonals) of the kind.
        long terrain = sky(i) ? -1 : long(i), open_sky = sky(i) && sky_painted ? long(i) : -1;
        for (const auto& [dc, dr] :
             {std::pair{0, -1}, {-1, 0}, {1, 0}, {0, 1}, {-1, -1}, {1, -1}, {-1, 1}, {1, 1}}) {
          if (col + dc < 0 || col + dc >= w || row + dr < 0 || row + dr >= picture.height) continue;
          const size_t j = size_t(row + dr) * size_t(w) + size_t(col + dc);
          if (terrain < 0 && !sky(j)) terrain = long(j);
          if (open_sky < 0 && sky(j) && picture.coverage[j] == 0) open_sky = long(j);
        }
        if (terrain < 0 || open_sky < 0) continue;
        ++mixed;
        for (size_t k = 0; k < 3; ++k) {
          const double want = c * linear(plain.rgb[3 * size_t(terrain) + k]) +
                              (1 - c) * linear(plain.rgb[3 * size_t(open_sky) + k]);
          EXPECT_NEAR(blended.rgb[3 * i + k], srgb_code(want), 0.51) << col << ", " << row;
        }
      }
    EXPECT_GT(edge, 150u);  // the far horizon (a level line: 215 pixels in all here)
    EXPECT_GT(mixed, edge * 9 / 10);
  }
}

// haze_distance: each terrain pixel mixed in linear light with the haze's colour by 1 -
// exp(-d / haze_distance), d its distance guide (worked here from the same painting without haze):
// the colour given, or the painted sky's mean; the sky and the sources unchanged; far pixels
// more hazed than near ones. Bad params named.
TEST(PaintPanorama, HazeFadesTheFarTerrainIntoTheSky) {
  const Scene& s = scene();
  const PanoramaPicture picture = read_panorama(s.picture, true);
  auto linear = [](uint8_t b) { return srgb_to_linear(b / 255.0); };
  nlohmann::json raw = s.params();
  raw["sky_class"] = 2;
  const PaintedPanorama plain = paint(s, raw);
  std::array<double, 3> sky_mean{};
  size_t sky = 0;
  for (size_t i = 0; i < picture.distance.size(); ++i)
    if (std::isnan(picture.distance[i])) {
      ++sky;
      for (size_t k = 0; k < 3; ++k) sky_mean[k] += linear(plain.rgb[3 * i + k]) / 1e6;
    }
  ASSERT_GT(sky, 1000u);
  for (double& m : sky_mean) m *= 1e6 / double(sky);
  for (const bool given : {false, true}) {
    SCOPED_TRACE(given ? "haze_color given" : "the sky's mean");
    raw["haze_distance"] = 20000;
    if (given) raw["haze_color"] = {200, 180, 250};
    const std::array<double, 3> haze =
        given ? std::array<double, 3>{linear(200), linear(180), linear(250)} : sky_mean;
    const PaintedPanorama hazed = paint(s, raw);
    ASSERT_EQ(std::memcmp(plain.source.data(), hazed.source.data(), 4 * plain.source.size()), 0);
    size_t terrain = 0;
    double near_change = 0, far_change = 0;
    size_t near = 0, far = 0;
    for (size_t i = 0; i < picture.distance.size(); ++i) {
      const double d = picture.distance[i];
      if (std::isnan(d)) {
        for (size_t k = 0; k < 3; ++k) ASSERT_EQ(hazed.rgb[3 * i + k], plain.rgb[3 * i + k]);
        continue;
      }
      ++terrain;
      const double f = 1 - std::exp(-d / 20000);
      double change = 0;
      for (size_t k = 0; k < 3; ++k) {
        const double want = (1 - f) * linear(plain.rgb[3 * i + k]) + f * haze[k];
        EXPECT_NEAR(hazed.rgb[3 * i + k], srgb_code(want), 0.51) << i;
        change += std::abs(linear(hazed.rgb[3 * i + k]) - linear(plain.rgb[3 * i + k]));
      }
      if (d < 4000) near_change += change, ++near;
      if (d > 12000) far_change += change, ++far;
    }
    EXPECT_GT(terrain, 30000u);
    ASSERT_GT(near, 1000u);
    ASSERT_GT(far, 1000u);
    EXPECT_GT(far_change / double(far), 2 * near_change / double(near));
  }

  // A picture without sky and no colour; a colour without a distance; not three numbers.
  PanoramaPicture no_sky = picture;
  for (float& d : no_sky.distance)
    if (std::isnan(d)) d = 50000;
  nlohmann::json hazy = s.params();
  hazy["haze_distance"] = 20000;
  const PaintParams params = paint_params(hazy, "hazy.json");
  try {
    paint_panorama(no_sky, *transfer_exemplar(params.exemplar), params);
    ADD_FAILURE() << "a haze without a colour, and no sky: it ran";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()),
              "hazy.json.haze_distance: the picture shows no sky to take the haze's colour from: "
              "give haze_color");
  }
  auto expect_refused = [](const nlohmann::json& raw, const std::string& message) {
    try {
      paint_params(raw, "c.json");
      ADD_FAILURE() << raw.dump() << ": accepted";
    } catch (const Error& e) {
      EXPECT_EQ(std::string(e.what()), message);
    }
  };
  hazy = s.params();
  hazy["haze_color"] = {1, 2, 3};
  expect_refused(hazy, "c.json.haze_color: given without haze_distance: it would colour nothing");
  hazy["haze_distance"] = 1000;
  hazy["haze_color"] = {1, 2};
  expect_refused(hazy, "c.json.haze_color: [1,2] is not 3 numbers (8-bit red, green, blue)");
}

TEST(PaintPanorama, TheProgramWritesTheSameBytesForThreadsAndTiles) {
  const Scene& s = scene();
  nlohmann::json params = s.params();
  params["sky_class"] = 2;
  params["painting_light"] = "lightness";
  params["w_light"] = 2;
  params["haze_distance"] = 20000;
  std::vector<std::string> runs;
  for (const auto& [tile, threads] : {std::pair{256, 1}, std::pair{64, 2}, std::pair{128, 2}}) {
    params["tile"] = tile;
    const std::string out = s.dir + "/painted-" + std::to_string(tile) + ".png";
    const std::string r = run_paint(s.picture + " " + write_params(s, params, "p.json") + " " +
                                    out + " -t " + std::to_string(threads));
    ASSERT_NE(r.find("exit 0"), std::string::npos) << r;
    runs.push_back(
        test::file_fingerprint(out) + " " +
        test::file_fingerprint(s.dir + "/painted-" + std::to_string(tile) + "-source.tif"));
    ASSERT_FALSE(test::file_fingerprint(out).empty());
  }
  EXPECT_EQ(runs[0], runs[1]);
  EXPECT_EQ(runs[0], runs[2]);
}

// The message of `run`'s maquette::Error, or "no error".
template <class Run>
std::string error_of(const Run& run) {
  try {
    run();
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

// A sky class that the painting does not have (or has only excluded) would have the sky painted
// from any class, the land's: refused, naming the params' field, the class and those the painting
// has.
TEST(PaintPanorama, ASkyClassWithoutPixelsIsRefused) {
  const Scene& s = scene();
  nlohmann::json params = s.params();
  params["sky_class"] = 7;
  EXPECT_EQ(error_of([&] { paint(s, params); }),
            "params.json.sky_class: painting class 7 has no pixel to copy (not in the painting, "
            "or excluded); the classes that have: 0, 1, 2");
  // The program: refused before anything is written.
  const std::string out = s.dir + "/no-sky.png";
  const std::string r =
      run_paint(s.picture + " " + write_params(s, params, "nosky.json") + " " + out);
  EXPECT_NE(r.find("nosky.json.sky_class: painting class 7 has no pixel to copy"),
            std::string::npos)
      << r;
  EXPECT_NE(r.find("exit 1"), std::string::npos) << r;
  EXPECT_FALSE(std::filesystem::exists(out));
}

// A class image, an exclusion mask, an altitude, distance or light image is one 8-bit band: a
// float or 16-bit image, an RGB one, is refused naming the field, the file and its type or bands
// (read as bytes, a float 0..1 altitude would be ~0 everywhere, an RGB image's red its classes).
TEST(PaintPanorama, MasksOfAnotherTypeOrBandsAreRefusedByField) {
  const Scene& s = scene();
  const auto refused = [&](const nlohmann::json& raw) {
    return error_of([&] { transfer_exemplar(paint_params(raw, "m.json").exemplar, "m.json"); });
  };
  // The altitude as floats 0..1, the classes as 16 bits (values 256..258, read as 255).
  test::RasterSpec spec;
  spec.width = kPaintingWidth, spec.height = kPaintingHeight,
  spec.geotransform = {0, 1, 0, 0, 0, 1};
  const std::string altf = s.dir + "/altf.tif", classes16 = s.dir + "/classes16.tif";
  test::write_raster(altf, spec, [](int, double, double y) { return 1 - y / kPaintingHeight; });
  spec.type = "UInt16";
  test::write_raster(classes16, spec,
                     [](int, double x, double y) { return 256 + painting_label(int(x), int(y)); });
  nlohmann::json params = s.params();
  params["painting_altitude"] = altf;
  params["altitude_range"] = {100, 700};
  EXPECT_EQ(refused(params), "m.json.painting_altitude: " + altf +
                                 ": the altitude image is Float32: it must be one 8-bit band "
                                 "(Byte, values 0..255)");
  params = s.params();
  params["labels"] = classes16;
  EXPECT_EQ(refused(params), "m.json.labels: " + classes16 +
                                 ": the class image is UInt16: it must be one 8-bit band (Byte, "
                                 "values 0..255)");
  // The RGB painting itself as the class image, the exclusion mask, the altitude, the distance.
  const std::string rgb = s.dir + "/painting.png";
  for (const auto& [field, what] :
       {std::pair{"labels", "class image"}, std::pair{"exclusion", "exclusion mask"},
        std::pair{"painting_altitude", "altitude image"},
        std::pair{"painting_distance", "distance image"}}) {
    params = s.params();
    params[field] = rgb;
    params["altitude_range"] = {100, 700};
    if (std::string(field) != "painting_altitude") params.erase("altitude_range");
    EXPECT_EQ(refused(params), "m.json." + std::string(field) + ": " + rgb + ": the " + what +
                                   " has 3 bands: it must be one 8-bit band (grey, not RGB or "
                                   "with alpha)");
  }
  // Class 255 in an 8-bit class image: reserved, the file named.
  const std::string reserved = s.dir + "/reserved.png";
  write_image(std::vector<uint8_t>(size_t(kPaintingWidth) * kPaintingHeight, 255), kPaintingWidth,
              kPaintingHeight, 1, {"PNG", {}}, reserved);
  params = s.params();
  params["labels"] = reserved;
  EXPECT_EQ(refused(params),
            "m.json.labels: " + reserved + ": class 255 is reserved (unknown); classes are 0..254");
}

// No output may be one of the run's inputs, however its path is spelled: the panorama's guides,
// the class image, the exclusion mask, the altitude, distance and light images (the panorama,
// the params, the painting and its guides too); nor may OUT-source.tif. Refused before anything
// is written, naming the output and the input.
TEST(PaintPanorama, NoOutputIsAnInput) {
  const Scene& s = scene();
  nlohmann::json params = s.params();
  for (const char* guide : {"alt", "dist", "light"})
    write_image(std::vector<uint8_t>(size_t(kPaintingWidth) * kPaintingHeight, 100), kPaintingWidth,
                kPaintingHeight, 1, {"PNG", {}}, s.dir + "/" + guide + ".png");
  params["painting_altitude"] = s.dir + "/alt.png";
  params["altitude_range"] = {100, 700};
  params["painting_distance"] = s.dir + "/dist.png";
  params["painting_light"] = s.dir + "/light.png";
  // The exclusion mask as a GeoTIFF named as another output's source companion.
  test::shell_output("gdal_translate -q " + s.dir + "/excluded.png " + s.dir + "/mask-source.tif");
  params["exclusion"] = s.dir + "/mask-source.tif";
  const std::string json = write_params(s, params, "inputs.json");
  for (const auto& [out, replaced, input] :
       {std::tuple<std::string, std::string, std::string>{
            s.dir + "/pano-guides.tif", s.dir + "/pano-guides.tif", "the panorama's guides"},
        {s.dir + "/./labels.png", s.dir + "/labels.png", "the class image (labels)"},
        {s.dir + "/alt.png", s.dir + "/alt.png",
         "the painting's altitude image (painting_altitude)"},
        {s.dir + "/../" + std::filesystem::path(s.dir).filename().string() + "/dist.png",
         s.dir + "/dist.png", "the painting's distance image (painting_distance)"},
        {s.dir + "/light.png", s.dir + "/light.png", "the painting's light image (painting_light)"},
        {s.dir + "/mask.png", s.dir + "/mask-source.tif", "the exclusion mask (exclusion)"}}) {
    const std::string before = test::file_fingerprint(replaced);
    ASSERT_FALSE(before.empty()) << replaced;
    const std::string r = run_paint(s.picture + " " + json + " " + out);
    const std::string named =
        out == s.dir + "/mask.png" ? s.dir + "/mask-source.tif" : out;  // the companion
    EXPECT_NE(r.find(named + " is " + input + " " + replaced +
                     ": it would be replaced; give another output path"),
              std::string::npos)
        << r;
    EXPECT_NE(r.find("exit 1"), std::string::npos) << r;
    EXPECT_EQ(test::file_fingerprint(replaced), before) << replaced;
  }
  // The same params with an output of its own run.
  const std::string r = run_paint(s.picture + " " + json + " " + s.dir + "/own.png");
  EXPECT_NE(r.find("exit 0"), std::string::npos) << r;
  // The further paintings' files are inputs too, named by their field.
  const nlohmann::json several = {
      {"painting", "a.png"},
      {"labels", "guides"},
      {"painting_guides", "a-guides.tif"},
      {"painting_distance", "rows"},
      {"painting_light", "lightness"},
      {"exemplars", {{{"painting", "b.png"}, {"labels", "b.geojson"}, {"exclusion", "bx.png"}}}}};
  std::string listed;
  for (const InputFile& input : exemplar_inputs(several))
    listed += input.what + " " + input.path + "; ";
  EXPECT_EQ(listed,
            "the painting (painting) a.png; the painting's guides (painting_guides) a-guides.tif; "
            "the painting (exemplars[0].painting) b.png; the class image (exemplars[0].labels) "
            "b.geojson; the exclusion mask (exemplars[0].exclusion) bx.png; ");
}

TEST(PaintPanorama, BadInputIsNamed) {
  const Scene& s = scene();
  const std::string good = write_params(s, s.params(), "good.json");
  // The guides of a panorama rendered without --land-cover.
  std::string r = run_paint(s.dir + "/bare.png " + good + " " + s.dir + "/x.png");
  EXPECT_NE(r.find("bare-guides.tif: no band 'land_cover'"), std::string::npos) << r;
  EXPECT_NE(r.find("exit 1"), std::string::npos) << r;
  nlohmann::json params = s.params();
  params.erase("painting_distance");
  r = run_paint(s.picture + " " + write_params(s, params, "half.json") + " " + s.dir + "/x.png");
  EXPECT_NE(r.find("half.json: distance_range is given without painting_distance"),
            std::string::npos)
      << r;
  params.erase("distance_range");
  params["w_distance"] = 2;
  r = run_paint(s.picture + " " + write_params(s, params, "weight.json") + " " + s.dir + "/x.png");
  EXPECT_NE(r.find("weight.json: w_distance is given without distance_range"), std::string::npos)
      << r;
  params = s.params();
  params["w_light"] = 1;
  r = run_paint(s.picture + " " + write_params(s, params, "light.json") + " " + s.dir + "/x.png");
  EXPECT_NE(r.find("light.json: w_light is given without painting_light"), std::string::npos) << r;
  params["painting_light"] = "rows";
  r = run_paint(s.picture + " " + write_params(s, params, "rows.json") + " " + s.dir + "/x.png");
  EXPECT_NE(r.find("rows.json.painting_light: \"rows\" is no light"), std::string::npos) << r;
  params["painting_light"] = s.dir + "/small-light.png";
  write_image(std::vector<uint8_t>(10 * 10, 100), 10, 10, 1, {"PNG", {}},
              s.dir + "/small-light.png");
  r = run_paint(s.picture + " " + write_params(s, params, "size.json") + " " + s.dir + "/x.png");
  EXPECT_NE(r.find("size.json.painting_light: " + s.dir +
                   "/small-light.png: the light image is 10 x 10, the painting 128 x 96"),
            std::string::npos)
      << r;
  EXPECT_NE(r.find("exit 1"), std::string::npos) << r;
  params = s.params();
  params["sky_class"] = 2;
  params["exclude_classes"] = {2};
  r = run_paint(s.picture + " " + write_params(s, params, "sky.json") + " " + s.dir + "/x.png");
  EXPECT_NE(r.find("sky.json.sky_class: class 2 is in exclude_classes"), std::string::npos) << r;
  params = s.params();
  params["w_distance"] = -1;
  r = run_paint(s.picture + " " + write_params(s, params, "neg.json") + " " + s.dir + "/x.png");
  EXPECT_NE(r.find("w_distance"), std::string::npos) << r;
  // Guides of another size than the picture's; guides rendered before the shading band.
  const std::vector<uint8_t> small(3 * 10 * 10, 100);
  write_image(small, 10, 10, 3, {"PNG", {}}, s.dir + "/small.png");
  std::filesystem::copy_file(s.dir + "/pano-guides.tif", s.dir + "/small-guides.tif");
  r = run_paint(s.dir + "/small.png " + good + " " + s.dir + "/x.png");
  EXPECT_NE(r.find("small-guides.tif: the guides are 320 x 200 pixels"), std::string::npos) << r;
  std::filesystem::copy_file(s.picture, s.dir + "/old.png");
  test::shell_output("gdal_translate -q -b 1 -b 2 -b 3 -b 4 -b 5 " + s.dir + "/pano-guides.tif " +
                     s.dir + "/old-guides.tif");
  r = run_paint(s.dir + "/old.png " + good + " " + s.dir + "/x.png");
  EXPECT_NE(r.find("old-guides.tif: no band 'shading'"), std::string::npos) << r;
  params = s.params();
  params["shading"] = 0;  // without the blend, the old guides serve
  r = run_paint(s.dir + "/old.png " + write_params(s, params, "flat.json") + " " + s.dir +
                "/old-painted.png");
  EXPECT_NE(r.find("exit 0"), std::string::npos) << r;
  r = run_paint(s.dir + "/missing.png " + good + " " + s.dir + "/x.png");
  EXPECT_NE(r.find("missing.png: GDAL cannot open the panorama"), std::string::npos) << r;
  EXPECT_NE(r.find("exit 1"), std::string::npos) << r;
  std::ifstream written(s.dir + "/x.png");
  EXPECT_FALSE(written.good());  // nothing written on failure
}

}  // namespace
}  // namespace maquette::synthesis
