// The scenes of the transfer in the picture's tests (paint_panorama_test.cpp,
// paint_light_test.cpp): a panorama that `maquette render panorama` draws of a synthetic DEM, a
// 600 m plateau (forest) on a plain (shrub) with the relief a test gives, so the plateau's far
// edge stands against the plain behind it (a silhouette) and the horizon against the sky; and a
// synthetic painting: two classes side by side, a sky class along its top, an excluded square in
// each class.
#pragma once

#include <array>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "../paint_panorama.h"
#include "../pixel_hash.h"
#include "gdal/image_file.h"
#include "run_cli.h"
#include "synthetic_raster.h"

// In an unnamed namespace, inline: each test file uses what it needs.
namespace maquette::synthesis {
namespace {

constexpr int kPaintingWidth = 128, kPaintingHeight = 96, kSkyRows = 20;

inline bool on_plateau(double lon, double lat) {
  return lon > 10.12 && lon < 10.18 && lat > 45.12 && lat < 45.18;
}
inline bool excluded_at(int x, int y) {
  return (x >= 20 && x < 32 && y >= 50 && y < 62) || (x >= 90 && x < 102 && y >= 30 && y < 42);
}
inline int painting_label(int x, int y) {
  return y < kSkyRows ? 2 : x >= kPaintingWidth / 2 ? 1 : 0;
}

// Metres added to the plateau and the plain at (lon, lat).
using Relief = double (*)(double lon, double lat);
inline double no_relief(double, double) { return 0; }

struct Scene {
  std::string dir = test::temp_dir();
  std::string picture = dir + "/pano.png";
  std::vector<uint8_t> painting;  // RGB, row-major, as written to painting.png

  explicit Scene(Relief relief = no_relief) {
    const std::string store = dir + "/s.mqt", dem = dir + "/dem.tif", lc = dir + "/lc.tif";
    test::write_raster(dem, test::lonlat_raster(10, 45.3, 600, 0.0005, "Float32"),
                       [relief](int, double lon, double lat) {
                         return (on_plateau(lon, lat) ? 700 : 100) + relief(lon, lat);
                       });
    test::write_raster(lc, test::lonlat_raster(10, 45.3, 600, 0.0005, "Byte"),
                       [](int, double lon, double lat) { return on_plateau(lon, lat) ? 41 : 52; });
    for (const std::string& args :
         {"ingest " + store + " --layer dem --as dem --vertical-datum ellipsoid " + dem,
          "ingest " + store + " --layer lc --as landcover " + lc,
          "render panorama " + store + " " + picture +
              " --dem dem --land-cover lc --camera 10.15 45.02 1500 --heading 0 --pitch -6 "
              "--fov 50 --size 320 200",
          "render panorama " + store + " " + dir +
              "/bare.png --dem dem --camera 10.15 45.02 "
              "1500 --heading 0 --pitch -6 --fov 50 --size 320 200"}) {
      const auto r = test::run_maquette(args);
      EXPECT_EQ(r.exit_code, 0) << args << "\n" << r.err;
    }
    // The painting: warm stripes (class 0) left, green blobs (class 1) right, a blue sky (class
    // 2) along the top; the excluded squares magenta.
    std::vector<uint8_t> labels(kPaintingWidth * kPaintingHeight), excluded(labels.size());
    painting.resize(3 * labels.size());
    for (int y = 0; y < kPaintingHeight; ++y)
      for (int x = 0; x < kPaintingWidth; ++x) {
        const size_t i = size_t(y) * kPaintingWidth + size_t(x);
        const double noise = double(splitmix64_mix(i) % 41) - 20;
        const int label = painting_label(x, y);
        labels[i] = uint8_t(label);
        excluded[i] = excluded_at(x, y) ? 255 : 0;
        const double r = excluded[i]  ? 255
                         : label == 2 ? 120 + noise
                         : label == 1 ? 40 + 30 * std::sin(x * 0.7) * std::sin(y * 0.6) + noise
                                      : 200 + 40 * std::sin(x / 3.0) + noise;
        const double g = excluded[i]  ? 0
                         : label == 2 ? 160 + noise
                         : label == 1 ? 110 + noise
                                      : 170 + noise;
        const double b = excluded[i] ? 255 : label == 2 ? 230 : label == 1 ? 50 : 60 + noise;
        painting[3 * i] = uint8_t(r), painting[3 * i + 1] = uint8_t(g),
                     painting[3 * i + 2] = uint8_t(b);
      }
    write_image(painting, kPaintingWidth, kPaintingHeight, 3, {"PNG", {}}, dir + "/painting.png");
    write_image(labels, kPaintingWidth, kPaintingHeight, 1, {"PNG", {}}, dir + "/labels.png");
    write_image(excluded, kPaintingWidth, kPaintingHeight, 1, {"PNG", {}}, dir + "/excluded.png");
  }

  nlohmann::json params() const {
    return {{"painting", dir + "/painting.png"},
            {"labels", dir + "/labels.png"},
            {"exclusion", dir + "/excluded.png"},
            {"exemplar_scale", 1},
            {"landcover_classes", {{"41", 1}, {"52", 0}}},
            {"painting_distance", "rows"},
            {"distance_range", {2000, 30000}},
            {"tile", 128}};
  }
};

inline PaintedPanorama paint(const Scene& s, const nlohmann::json& raw) {
  const PaintParams params = paint_params(raw, "params.json");
  const PanoramaPicture picture = read_panorama(s.picture, true);
  return paint_panorama(picture, *transfer_exemplar(params.exemplar), params);
}

// The painting pixel of `p`'s pixel i (x, y), or {-1, -1} unpainted.
inline std::array<int, 2> source_of(const PaintedPanorama& p, size_t i) {
  if (std::isnan(p.source[2 * i])) return {-1, -1};
  return {int(p.source[2 * i]), int(p.source[2 * i + 1])};
}

inline std::string run_paint(const std::string& args) {
  return test::shell_output("(" + std::string(MAQUETTE_BIN_DIR) + "/maquette-paint " + args +
                            " 2>&1; echo \"exit $?\")");
}

inline std::string write_params(const Scene& s, const nlohmann::json& params,
                                const std::string& name) {
  const std::string path = s.dir + "/" + name;
  std::ofstream(path) << params.dump();
  return path;
}

}  // namespace
}  // namespace maquette::synthesis
