// The painting's masks from its guides (painting_guides.h: maquette-paint's painting_guides,
// labels and painting_distance "guides"), on panorama_scene.h's scene without relief. The
// oracle: the painting is the scene's panorama rendered from one camera (its picture the
// painting, its guides file the painting's guides), the target a panorama of the same scene
// from another camera. Checked: terrain sources whose land cover (read from the painting's
// guides) is the target pixel's (>= 0.97), none on the painting's sky without sky_class, the
// target's sky from the painting's sky with it; the distance mismatch lower with w_distance than
// without; the mappings by hand; the cache key and files; the program's bytes for threads and
// tiles; bad input named.
#include <gdal_priv.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>

#include "../painting_guides.h"
#include "core/error.h"
#include "panorama_scene.h"

namespace maquette::synthesis {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

// The scene, and its panorama from a second camera (farther east, higher, turned left): the
// target.
struct TwoViews {
  Scene scene;
  std::string target = scene.dir + "/other.png";
  TwoViews() {
    const std::string args = "render panorama " + scene.dir + "/s.mqt " + target +
                             " --dem dem --land-cover lc --camera 10.17 45.04 1900 --heading -8 "
                             "--pitch -8 --fov 44 --size 320 200";
    const auto r = test::run_maquette(args);
    EXPECT_EQ(r.exit_code, 0) << args << "\n" << r.err;
  }
  // The scene's panorama as the painting, its masks from its guides.
  nlohmann::json params() const {
    return {{"painting", scene.picture},
            {"painting_guides", scene.dir + "/pano-guides.tif"},
            {"labels", "guides"},
            {"painting_distance", "guides"},
            {"distance_range", {2000, 30000}},
            {"exemplar_scale", 1},
            {"landcover_classes", {{"41", 1}, {"52", 0}}},
            {"tile", 128}};
  }
};

const TwoViews& views() {
  static const TwoViews v;
  return v;
}

PaintedPanorama paint_target(const nlohmann::json& raw) {
  const PaintParams params = paint_params(raw, "params.json");
  return paint_panorama(read_panorama(views().target, true), *transfer_exemplar(params.exemplar),
                        params);
}

TEST(PaintingGuides, MappingsByHand) {
  const std::map<int, uint8_t> table = {{41, 1}, {52, 0}};
  EXPECT_EQ(picture_class(table, std::nullopt, 41, 5000), 1);
  EXPECT_EQ(picture_class(table, std::nullopt, 52, 5000), 0);
  EXPECT_EQ(picture_class(table, std::nullopt, 99, 5000), kUnknownLabel);    // not in the table
  EXPECT_EQ(picture_class(table, uint8_t(2), kNaN, 5000), kUnknownLabel);    // terrain, no cover
  EXPECT_EQ(picture_class(table, std::nullopt, kNaN, kNaN), kUnknownLabel);  // the sky
  EXPECT_EQ(picture_class(table, uint8_t(2), kNaN, kNaN), 2);
  // Logarithmic: the geometric mean of 2 and 30 km is halfway.
  const std::array<double, 2> near_far = {2000, 30000};
  EXPECT_FLOAT_EQ(picture_distance(kNaN, near_far), 1);
  EXPECT_FLOAT_EQ(picture_distance(1000, near_far), 0);
  EXPECT_FLOAT_EQ(picture_distance(2000, near_far), 0);
  EXPECT_NEAR(picture_distance(float(std::sqrt(2000.0 * 30000.0)), near_far), 0.5, 1e-6);
  EXPECT_FLOAT_EQ(picture_distance(60000, near_far), 1);
  const std::array<double, 2> low_high = {100, 700};
  EXPECT_FLOAT_EQ(painting_altitude(kNaN, low_high), 1);
  EXPECT_FLOAT_EQ(painting_altitude(50, low_high), 0);
  EXPECT_FLOAT_EQ(painting_altitude(400, low_high), 0.5);
  EXPECT_FLOAT_EQ(painting_altitude(1000, low_high), 1);
}

TEST(PaintingGuides, MasksFromAGuidesFileByHand) {
  // 3 x 2 pixels: forest near, shrub far, a land cover the table lacks; the sky, shrub at the
  // near end of the range, forest at the geometric mean.
  const std::string dir = test::temp_dir(), path = dir + "/g.tif";
  const std::vector<float> land_cover = {41, 52, 90, kNaN, 52, 41},
                           distance = {2000, 30000, 5000, kNaN, 1000, 7745.967f},
                           altitude = {100, 700, 400, kNaN, 250, 1000};
  {
    GDALAllRegister();
    std::unique_ptr<GDALDataset> ds(GetGDALDriverManager()->GetDriverByName("GTiff")->Create(
        path.c_str(), 3, 2, 3, GDT_Float64, nullptr));
    ASSERT_TRUE(ds);
    const std::pair<const char*, const std::vector<float>*> bands[] = {
        {"distance", &distance}, {"land_cover", &land_cover}, {"altitude", &altitude}};
    for (int b = 0; b < 3; ++b) {
      GDALRasterBand* band = ds->GetRasterBand(b + 1);
      band->SetDescription(bands[b].first);
      ASSERT_EQ(band->RasterIO(GF_Write, 0, 0, 3, 2, const_cast<float*>(bands[b].second->data()), 3,
                               2, GDT_Float32, 0, 0),
                CE_None);
    }
  }
  nlohmann::json fields = {{"painting", "painting.png"},
                           {"painting_guides", path},
                           {"labels", "guides"},
                           {"painting_altitude", "guides"},
                           {"altitude_range", {100, 700}},
                           {"painting_distance", "guides"},
                           {"distance_range", {2000, 30000}},
                           {"landcover_classes", {{"41", 1}, {"52", 0}}}};
  GuidedMasks m = guided_masks(fields, "p.json", 3, 2);
  EXPECT_EQ(m.labels, (std::vector<uint8_t>{1, 0, kUnknownLabel, kUnknownLabel, 0, 1}));
  const std::vector<float> far = {0, 1, float(std::log(2.5) / std::log(15.0)), 1, 0, 0.5f},
                           high = {0, 1, 0.5f, 1, 0.25f, 1};
  ASSERT_EQ(m.distance.size(), 6u);
  ASSERT_EQ(m.altitude.size(), 6u);
  for (size_t i = 0; i < 6; ++i) {
    EXPECT_NEAR(m.distance[i], far[i], 1e-6) << i;
    EXPECT_FLOAT_EQ(m.altitude[i], high[i]) << i;
  }
  fields["sky_class"] = 2;
  fields.erase("painting_altitude");
  m = guided_masks(fields, "p.json", 3, 2);
  EXPECT_EQ(m.labels, (std::vector<uint8_t>{1, 0, kUnknownLabel, 2, 0, 1}));
  EXPECT_TRUE(m.altitude.empty());  // not "guides": not made
  try {
    guided_masks(fields, "p.json", 4, 2);
    ADD_FAILURE() << "a painting of another size than its guides, and it ran";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), "p.json.painting_guides: " + path +
                                         ": the guides are 3 x 2 pixels, the painting "
                                         "painting.png 4 x 2");
  }
}

TEST(PaintingGuides, TheCacheKeysTheGuidesFileAndWhatMapsIt) {
  nlohmann::json params = paint_params(views().params(), "p.json").exemplar;
  EXPECT_EQ(
      exemplar_input_files(params),
      (std::vector<std::string>{views().scene.picture, views().scene.dir + "/pano-guides.tif"}));
  const nlohmann::json key = exemplar_key_params(params);
  EXPECT_EQ(key.at("painting_guides"), views().scene.dir + "/pano-guides.tif");
  EXPECT_EQ(key.at("guided"), (nlohmann::json{{"landcover_classes", {{"41", 1}, {"52", 0}}},
                                              {"distance_range", {2000, 30000}}}));
  // The sky's class is a class of the guided labels: another exemplar.
  nlohmann::json with_sky = views().params();
  with_sky["sky_class"] = 2;
  EXPECT_EQ(
      exemplar_key_params(paint_params(with_sky, "p.json").exemplar).at("guided").at("sky_class"),
      2);
  // The hand-made masks' params keep their key (no "guided").
  EXPECT_FALSE(exemplar_key_params(paint_params(views().scene.params(), "p.json").exemplar)
                   .contains("guided"));
}

TEST(PaintingGuides, TerrainTakesTheTargetsLandCoverNeverTheSky) {
  const PanoramaPicture target = read_panorama(views().target, true);
  const PanoramaPicture painting = read_panorama(views().scene.picture, false);  // its guides
  const PaintedPanorama p = paint_target(views().params());
  size_t terrain = 0, kept = 0, from_sky = 0, sky_painted = 0;
  for (size_t i = 0; i < target.distance.size(); ++i) {
    const auto [x, y] = source_of(p, i);
    if (std::isnan(target.distance[i])) {
      sky_painted += x >= 0;
      continue;
    }
    ASSERT_GE(x, 0) << i;
    ++terrain;
    const size_t s = size_t(y) * size_t(painting.width) + size_t(x);
    from_sky += std::isnan(painting.distance[s]);
    kept += painting.land_cover[s] == target.land_cover[i];
  }
  std::printf(
      "%zu terrain pixels, %zu of their sources of the target's land cover, %zu on the "
      "painting's sky; %zu sky pixels painted\n",
      terrain, kept, from_sky, sky_painted);
  ASSERT_GT(terrain, 20000u);
  EXPECT_EQ(from_sky, 0u);
  EXPECT_EQ(sky_painted, 0u);
  EXPECT_GE(double(kept) / double(terrain), 0.97) << kept << " of " << terrain;
}

TEST(PaintingGuides, TheSkyFromThePaintingsSkyWithASkyClass) {
  const PanoramaPicture target = read_panorama(views().target, true);
  const PanoramaPicture painting = read_panorama(views().scene.picture, false);
  nlohmann::json params = views().params();
  params["sky_class"] = 2;
  const PaintedPanorama p = paint_target(params);
  size_t sky = 0, from_sky = 0, terrain_from_sky = 0;
  for (size_t i = 0; i < target.distance.size(); ++i) {
    const auto [x, y] = source_of(p, i);
    ASSERT_GE(x, 0) << i;
    const bool source_sky =
        std::isnan(painting.distance[size_t(y) * size_t(painting.width) + size_t(x)]);
    if (std::isnan(target.distance[i]))
      ++sky, from_sky += source_sky;
    else
      terrain_from_sky += source_sky;
  }
  std::printf("%zu of %zu sky pixels from the painting's sky, %zu terrain pixels\n", from_sky, sky,
              terrain_from_sky);
  ASSERT_GT(sky, 5000u);
  EXPECT_GE(double(from_sky) / double(sky), 0.97) << from_sky << " of " << sky;
  EXPECT_LE(terrain_from_sky, 50u);
}

TEST(PaintingGuides, TheDistanceWeightLowersTheDistanceMismatch) {
  const PanoramaPicture target = read_panorama(views().target, true);
  const PanoramaPicture painting = read_panorama(views().scene.picture, false);
  const std::array<double, 2> range = {2000, 30000};
  std::vector<double> mismatch;
  for (const double w : {0.0, 2.0}) {
    nlohmann::json params = views().params();
    params["w_distance"] = w;
    const PaintedPanorama p = paint_target(params);
    double sum = 0;
    size_t n = 0;
    for (size_t i = 0; i < target.distance.size(); ++i) {
      if (std::isnan(target.distance[i])) continue;
      const auto [x, y] = source_of(p, i);
      const float source = painting.distance[size_t(y) * size_t(painting.width) + size_t(x)];
      sum +=
          std::abs(picture_distance(target.distance[i], range) - picture_distance(source, range));
      ++n;
    }
    mismatch.push_back(sum / double(n));
    std::printf("w_distance %g: mean distance mismatch %.4f\n", w, mismatch.back());
  }
  EXPECT_LT(mismatch[1], 0.5 * mismatch[0]);
}

TEST(PaintingGuides, TheProgramWritesTheSameBytesForThreadsAndTiles) {
  const Scene& s = views().scene;
  nlohmann::json params = views().params();
  params["sky_class"] = 2;
  std::vector<std::string> runs;
  for (const auto& [tile, threads] : {std::pair{256, 1}, std::pair{64, 2}}) {
    params["tile"] = tile;
    const std::string out = s.dir + "/guided-" + std::to_string(tile) + ".png";
    const std::string r = run_paint(views().target + " " + write_params(s, params, "g.json") + " " +
                                    out + " -t " + std::to_string(threads));
    ASSERT_NE(r.find("exit 0"), std::string::npos) << r;
    ASSERT_FALSE(test::file_fingerprint(out).empty());
    runs.push_back(
        test::file_fingerprint(out) + " " +
        test::file_fingerprint(s.dir + "/guided-" + std::to_string(tile) + "-source.tif"));
  }
  EXPECT_EQ(runs[0], runs[1]);
}

TEST(PaintingGuides, BadInputIsNamed) {
  const Scene& s = views().scene;
  const std::string out = s.dir + "/x.png";
  const auto run = [&](const nlohmann::json& params, const std::string& name) {
    return run_paint(views().target + " " + write_params(s, params, name) + " " + out);
  };
  // Guides of another size than the painting.
  test::shell_output("gdal_translate -q -srcwin 0 0 100 80 " + s.dir + "/pano-guides.tif " + s.dir +
                     "/cut-guides.tif");
  nlohmann::json params = views().params();
  params["painting_guides"] = s.dir + "/cut-guides.tif";
  std::string r = run(params, "cut.json");
  EXPECT_NE(r.find("cut.json.painting_guides: " + s.dir +
                   "/cut-guides.tif: the guides are 100 x 80 pixels, the painting " + s.picture +
                   " 320 x 200"),
            std::string::npos)
      << r;
  EXPECT_NE(r.find("exit 1"), std::string::npos) << r;
  // Guides rendered without --land-cover, for labels "guides".
  params["painting_guides"] = s.dir + "/bare-guides.tif";
  r = run(params, "bare.json");
  EXPECT_NE(r.find("bare-guides.tif: no band 'land_cover' (render them with --land-cover)"),
            std::string::npos)
      << r;
  params.erase("painting_guides");
  r = run(params, "none.json");
  EXPECT_NE(r.find("none.json.labels: \"guides\" is given without painting_guides"),
            std::string::npos)
      << r;
  params = views().params();
  params["labels"] = s.dir + "/labels.png";  // the scene's hand-made class image
  params["painting"] = s.dir + "/painting.png";
  params["painting_distance"] = "rows";
  r = run(params, "unused.json");
  EXPECT_NE(r.find("unused.json.painting_guides: given, but none of labels, painting_altitude and "
                   "painting_distance is \"guides\""),
            std::string::npos)
      << r;
  params = views().params();
  params["painting_altitude"] = "guides";
  r = run(params, "altitude.json");
  EXPECT_NE(r.find("altitude.json: painting_altitude is given without altitude_range"),
            std::string::npos)
      << r;
  // The guides are an input: not overwritten by the output.
  r = run_paint(views().target + " " + write_params(s, views().params(), "good.json") + " " +
                s.dir + "/pano-guides.tif");
  EXPECT_NE(r.find("is the painting's guides"), std::string::npos) << r;
  EXPECT_NE(r.find("exit 1"), std::string::npos) << r;
  // OUT is a picture: PNG or JPEG by its extension (other names got PNG bytes, exit 0).
  r = run_paint(views().target + " " + write_params(s, views().params(), "good.json") + " " +
                s.dir + "/painted.tif");
  EXPECT_NE(r.find("painted.tif: a panorama is written as PNG (.png) or JPEG (.jpg, .jpeg), not "
                   "'.tif'"),
            std::string::npos)
      << r;
  EXPECT_FALSE(std::ifstream(s.dir + "/painted.tif"));
  // A write that fails (files limited to 200 KiB: the picture fits, its source does not) fails
  // the run and leaves neither file (GDAL said it only while closing the source: exit 0, the
  // source cut short, an audit's find).
  r = test::shell_output("(trap '' XFSZ; ulimit -f 200; " + std::string(MAQUETTE_BIN_DIR) +
                         "/maquette-paint " + views().target + " " +
                         write_params(s, views().params(), "good.json") + " " + s.dir +
                         "/limited.png 2>&1; echo \"exit $?\")");
  EXPECT_NE(r.find("limited-source.tif: GDAL cannot write it: "), std::string::npos) << r;
  EXPECT_NE(r.find("exit 1"), std::string::npos) << r;
  EXPECT_FALSE(std::ifstream(s.dir + "/limited.png"));
  EXPECT_FALSE(std::ifstream(s.dir + "/limited-source.tif"));
  // --help says what each argument is, and exits 0.
  r = run_paint("--help");
  EXPECT_NE(r.find("PANORAMA-guides.tif"), std::string::npos) << r;
  EXPECT_NE(r.find("exit 0"), std::string::npos) << r;
  std::ifstream written(out);
  EXPECT_FALSE(written.good());  // nothing written on failure
}

}  // namespace
}  // namespace maquette::synthesis
