// Several paintings searched at once (issue 18): two synthetic paintings with a known colour cast
// per label, their classes numbered differently and each with its own exclusions. After
// harmonization each label's CIELAB statistics (OpenCV's conversion, not the module's) match the
// first painting's; the output draws from both; every output pixel's colour is its source
// painting pixel's colour harmonized as an independent Reinhard transfer computed here with
// OpenCV; tiles equal the whole image; no excluded pixel of either painting is copied; bad params
// are named with the exemplar's index, the field and the value. And The Starry Night beside
// Bruegel's Harvesters when scripts/setup.sh has fetched it.
#include <gdal_priv.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <map>
#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

#include "../../texture/colour.h"
#include "../combined_exemplar.h"
#include "../synthesis.h"
#include "../transfer_exemplar.h"
#include "../transfer_params.h"
#include "core/error.h"
#include "run_cli.h"
#include "runtime/params_schema.h"
#include "synthetic_raster.h"

namespace maquette::synthesis {
namespace {

using nlohmann::json;

// The first painting: 96 x 80, class 0 left of column 48, class 1 right of it, class 2 (excluded
// by class) from row 72. The second: 80 x 96, class 5 above row 48, class 7 below it, class 9 (no
// table entry: never copied) from column 72, rows 0..7 excluded by a mask. Its class 5 serves the
// first's class 0, 7 the first's 1, with another mean and spread per channel (the cast).
constexpr int kWa = 96, kHa = 80, kWb = 80, kHb = 96;

int class_a(int x, int y) { return y >= 72 ? 2 : x < 48 ? 0 : 1; }
int class_b(int x, int y) { return x >= 72 ? 9 : y < 48 ? 5 : 7; }
bool excluded_b(int x, int y) { return y < 8 || class_b(x, y) == 9; }

// Deterministic noise in [-1, 1] with some structure (strokes along the rows).
double noise(int x, int y, int k) {
  const uint32_t h = uint32_t(x) * 73856093u ^ uint32_t(y) * 19349663u ^ uint32_t(k) * 83492791u;
  return 0.6 * std::sin(0.45 * x + 1.7 * k + 0.2 * y) + 0.4 * (double(h % 1001) / 500.0 - 1.0);
}

// A class's colours: per channel a mean and the noise's amplitude, the noise drawn with
// channels `seed`, `seed` + 1, `seed` + 2.
struct Palette {
  std::array<double, 3> mean, amplitude;
  int seed;
};

std::array<double, 3> painted(const Palette& p, int x, int y) {
  std::array<double, 3> out{};
  for (int c = 0; c < 3; ++c)
    out[size_t(c)] = p.mean[size_t(c)] + p.amplitude[size_t(c)] * noise(x, y, p.seed + c);
  return out;
}

std::array<double, 3> colour_a(int x, int y) {
  const int c = class_a(x, y);
  if (c == 2) return {250, 0, 250};
  return painted(
      c == 0 ? Palette{{90, 130, 70}, {40, 30, 20}, 0} : Palette{{150, 110, 80}, {30, 25, 15}, 3},
      x, y);
}

std::array<double, 3> colour_b(int x, int y) {
  if (y < 8) return {255, 255, 0};
  const int c = class_b(x, y);
  if (c == 9) return {0, 255, 255};
  return painted(
      c == 5 ? Palette{{60, 150, 120}, {25, 45, 30}, 6} : Palette{{190, 80, 120}, {20, 15, 10}, 9},
      x, y);
}

// The two paintings' params through synthesis.transfer's schema (defaults filled).
json two_paintings(const std::string& harmonize) {
  const std::string a =
      test::write_png(test::temp_dir() + "/a.png", kWa, kHa, 3,
                      [](int x, int y, int b) { return colour_a(x, y)[size_t(b)]; });
  const std::string b =
      test::write_png(test::temp_dir() + "/b.png", kWb, kHb, 3,
                      [](int x, int y, int c) { return colour_b(x, y)[size_t(c)]; });
  const json params = {
      {"painting", a},
      {"labels", test::write_png(test::temp_dir() + "/a-classes.png", kWa, kHa, 1,
                                 [](int x, int y, int) { return class_a(x, y); })},
      {"exclude_classes", {2}},
      {"landcover_classes", {{"10", 0}, {"20", 1}}},
      {"exemplar_scale", 1},
      {"harmonize", harmonize},
      {"exemplars",
       {{{"painting", b},
         {"labels", test::write_png(test::temp_dir() + "/b-classes.png", kWb, kHb, 1,
                                    [](int x, int y, int) { return class_b(x, y); })},
         {"exclusion", test::write_png(test::temp_dir() + "/b-mask.png", kWb, kHb, 1,
                                       [](int, int y, int) { return y < 8 ? 255 : 0; })},
         {"landcover_classes", {{"10", 5}, {"20", 7}}}}}}};
  return validate_params(transfer_params_schema(), params, "test");
}

// The CIELAB colour (OpenCV's float conversion) of an sRGB colour 0..255, and back (clamped).
cv::Vec3f lab(const std::array<double, 3>& rgb) {
  cv::Mat in(1, 1, CV_32FC3, cv::Scalar(rgb[0] / 255, rgb[1] / 255, rgb[2] / 255)), out;
  cv::cvtColor(in, out, cv::COLOR_RGB2Lab);
  return out.at<cv::Vec3f>(0, 0);
}
std::array<double, 3> rgb(const cv::Vec3f& lab) {
  cv::Mat in(1, 1, CV_32FC3, cv::Scalar(lab[0], lab[1], lab[2])), out;
  cv::cvtColor(in, out, cv::COLOR_Lab2RGB);
  const cv::Vec3f v = out.at<cv::Vec3f>(0, 0);
  return {std::clamp(v[0] * 255.0, 0.0, 255.0), std::clamp(v[1] * 255.0, 0.0, 255.0),
          std::clamp(v[2] * 255.0, 0.0, 255.0)};
}

// Per channel mean and population standard deviation.
std::array<std::array<double, 2>, 3> stats(const std::vector<cv::Vec3f>& v) {
  std::array<std::array<double, 2>, 3> out{};
  for (int c = 0; c < 3; ++c) {
    double sum = 0, sum2 = 0;
    for (const auto& p : v) sum += p[c];
    const double mean = sum / double(v.size());
    for (const auto& p : v) sum2 += (p[c] - mean) * (p[c] - mean);
    out[size_t(c)] = {mean, std::sqrt(sum2 / double(v.size()))};
  }
  return out;
}

// The CIELAB colours of painting `part`'s allowed pixels of combined label `label`, as the
// exemplar holds them (harmonized), by OpenCV.
std::vector<cv::Vec3f> exemplar_lab(const TransferExemplar& t, int part, uint8_t label) {
  const ExemplarLevel& e = t.pyramid.levels[0];
  std::vector<cv::Vec3f> out;
  for (const int32_t i : e.by_label[label])
    if (t.source_of(i).exemplar == part) {
      const size_t s = size_t(i);
      out.push_back(
          lab({e.rgb[3 * s] * 255.0, e.rgb[3 * s + 1] * 255.0, e.rgb[3 * s + 2] * 255.0}));
    }
  return out;
}

// The target: class 10 (the first's 0) left, 20 (its 1) right, a band of unknown labels between
// them (it may take any class: no excluded pixel may come of it either).
constexpr PixelRect kWindow{1000, 2000, 96, 96};

TargetGuides target(const PixelRect& rect) {
  TargetGuides g;
  g.rect = rect;
  g.labels.resize(size_t(rect.width) * size_t(rect.height));
  for (int64_t r = 0; r < rect.height; ++r)
    for (int64_t c = 0; c < rect.width; ++c) {
      const int64_t x = rect.col0 + c - kWindow.col0;
      g.labels[size_t(r) * size_t(rect.width) + size_t(c)] = std::abs(x - 48) < 4 ? kUnknownLabel
                                                             : x < 48             ? 0
                                                                                  : 1;
    }
  return g;
}

std::vector<int32_t> synthesized(const TransferExemplar& t, const PixelRect& out) {
  const int h = synthesis_halo();
  return synthesize(t.pyramid,
                    target({out.col0 - h, out.row0 - h, out.width + 2 * h, out.height + 2 * h}), {},
                    out);
}

// The harmonization's way back from CIELAB (texture/colour.h's lab_to_srgb): OpenCV's float
// conversion's colour (clamped to 0..255) within 0.2 of 255 for CIELAB colours across the gamut
// and beyond it (OpenCV's sRGB curve is a spline: up to 0.09 apart measured), and srgb_to_lab's
// inverse within 1e-3 over a grid of sRGB colours (the matrices' 7 digits: up to 4.3e-4 measured).
TEST(Colour, LabToSrgbIsOpenCVsAndInvertsSrgbToLab) {
  double opencv = 0, round_trip = 0;  // the largest differences
  for (double l = 0; l <= 100; l += 10)
    for (double a = -80; a <= 80; a += 16)
      for (double b = -80; b <= 80; b += 16) {
        const std::array<double, 3> ours = texture::lab_to_srgb({l, a, b});
        const std::array<double, 3> theirs = rgb(cv::Vec3f{float(l), float(a), float(b)});
        for (size_t c = 0; c < 3; ++c) opencv = std::max(opencv, std::abs(ours[c] - theirs[c]));
      }
  for (int r = 0; r <= 255; r += 15)
    for (int g = 0; g <= 255; g += 15)
      for (int b = 0; b <= 255; b += 15) {
        const std::array<double, 3> back = texture::lab_to_srgb(texture::srgb_to_lab(r, g, b));
        const std::array<int, 3> given = {r, g, b};
        for (size_t c = 0; c < 3; ++c)
          round_trip = std::max(round_trip, std::abs(back[c] - given[c]));
      }
  std::printf("largest differences: OpenCV %.4f, round trip %.2e\n", opencv, round_trip);
  EXPECT_LT(opencv, 0.2);
  EXPECT_LT(round_trip, 1e-3);
}

TEST(MultiExemplar, ReinhardMatchesEachLabelsStatisticsToTheFirstPainting) {
  const auto none = transfer_exemplar(two_paintings("none"));
  const auto matched = transfer_exemplar(two_paintings("reinhard"));
  ASSERT_EQ(matched->parts.size(), 2u);
  for (const uint8_t label : {0, 1}) {
    const auto reference = stats(exemplar_lab(*matched, 0, label));
    const auto after = stats(exemplar_lab(*matched, 1, label));
    const auto before = stats(exemplar_lab(*none, 1, label));
    EXPECT_EQ(stats(exemplar_lab(*none, 0, label)), reference) << "the first painting changed";
    for (int c = 0; c < 3; ++c) {
      // Within 0.5 of a CIELAB unit (the module's D65 white and OpenCV's differ in the 5th digit,
      // and colours are kept as floats: no rounding).
      EXPECT_NEAR(after[size_t(c)][0], reference[size_t(c)][0], 0.5) << int(label) << " " << c;
      EXPECT_NEAR(after[size_t(c)][1], reference[size_t(c)][1], 0.5) << int(label) << " " << c;
    }
    // The cast is there without harmonization: some channel's mean is off by more than 5.
    double worst = 0;
    for (int c = 0; c < 3; ++c)
      worst = std::max(worst, std::abs(before[size_t(c)][0] - reference[size_t(c)][0]));
    EXPECT_GT(worst, 5.0) << int(label);
  }
}

TEST(MultiExemplar, HistogramMatchingMatchesEachLabelsQuantiles) {
  const auto matched = transfer_exemplar(two_paintings("histogram"));
  for (const uint8_t label : {0, 1}) {
    auto reference = exemplar_lab(*matched, 0, label), after = exemplar_lab(*matched, 1, label);
    for (int c = 0; c < 3; ++c) {
      const auto quantile = [c](std::vector<cv::Vec3f>& v, double q) {
        std::vector<double> x;
        for (const auto& p : v) x.push_back(p[c]);
        std::sort(x.begin(), x.end());
        return x[size_t(q * double(x.size() - 1))];
      };
      // Deciles within 1 CIELAB unit (the quantile steps of about 3,000 pixels, the round trip
      // through sRGB moving the other channels a little).
      for (const double q : {0.1, 0.25, 0.5, 0.75, 0.9})
        EXPECT_NEAR(quantile(after, q), quantile(reference, q), 1.0)
            << int(label) << " channel " << c << " quantile " << q;
    }
  }
}

TEST(MultiExemplar, DrawsFromBothEachPixelItsHarmonizedSourcesColour) {
  const auto t = transfer_exemplar(two_paintings("reinhard"));
  const std::vector<int32_t> src = synthesized(*t, kWindow);
  // The Reinhard transfer computed here: each label's OpenCV CIELAB statistics of both paintings'
  // allowed pixels, read from the paintings' own colours (colour_a, colour_b as PNG bytes).
  std::map<int, std::vector<cv::Vec3f>> of_a, of_b;
  for (int y = 0; y < kHa; ++y)
    for (int x = 0; x < kWa; ++x)
      if (class_a(x, y) != 2) {
        auto c = colour_a(x, y);
        for (auto& v : c) v = double(std::clamp(std::lround(v), 0L, 255L));
        of_a[class_a(x, y)].push_back(lab(c));
      }
  for (int y = 0; y < kHb; ++y)
    for (int x = 0; x < kWb; ++x)
      if (!excluded_b(x, y)) {
        auto c = colour_b(x, y);
        for (auto& v : c) v = double(std::clamp(std::lround(v), 0L, 255L));
        of_b[class_b(x, y) == 5 ? 0 : 1].push_back(lab(c));
      }
  const ExemplarLevel& e = t->pyramid.levels[0];
  size_t from_b = 0, worst_pixel = 0;
  double worst = 0;
  for (size_t i = 0; i < src.size(); ++i) {
    const SourcePixel s = t->source_of(src[i]);
    std::array<double, 3> expected{};
    // Inside its painting (not the gap between the two), and not excluded there.
    ASSERT_TRUE(s.col >= 0 && s.row >= 0 && s.col < (s.exemplar == 0 ? kWa : kWb) &&
                s.row < (s.exemplar == 0 ? kHa : kHb))
        << "a pixel outside painting " << s.exemplar << " copied: " << s.col << " " << s.row;
    if (s.exemplar == 0) {
      ASSERT_NE(class_a(s.col, s.row), 2) << "an excluded pixel of the first painting copied";
      expected = colour_a(s.col, s.row);
      for (auto& v : expected) v = double(std::clamp(std::lround(v), 0L, 255L));
    } else {
      ASSERT_EQ(s.exemplar, 1);
      ASSERT_FALSE(excluded_b(s.col, s.row)) << "an excluded pixel of the second copied";
      ++from_b;
      auto c = colour_b(s.col, s.row);
      for (auto& v : c) v = double(std::clamp(std::lround(v), 0L, 255L));
      const int label = class_b(s.col, s.row) == 5 ? 0 : 1;
      const auto a = stats(of_a[label]), b = stats(of_b[label]);
      cv::Vec3f v = lab(c);
      for (int k = 0; k < 3; ++k)
        v[k] =
            float((v[k] - b[size_t(k)][0]) * a[size_t(k)][1] / b[size_t(k)][1] + a[size_t(k)][0]);
      expected = rgb(v);
    }
    for (int k = 0; k < 3; ++k) {
      const double d =
          std::abs(e.rgb[3 * size_t(src[i]) + size_t(k)] * 255.0 - expected[size_t(k)]);
      if (d > worst) worst = d, worst_pixel = i;
    }
  }
  // Every colour its source's (harmonized) within 1 of 255 (OpenCV's conversion against the
  // module's, floats on both sides).
  const SourcePixel at = t->source_of(src[worst_pixel]);
  EXPECT_LT(worst, 1.0) << "at output pixel " << worst_pixel << " from " << at.exemplar << " "
                        << at.col << " " << at.row;
  // Both paintings drawn from (their usable pixels are about equal: 3,456 and 2,880 of class 0,
  // 3,456 and 3,456 of class 1): each at least a fifth of the output.
  const double share_b = double(from_b) / double(src.size());
  EXPECT_GE(share_b, 0.2);
  EXPECT_LE(share_b, 0.8);
}

TEST(MultiExemplar, TilesEqualTheWholeImage) {
  const auto t = transfer_exemplar(two_paintings("reinhard"));
  const std::vector<int32_t> whole = synthesized(*t, kWindow);
  size_t differing = 0;
  for (int ty = 0; ty < 2; ++ty)
    for (int tx = 0; tx < 2; ++tx) {
      const PixelRect tile{kWindow.col0 + 48 * tx, kWindow.row0 + 48 * ty, 48, 48};
      const std::vector<int32_t> part = synthesized(*t, tile);
      for (int r = 0; r < 48; ++r)
        for (int c = 0; c < 48; ++c)
          differing += part[size_t(r) * 48 + size_t(c)] !=
                       whole[size_t(48 * ty + r) * size_t(kWindow.width) + size_t(48 * tx + c)];
    }
  EXPECT_EQ(differing, 0u);
}

TEST(MultiExemplar, SourceMapsBackToThePaintingPixel) {
  const auto t = transfer_exemplar(two_paintings("none"));
  ASSERT_EQ(t->parts.size(), 2u);
  // The second painting lies right of the first, past the gap, on the coarsest level's grid.
  EXPECT_GE(t->parts[1].x0, kWa + kCombinedGap);
  EXPECT_EQ(t->parts[1].x0 % (1 << (kLevels - 1)), 0);
  for (const auto& [part, col, row] : {std::array<int, 3>{0, 5, 7}, {1, 70, 90}, {0, 95, 79}}) {
    const int32_t s = t->pixel_of(part, col, row);
    ASSERT_GE(s, 0);
    const SourcePixel back = t->source_of(s);
    EXPECT_EQ(back.exemplar, part);
    EXPECT_EQ(back.col, col);
    EXPECT_EQ(back.row, row);
  }
  EXPECT_EQ(t->pixel_of(1, kWb, 0), -1);
  EXPECT_EQ(t->pixel_of(2, 0, 0), -1);
}

// No pyramid level lets a patch straddle the two paintings: at every level the columns between
// the first painting's last and the second's first are excluded on every row, and there are at
// least kCombinedGap >> level of them.
TEST(MultiExemplar, TheGapIsExcludedAtEveryLevel) {
  const auto t = transfer_exemplar(two_paintings("none"));
  ASSERT_EQ(t->parts.size(), 2u);
  for (size_t l = 0; l < t->pyramid.levels.size(); ++l) {
    const ExemplarLevel& e = t->pyramid.levels[l];
    const int a_end = (t->parts[0].width + (1 << l) - 1) >> l, b_begin = t->parts[1].x0 >> l;
    EXPECT_GE(b_begin - a_end, kCombinedGap >> l) << "level " << l;
    for (int y = 0; y < e.height; ++y)
      for (int x = a_end; x < b_begin; ++x)
        ASSERT_EQ(e.excluded[size_t(e.index(x, y))], 1) << "level " << l << " at " << x << " " << y;
  }
}

// A further painting's labels follow the first painting's table, not only its groups: two tables
// with the same groups, their classes swapped, are two exemplars (one cached analysis would give
// the second the first's labels).
TEST(MultiExemplar, AnotherFirstTableWithTheSameGroupsRelabelsTheFurtherPainting) {
  const json params = two_paintings("none");  // the same files for both
  json swapped = params;
  swapped["landcover_classes"] = {{"10", 1}, {"20", 0}};
  const auto t = transfer_exemplar(params), u = transfer_exemplar(swapped);
  // The second painting's (10, 20) is class 5, serving target value 10.
  const int32_t s = t->pixel_of(1, 10, 20);
  ASSERT_GE(s, 0);
  EXPECT_EQ(t->pyramid.levels[0].labels[size_t(s)], 0);
  EXPECT_EQ(u->pyramid.levels[0].labels[size_t(s)], 1);
}

// The message of the error `params` raise, validated then built.
std::string refusal(const json& params) {
  try {
    transfer_exemplar(validate_params(transfer_params_schema(), params, "step"));
  } catch (const Error& e) {
    return e.what();
  }
  return "accepted";
}

TEST(MultiExemplar, BadParamsNameTheExemplarTheFieldAndTheValue) {
  const json good = two_paintings("reinhard");
  const auto with = [&](const std::string& field, const json& value) {
    json p = good;
    p["exemplars"][0][field] = value;
    return refusal(p);
  };
  EXPECT_NE(with("painting", 3).find("params.exemplars[0].painting: expected a string, got 3"),
            std::string::npos);
  EXPECT_NE(with("colour", 1).find("params.exemplars[0]: unknown field 'colour'"),
            std::string::npos);
  const std::string unknown = with("landcover_classes", {{"30", 5}});
  EXPECT_NE(unknown.find("synthesis.transfer.exemplars[0].landcover_classes.30: target value 30 "
                         "is not in the first painting's landcover_classes"),
            std::string::npos)
      << unknown;
  const std::string twice = with("landcover_classes", {{"10", 5}, {"20", 5}});
  EXPECT_NE(twice.find("synthesis.transfer.exemplars[0].landcover_classes.20: painting class 5 "
                       "serves target values 10 and 20"),
            std::string::npos)
      << twice;
  // Class 8 is not in the second painting: it would serve target value 20 with nothing.
  const std::string absent = with("landcover_classes", {{"10", 5}, {"20", 8}});
  EXPECT_NE(absent.find("synthesis.transfer.exemplars[0].landcover_classes.20: painting class 8 "
                        "has no pixel to copy in " +
                        good["exemplars"][0]["painting"].get<std::string>() +
                        " (not in it, or excluded)"),
            std::string::npos)
      << absent;
  const std::string altitude = with("painting_altitude", "rows");
  EXPECT_NE(altitude.find("synthesis.transfer.exemplars[0].painting_altitude: given, but the "
                          "first painting has none"),
            std::string::npos)
      << altitude;
  json small = good;
  small["exemplars"].push_back(good["exemplars"][0]);
  small["exemplars"][1]["painting"] =
      test::write_png(test::temp_dir() + "/tiny.png", 4, 4, 3, [](int, int, int) { return 100; });
  const std::string tiny = refusal(small);
  EXPECT_NE(tiny.find("synthesis.transfer.exemplars[1].painting: "), std::string::npos) << tiny;
  EXPECT_NE(tiny.find("is 4 x 4 pixels"), std::string::npos) << tiny;
  // Two further paintings 33,000 pixels wide: side by side wider than a packed column allows.
  json wide = good;
  wide["exemplars"] = json::array();
  for (const char* name : {"wide1", "wide2"})
    wide["exemplars"].push_back(
        {{"painting", test::write_png(test::temp_dir() + "/" + name + ".png", 33000, 16, 3,
                                      [](int x, int, int b) { return (x * 7 + b * 50) % 256; })},
         {"labels", test::write_png(test::temp_dir() + "/" + name + "-classes.png", 33000, 16, 1,
                                    [](int, int, int) { return 5; })},
         {"landcover_classes", {{"10", 5}}}});
  const std::string too_wide = refusal(wide);
  EXPECT_NE(too_wide.find("synthesis.transfer: the exemplar is 66"), std::string::npos) << too_wide;
  EXPECT_NE(too_wide.find("at most 65535 x 32767"), std::string::npos) << too_wide;
  json harmonize = good;
  harmonize["harmonize"] = "mean";
  EXPECT_NE(refusal(harmonize).find("params.harmonize: \"mean\" is not one of"), std::string::npos)
      << refusal(harmonize);
}

TEST(MultiExemplar, StarryNightBesideTheHarvesters) {
  const std::string starry = std::string(MAQUETTE_BIN_DIR) + "/../demo-data/starry_night.jpg";
  if (!std::filesystem::exists(starry))
    GTEST_SKIP() << starry << " is absent: scripts/setup.sh fetches it (Debian's opencv-doc)";
  const std::string harvesters =
      std::string(MAQUETTE_SHARED_DIR) + "/data/painting/bruegel_the_harvesters_1565.png";
  if (!std::filesystem::exists(harvesters)) GTEST_SKIP() << "../shared/data is absent";
  const std::string repo = MAQUETTE_SOURCE_DIR;
  // The benchmark's classes (benchmarks/README.md): Bruegel's by hand, The Starry Night's by hand.
  const json params =
      validate_params(transfer_params_schema(),
                      {{"painting", harvesters},
                       {"labels", repo + "/examples/bruegel-harvesters-classes.geojson"},
                       {"exclude_classes", {0, 1}},
                       {"landcover_classes", {{"1", 4}, {"2", 6}, {"3", 2}, {"4", 4}, {"5", 3}}},
                       {"exemplar_scale", 4},
                       {"exemplars",
                        {{{"painting", starry},
                          {"labels", repo + "/examples/starry-night-classes.geojson"},
                          {"exclude_classes", {0, 1}},
                          {"landcover_classes", {{"2", 4}, {"3", 3}, {"4", 2}, {"5", 5}}}}}}},
                      "test");
  const auto t = transfer_exemplar(params);
  ASSERT_EQ(t->parts.size(), 2u);
  EXPECT_EQ(t->parts[1].width, 752 / 4);
  EXPECT_EQ(t->parts[1].height, 600 / 4);
  // Each class of The Starry Night's table has pixels of both paintings (buildings 6, wheat 2,
  // trees 4, stubble 3); its sky and frame, excluded, are never copied.
  std::map<uint8_t, std::array<size_t, 2>> count;
  const ExemplarLevel& e = t->pyramid.levels[0];
  for (const int32_t i : e.allowed) ++count[e.labels[size_t(i)]][size_t(t->source_of(i).exemplar)];
  for (const uint8_t label : {2, 3, 4, 6}) {
    EXPECT_GT(count[label][0], 0u) << int(label);
    EXPECT_GT(count[label][1], 0u) << int(label);
  }
  for (const auto& [label, n] : count)
    EXPECT_TRUE(n[1] == 0 || label == 2 || label == 3 || label == 4 || label == 6) << int(label);
}

}  // namespace
}  // namespace maquette::synthesis
