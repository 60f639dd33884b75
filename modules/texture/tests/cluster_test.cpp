// texture.cluster: a Gaussian mixture recovers a known mixture, k chosen automatically finds the
// true number of well-separated clusters (hue-saturation and hue-saturation-value), the density
// plot read back with GDAL, same bits twice and with 1 or 2 threads through the runner, and
// errors naming the parameter.
#include <gdal_priv.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "../colour_clusters.h"
#include "../hs_classes.h"
#include "../hs_plot.h"
#include "runtime/pipeline.h"
#include "runtime/runner.h"
#include "texture_module.h"

namespace maquette::texture {
namespace {

using namespace texture_test;
namespace fs = std::filesystem;

// An axis-aligned Gaussian in colour-wheel coordinates (s cos h, s sin h, v).
struct Blob {
  double weight;
  Point mean;
  Point sd;
};

Point at(double hue, double saturation, double value = 0) {
  const auto xy = wheel(hue, saturation);
  return {xy[0], xy[1], value};
}

// The expected histogram of `pixels` pixels drawn from the blobs: the density integrated over
// each bin (a polar sector [x value range]) by the midpoint rule on 8 x 8 [x 4] sub-cells.
std::vector<uint64_t> histogram_of(const std::vector<Blob>& blobs, ColourSpace space,
                                   double pixels) {
  const bool hsv = space == ColourSpace::Hsv;
  const int dims = hsv ? 3 : 2, sub = 8, sub_v = hsv ? 4 : 1;
  const double dh = 360.0 / kHueBins / sub, ds = 1.0 / kSatBins / sub,
               dv = 1.0 / kValueBins / sub_v;
  const auto density = [&](const Point& x) {
    double sum = 0;
    for (const Blob& b : blobs) {
      double e = 0, norm = b.weight;
      for (size_t d = 0; d < size_t(dims); ++d) {
        const double z = (x[d] - b.mean[d]) / b.sd[d];
        e += z * z;
        norm /= std::sqrt(2 * M_PI) * b.sd[d];
      }
      sum += norm * std::exp(-e / 2);
    }
    return sum;
  };
  std::vector<uint64_t> out(size_t(histogram_bins(space)), 0);
  for (size_t i = 0; i < out.size(); ++i) {
    const int hs = int(i) / (hsv ? kValueBins : 1), vb = hsv ? int(i) % kValueBins : 0;
    double mass = 0;
    for (int a = 0; a < sub; ++a)
      for (int b = 0; b < sub; ++b)
        for (int c = 0; c < sub_v; ++c) {
          const double s = (hs % kSatBins) * sub * ds + (b + 0.5) * ds;
          const double v = hsv ? vb * sub_v * dv + (c + 0.5) * dv : 0;
          // area of the sub-sector s ds dh (radians) [x dv]
          mass += density(at((hs / kSatBins) * sub * dh + (a + 0.5) * dh, s, v)) * s * ds *
                  (dh * M_PI / 180) * (hsv ? dv : 1);
        }
    out[i] = uint64_t(std::llround(pixels * mass));
  }
  return out;
}

TEST(Cluster, GaussianMixtureRecoversKnownComponents) {
  const std::vector<Blob> truth = {{0.7, at(30, 0.5), {0.06, 0.04, 0}},
                                   {0.3, at(200, 0.4), {0.05, 0.05, 0}}};
  const auto hist = histogram_of(truth, ColourSpace::Hs, 1e6);
  const ColourClusters c = find_clusters(hist, {ClusterMethod::Gmm, ColourSpace::Hs, 2, 8});
  ASSERT_TRUE(c.mixture);
  ASSERT_EQ(c.mixture->components.size(), 2u);
  for (size_t j = 0; j < 2; ++j) {
    const Gaussian& g = c.mixture->components[j];  // ids in decreasing pixels: same order
    EXPECT_NEAR(g.weight, truth[j].weight, 0.01) << j;
    for (size_t d = 0; d < 2; ++d) {
      EXPECT_NEAR(g.mean[d], truth[j].mean[d], 0.005) << j << " " << d;
      // The binning is deconvolved: the colours' own spread.
      EXPECT_NEAR(std::sqrt(g.covariance[d][d]) / truth[j].sd[d], 1, 0.03) << j << " " << d;
    }
    EXPECT_NEAR(g.covariance[0][1], 0, 2e-4) << j;
    EXPECT_EQ(c.centres[j], g.mean);
  }
  const Hsv first = point_colour(c.centres[0]);
  EXPECT_NEAR(first.h, 30, 0.5);
  EXPECT_NEAR(first.s, 0.5, 0.005);
  EXPECT_NEAR(double(c.pixels[0]) / double(c.pixels[0] + c.pixels[1]), 0.7, 0.01);
}

std::vector<Blob> separated(int k) {
  std::vector<Blob> blobs;
  for (int j = 0; j < k; ++j)
    blobs.push_back({1.0 + j, at(360.0 * j / k + 10, 0.4 + 0.1 * (j % 3)), {0.05, 0.05, 0}});
  return blobs;
}

TEST(Cluster, AutomaticKFindsTheTrueNumber) {
  for (const int k : {3, 5})
    for (const ClusterMethod method : {ClusterMethod::KMeans, ClusterMethod::Gmm}) {
      const ColourClusters c = find_clusters(histogram_of(separated(k), ColourSpace::Hs, 1e5),
                                             {method, ColourSpace::Hs, 0, 8});
      EXPECT_EQ(c.centres.size(), size_t(k)) << k << " " << int(method);
      // Tried k: 2..8 for k-means (silhouette), 1..8 for the mixture (BIC).
      EXPECT_EQ(c.tried_k.size(), method == ClusterMethod::Gmm ? 8u : 7u);
    }
}

TEST(Cluster, ValueSeparatesWhatHueAndSaturationCannot) {
  // Three blobs of the same hue and saturation, dark, middle and bright.
  std::vector<Blob> blobs;
  for (const double v : {0.2, 0.5, 0.8}) blobs.push_back({1, at(100, 0.5, v), {0.05, 0.05, 0.06}});
  const auto hist = histogram_of(blobs, ColourSpace::Hsv, 1e5);
  const ColourClusters hsv = find_clusters(hist, {ClusterMethod::Gmm, ColourSpace::Hsv, 0, 5});
  ASSERT_EQ(hsv.centres.size(), 3u);
  std::vector<double> values;
  for (const Point& p : hsv.centres) values.push_back(point_colour(p).v);
  std::sort(values.begin(), values.end());
  EXPECT_NEAR(values[0], 0.2, 0.01);
  EXPECT_NEAR(values[1], 0.5, 0.01);
  EXPECT_NEAR(values[2], 0.8, 0.01);
  const ColourClusters hs = find_clusters(hs_marginal(hist, ColourSpace::Hsv),
                                          {ClusterMethod::Gmm, ColourSpace::Hs, 0, 6});
  EXPECT_EQ(hs.centres.size(), 1u);
}

const CellId kCell = CellId::FromFaceColRow(2, 10, 520, 500);

// A 4 x 4 image: 12 pixels of red (hue 0, saturation 0.8), 4 of green (hue 120, 0.8).
CellData two_colours() {
  Tile<float> t(4, 3);
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) {
      const bool red = r < 3;
      t.at(c, r, 0) = red ? 255 : 51;
      t.at(c, r, 1) = red ? 51 : 255;
      t.at(c, r, 2) = 51;
    }
  CellData d;
  d.inputs.emplace("rgb", t);
  return d;
}

struct Rgba {
  std::vector<uint8_t> bytes;  // interleaved
  int width = 0, height = 0, bands = 0;
  const uint8_t* at(const std::array<double, 2>& p) const {
    return &bytes[(size_t(p[1]) * size_t(width) + size_t(p[0])) * size_t(bands)];
  }
};

Rgba read_png(const std::string& path) {
  GDALAllRegister();
  const GDALDatasetUniquePtr ds(GDALDataset::Open(path.c_str(), GDAL_OF_RASTER));
  if (!ds) throw Error("cannot open " + path);
  Rgba img{{}, ds->GetRasterXSize(), ds->GetRasterYSize(), ds->GetRasterCount()};
  img.bytes.resize(size_t(img.width) * size_t(img.height) * size_t(img.bands));
  if (ds->RasterIO(GF_Read, 0, 0, img.width, img.height, img.bytes.data(), img.width, img.height,
                   GDT_Byte, img.bands, nullptr, img.bands, GSpacing(img.bands) * img.width, 1,
                   nullptr) != CE_None)
    throw Error("cannot read " + path);
  return img;
}

TEST(Cluster, DensityPlotReadBackWithGdal) {
  const std::string path =
      (fs::temp_directory_path() / ("cluster_plot_" + std::to_string(::getpid()) + ".png"))
          .string();
  const json doc = run_reduce("texture.cluster", {kCell}, 4, [](CellId) { return two_colours(); },
                              {{"k", 1}, {"plot", path}});
  const Rgba img = read_png(path);
  fs::remove(path);
  ASSERT_EQ(img.width, kPlotSize);
  ASSERT_EQ(img.height, kPlotSize);
  ASSERT_EQ(img.bands, 4);
  // The bins' centres: red in hue bin 0 (2.5 degrees), green in bin 24 (122.5), saturation 0.8
  // in bin 16 (0.825). Grey = 255 log(1 + n) / log(1 + 12).
  const uint8_t* red = img.at(plot_position(2.5, 0.825));
  const uint8_t* green = img.at(plot_position(122.5, 0.825));
  const uint8_t* empty = img.at(plot_position(240, 0.5));
  EXPECT_EQ(red[0], 255);
  EXPECT_EQ(green[0], std::lround(255 * std::log(5.0) / std::log(13.0)));  // 160
  EXPECT_EQ(green[1], green[0]);
  EXPECT_EQ(empty[0], 0);
  EXPECT_EQ(empty[3], 255);    // opaque inside the wheel
  EXPECT_EQ(img.bytes[3], 0);  // the corner: transparent
  const uint8_t* rim = img.at(plot_position(120, 1.025));
  EXPECT_EQ(rim[0], 0);  // the rim shows the hue: pure green at 120 degrees
  EXPECT_EQ(rim[1], 255);
  // The one centre, the weighted mean of the two bins, is marked in red.
  const json& c = doc.at("centres").at(0);
  const uint8_t* mark = img.at(plot_position(c["hue"], c["saturation"]));
  EXPECT_EQ(std::vector<uint8_t>(mark, mark + 4), (std::vector<uint8_t>{255, 0, 0, 255}));
  // Hand-computed centre: (12 a + 4 b) / 16 with a, b the bins' wheel points.
  const Point a = at(2.5, 0.825), b = at(122.5, 0.825);
  const Hsv mean = point_colour({(12 * a[0] + 4 * b[0]) / 16, (12 * a[1] + 4 * b[1]) / 16, 0});
  EXPECT_NEAR(c["hue"].get<double>(), mean.h, 1e-9);
  EXPECT_NEAR(c["saturation"].get<double>(), mean.s, 1e-9);
  EXPECT_EQ(c["pixels"], 16);
}

TEST(Cluster, HsvCentresClassify) {
  const json doc = run_reduce("texture.cluster", {kCell}, 4, [](CellId) { return two_colours(); },
                              {{"k", 2}, {"space", "hsv"}, {"method", "gmm"}});
  const json& c = doc.at("centres");
  ASSERT_EQ(c.size(), 2u);
  EXPECT_NEAR(c[0]["value"].get<double>(), 0.95, 1e-9);  // both colours have value 1: bin 9
  EXPECT_EQ(c[0]["pixels"], 12);
  EXPECT_EQ(doc.at("histogram").at("counts").size(), size_t(kHueBins * kSatBins * kValueBins));
  // The centres as texture.classify reads them: red pixels to 0, green to 1.
  const HsClassifier classifier =
      HsClassifier::from_params({{"grey_threshold", 10}, {"grey_hue", 300}, {"centres", c}});
  EXPECT_EQ(classifier.classify(255, 51, 51), 0);
  EXPECT_EQ(classifier.classify(51, 255, 51), 1);
  json mixed = c;
  mixed[1].erase("value");
  try {
    HsClassifier::from_params({{"grey_threshold", 10}, {"grey_hue", 300}, {"centres", mixed}});
    FAIL();
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(),
                 "params.centres: give \"value\" for every centre or for none (centre id 1)");
  }
}

// A 2 x 2 block of 32 x 32 RGB tiles of three colour zones varying in brightness, run through
// the runner with `threads`; returns the artifact's and the plot's bytes.
std::pair<std::vector<std::byte>, std::string> run_pipeline_with(const fs::path& dir, int threads) {
  const std::string store_path = (dir / ("t" + std::to_string(threads) + ".mqt")).string();
  const std::string plot = (dir / "plot.png").string();
  fs::remove(store_path);
  std::vector<CellId> cells;
  {
    const auto store = Store::open(store_path, Store::Mode::Create);
    LayerInfo rgb;
    rgb.name = "rgb";
    rgb.dtype = DType::U8;
    rgb.channels = 3;
    rgb.tile_size = 32;
    rgb.level = 9;
    store->create_layer(rgb);
    for (uint32_t r = 0; r < 2; ++r)
      for (uint32_t c = 0; c < 2; ++c)
        cells.push_back(CellId::FromFaceColRow(2, 9, 260 + c, 250 + r));
    for (const CellId cell : cells) {
      Tile<float> t(32, 3);
      for (int row = 0; row < 32; ++row)
        for (int col = 0; col < 32; ++col) {
          const int zone = (col / 8 + row / 8 + int(cell.col() + cell.row())) % 3;
          const float shade = float(0.6 + 0.4 * ((col * 7 + row * 3) % 11) / 10.0);
          const float colours[3][3] = {{180, 70, 40}, {60, 140, 50}, {90, 100, 150}};
          for (int k = 0; k < 3; ++k) t.at(col, row, k) = std::round(colours[zone][k] * shade);
        }
      store->put_tile("rgb", cell, from_tile(t, DType::U8));
    }
  }
  json region = json::array();
  for (const CellId c : cells) region.push_back(c.ToText());
  const json doc = {
      {"store", store_path},
      {"region", {{"cells", region}}},
      {"level", 9},
      {"tile_size", 32},
      {"steps",
       {{{"op", "texture.cluster"},
         {"inputs", {{"rgb", "rgb"}}},
         {"outputs", {{"clusters", "clusters"}}},
         {"params",
          {{"k", "auto"}, {"k_max", 5}, {"method", "gmm"}, {"space", "hsv"}, {"plot", plot}}}}}}};
  static const OperatorRegistry registry = [] {
    OperatorRegistry r;
    r.add(load_module(MAQUETTE_MODULE_DIR "/libmaquette_texture.so"));
    return r;
  }();
  RunOptions options;
  options.threads = threads;
  options.quiet = true;
  run_pipeline(parse_pipeline(doc.dump(), "test", dir.string(), registry), options);
  const auto store = Store::open(store_path, Store::Mode::ReadOnly);
  std::ifstream png(plot, std::ios::binary);
  return {store->get_artifact("clusters")->data,
          std::string(std::istreambuf_iterator<char>(png), {})};
}

TEST(Cluster, SameBitsTwiceAndWithAnyThreadCount) {
  const fs::path dir = fs::temp_directory_path() / ("cluster_runner_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const auto first = run_pipeline_with(dir, 1);
  EXPECT_EQ(run_pipeline_with(dir, 2), first);
  EXPECT_EQ(run_pipeline_with(dir, 1), first);
  const json doc = json::parse(
      std::string(reinterpret_cast<const char*>(first.first.data()), first.first.size()));
  EXPECT_EQ(doc.at("selection").at("criterion"), "bic");
  EXPECT_GE(doc.at("k").get<int>(), 3);  // at least the three colour zones
  EXPECT_GT(first.second.size(), 1000u);
  fs::remove_all(dir);
}

TEST(Cluster, ErrorsNameFieldAndValue) {
  const auto error = [](const json& params) {
    try {
      run_reduce(
          "texture.cluster", {kCell}, 4, [](CellId) { return two_colours(); }, params);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(error({{"k", 0}}), "texture.cluster: params.k: 0 is below the minimum 1");
  EXPECT_EQ(error({{"k", 33}}), "texture.cluster: params.k: 33 is above the maximum 32");
  EXPECT_EQ(error({{"k", "many"}}),
            "texture.cluster: params.k: expected an integer 1..32 or \"auto\", got \"many\"");
  EXPECT_EQ(error({{"k", "auto"}, {"k_max", 1}}),
            "texture.cluster: params.k_max: 1 is below the minimum 2");
  EXPECT_EQ(error({{"k", 2}, {"method", "em"}}),
            "texture.cluster: params.method: \"em\" is not one of [\"kmeans\",\"gmm\"]");
  EXPECT_EQ(error({{"k", 2}, {"space", "rgb"}}),
            "texture.cluster: params.space: \"rgb\" is not one of [\"hs\",\"hsv\",\"lab\"]");
  EXPECT_EQ(error({{"k", 2}, {"space", "lab"}, {"plot", "plot.png"}}),
            "texture.cluster: params.plot: the density plot is drawn in \"hs\" or \"hsv\", not "
            "in space \"lab\"");
  EXPECT_EQ(error({{"k", 2}, {"plot", "/nonexistent-dir/plot.png"}})
                .rfind("texture.cluster: params.plot: cannot write /nonexistent-dir/plot.png", 0),
            0u);
}

}  // namespace
}  // namespace maquette::texture
