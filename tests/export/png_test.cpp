// export png, decoded with OpenCV: class colours, hillshade, the 2-98 % stretch of imagery, the
// hypsometric tints of heights and the legend.
#include <gtest/gtest.h>

#include <map>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <set>

#include "export_fixture.h"

namespace maquette::test {
namespace {

cv::Mat export_png(const std::string& layer, const std::string& extra = "--no-legend") {
  return cv::imread(export_layer("png", layer, "png", extra), cv::IMREAD_UNCHANGED);
}

// Opaque pixels as RGB triples, with their counts.
std::map<std::array<int, 3>, int> colours(const cv::Mat& png) {
  std::map<std::array<int, 3>, int> out;
  for (int r = 0; r < png.rows; ++r)
    for (int c = 0; c < png.cols; ++c)
      if (const auto& p = png.at<cv::Vec4b>(r, c); p[3] == 255) ++out[{p[2], p[1], p[0]}];
  return out;
}

TEST(Png, LandcoverUsesExactlyTheClassColours) {
  const cv::Mat png = export_png("landcover");
  ASSERT_EQ(png.type(), CV_8UC4);
  const std::set<std::array<int, 3>> expected = {
      {0x22, 0x8b, 0x22}, {0x1e, 0x90, 0xff}, {0xff, 0x00, 0x00}};
  std::set<std::array<int, 3>> seen;
  for (const auto& [rgb, count] : colours(png)) seen.insert(rgb);
  EXPECT_EQ(seen, expected);
}

TEST(Png, HillshadeChangesTheDemPicture) {
  const cv::Mat plain = export_png("dem"), shaded = export_png("dem", "--hillshade --no-legend");
  ASSERT_FALSE(plain.empty());
  ASSERT_EQ(plain.size(), shaded.size());
  EXPECT_GT(cv::norm(plain, shaded, cv::NORM_L1), 0.0);
  // Shading only darkens the ramp.
  const auto a = colours(plain), b = colours(shaded);
  EXPECT_EQ(a.size() > 1, true);
  int darker = 0, total = 0;
  for (int r = 0; r < plain.rows; ++r)
    for (int c = 0; c < plain.cols; ++c) {
      const auto p = plain.at<cv::Vec4b>(r, c), s = shaded.at<cv::Vec4b>(r, c);
      if (p[3] != 255) continue;
      ++total;
      darker += s[0] <= p[0] && s[1] <= p[1] && s[2] <= p[2];
    }
  EXPECT_EQ(darker, total);
}

// Fraction of opaque pixels whose channel k equals v.
double fraction(const cv::Mat& png, int k, int v) {
  int hit = 0, total = 0;
  for (int r = 0; r < png.rows; ++r)
    for (int c = 0; c < png.cols; ++c)
      if (const auto& p = png.at<cv::Vec4b>(r, c); p[3] == 255) ++total, hit += p[k] == v;
  return double(hit) / total;
}

TEST(Png, ImageryIsStretchedTwoToNinetyEightPercentPerBand) {
  const cv::Mat png = export_png("rgb");
  ASSERT_EQ(png.type(), CV_8UC4);
  for (int k = 0; k < 3; ++k) {
    // Roughly 2 % of the samples lie at or below the 2nd percentile, 2 % at or above the 98th.
    EXPECT_NEAR(fraction(png, k, 0), 0.025, 0.015) << k;
    EXPECT_NEAR(fraction(png, k, 255), 0.025, 0.015) << k;
  }
  // --bands picks which channels are drawn: 3,2,1 swaps red and blue.
  const cv::Mat swapped = export_png("rgb", "--bands 3,2,1 --no-legend");
  cv::Mat a[4], b[4];
  cv::split(png, a);
  cv::split(swapped, b);
  EXPECT_EQ(cv::norm(a[0], b[2], cv::NORM_L1), 0.0);
  EXPECT_EQ(cv::norm(a[2], b[0], cv::NORM_L1), 0.0);
}

// Rows [first, last) of a PNG whose pixels are all opaque and hold `rgb` somewhere.
bool margin_has(const cv::Mat& png, int first, const std::array<int, 3>& rgb) {
  for (int r = first; r < png.rows; ++r)
    for (int c = 0; c < png.cols; ++c)
      if (const auto& p = png.at<cv::Vec4b>(r, c);
          p[3] == 255 && p[2] == rgb[0] && p[1] == rgb[1] && p[0] == rgb[2])
        return true;
  return false;
}

TEST(Png, LegendGoesBelowTheUnchangedMap) {
  for (const char* layer : {"dem", "landcover"}) {
    const cv::Mat plain = export_png(layer), legend = export_png(layer, "");
    ASSERT_GT(legend.rows, plain.rows) << layer;
    ASSERT_GE(legend.cols, plain.cols) << layer;
    EXPECT_EQ(cv::norm(plain, legend(cv::Rect(0, 0, plain.cols, plain.rows)), cv::NORM_L1), 0.0)
        << layer;
    // White paper and dark ink (tick labels, names) in the margin.
    EXPECT_TRUE(margin_has(legend, plain.rows, {255, 255, 255})) << layer;
    EXPECT_TRUE(margin_has(legend, plain.rows, {30, 30, 30})) << layer;
  }
  // Land cover: a swatch of each class colour.
  const cv::Mat lc = export_png("landcover", ""), map = export_png("landcover");
  for (const auto& rgb :
       {std::array<int, 3>{0x22, 0x8b, 0x22}, std::array<int, 3>{0x1e, 0x90, 0xff},
        std::array<int, 3>{0xff, 0x00, 0x00}})
    EXPECT_TRUE(margin_has(lc, map.rows, rgb));
}

}  // namespace
}  // namespace maquette::test
