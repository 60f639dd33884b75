// The fixtures of the face-seam tests (seams_test.cpp, turned_edges_test.cpp): a small
// synthetic painting, a land cover that is a function of longitude and latitude, synthesis.transfer
// run on one cell with its land cover sampled with the store's halo, and one synthesis of a plane
// window whose guides the test lays itself (the faces' plane by hand: O P Q R left to right, the
// row's columns modulo its width, N above O and S below it; or another chart).
#pragma once

#include <gdal_priv.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "../synthesis.h"
#include "../transfer_exemplar.h"
#include "../transfer_params.h"
#include "core/face_plane.h"
#include "core/halo.h"
#include "core/splitmix64.h"
#include "runtime/operator_registry.h"
#include "runtime/params_schema.h"

namespace maquette::synthesis::seams {
namespace fs = std::filesystem;
using nlohmann::json;

constexpr int kFaceN = 0, kFaceO = 1, kFaceP = 2, kFaceQ = 3, kFaceR = 4, kFaceS = 5;  // cell_id.h
constexpr int kLevel = 5, kSize = 256;               // tiles of 256 pixels: the halo's 213 fit
constexpr int64_t kFace = int64_t(kSize) << kLevel;  // pixels a face
constexpr int kPixelLevel = kLevel + 8;
constexpr uint32_t kRow = 1u << (kLevel - 1);  // cells on the equator, far from the cube corners

// Land cover 1 and 2 in blobs a few kilometres across, a function of the point alone.
inline double land_cover(LonLat p) {
  const double x = p.lon * 40, y = p.lat * 40;
  return std::sin(x) + std::sin(0.7 * y + 0.3 * x) > 0.2 ? 2 : 1;
}

// A 128 x 96 painting: warm stripes on the left, green blobs on the right.
inline std::string write_painting(const fs::path& dir) {
  GDALAllRegister();
  const int w = 128, h = 96;
  std::unique_ptr<GDALDataset> ds(
      GetGDALDriverManager()->GetDriverByName("MEM")->Create("", w, h, 3, GDT_Byte, nullptr));
  std::vector<uint8_t> rgb(size_t(w) * size_t(h) * 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const size_t i = size_t(y) * size_t(w) + size_t(x);
      const double noise = double(splitmix64_mix(i) % 41) - 20;
      const bool right = x >= w / 2;
      rgb[3 * i] =
          uint8_t(std::clamp(right ? 40 + 30 * std::sin(x * 0.7) * std::sin(y * 0.6) + noise
                                   : 200 + 40 * std::sin(x / 3.0) + noise,
                             0.0, 255.0));
      rgb[3 * i + 1] = uint8_t(std::clamp((right ? 110 : 170) + noise, 0.0, 255.0));
      rgb[3 * i + 2] = uint8_t(right ? 50 : 60 + noise / 2);
    }
  int bands[3] = {1, 2, 3};
  EXPECT_EQ(ds->RasterIO(GF_Write, 0, 0, w, h, rgb.data(), w, h, GDT_Byte, 3, bands, 3, long(w) * 3,
                         1, nullptr),
            CE_None);
  const std::string path = (dir / "painting.png").string();
  GDALClose(GetGDALDriverManager()->GetDriverByName("PNG")->CreateCopy(
      path.c_str(), ds.get(), false, nullptr, nullptr, nullptr));
  return path;
}

class Seams : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new fs::path(fs::temp_directory_path() / ("maquette-seams-" + std::to_string(getpid())));
    fs::create_directories(*dir_);
    registry_ = new OperatorRegistry;
    registry_->add(load_module(MAQUETTE_MODULE_DIR "/libmaquette_synthesis.so"));
    operator_ = registry_->find("synthesis.transfer");
    params_ = new json(validate_params(operator_->spec().params_schema,
                                       {{"painting", write_painting(*dir_)},
                                        {"classes", 2},
                                        {"landcover_classes", {{"1", 0}, {"2", 1}}},
                                        {"exemplar_scale", 1}},
                                       "seams"));
  }
  static void TearDownTestSuite() {
    fs::remove_all(*dir_);
    delete dir_;
    delete registry_;
    delete params_;
  }

  // The operator's `source` output on `cell` (tiles of `size`, output `refine` levels finer), its
  // land cover sampled with the store's halo.
  static Tile<float> transfer(CellId cell, int size, int refine = 0) {
    const Grid& grid = default_grid();
    CellContext ctx;
    ctx.cell = cell;
    ctx.tile_size = size;
    ctx.refine = refine;
    ctx.grid = &grid;
    ctx.params = params_;
    // The land cover's layer as a store describes it: categorical (the operator checks).
    static const InputLayers layers = [] {
      LayerInfo landcover;
      landcover.name = "landcover";
      landcover.semantics = Semantics::Categorical;
      return InputLayers{{"landcover", landcover}};
    }();
    ctx.input_layers = &layers;
    CellData data;
    data.inputs.emplace("landcover",
                        assemble_halo(grid, cell, size, operator_->spec().halo, [&](CellId c) {
                          return std::optional(sample_field(grid, c, size, land_cover));
                        }));
    data.outputs.emplace("source", Tile<float>::uninitialized(size, 2));
    static_cast<const CellOperator*>(operator_)->run(ctx, data);
    return data.outputs.at("source");
  }

  // The face pixel the plane lays at plane pixel (x, r), x modulo the row (at kPixelLevel: face
  // O P Q R by column, N above O and S below it).
  static FaceCoord plane_pixel(int64_t x, int64_t r) {
    const bool row = r >= 0 && r < kFace;
    EXPECT_TRUE(row || (x < kFace && r >= -kFace && r < 2 * kFace));
    return row     ? FaceCoord{kFaceO + int(x / kFace), x % kFace, r}
           : r < 0 ? FaceCoord{kFaceN, x, r + kFace}
                   : FaceCoord{kFaceS, x, r - kFace};
  }
  using Lay = std::function<FaceCoord(int64_t x, int64_t r)>;

  // One synthesis of plane window `out` (pixels at kPixelLevel + shift), its guides laid here by
  // `lay` at kPixelLevel (x modulo the row's 4 faces): the exemplar's source of each pixel as
  // (column, row).
  static std::vector<std::array<int, 2>> whole(const PixelRect& out, const Lay& lay = plane_pixel,
                                               int shift = 0) {
    const Grid& grid = default_grid();
    const auto table = class_table(params_->at("landcover_classes"), "seams");
    TargetGuides g;
    g.shift = shift;
    g.rect = guide_rect(out, shift);
    g.col_period = (4 * kFace) << shift;
    for (int64_t r = g.rect.row0; r < g.rect.row0 + g.rect.height; ++r)
      for (int64_t c = g.rect.col0; c < g.rect.col0 + g.rect.width; ++c) {
        const FaceCoord pixel = lay((c % (4 * kFace) + 4 * kFace) % (4 * kFace), r);
        g.labels.push_back(
            painting_class(table, float(land_cover(pixel_centre(grid, pixel, kPixelLevel)))));
      }
    const auto exemplar = transfer_exemplar(*params_);
    const auto src = synthesize(exemplar->pyramid, g, synthesis_params(*params_), out);
    const int width = exemplar->pyramid.levels[0].width;
    std::vector<std::array<int, 2>> out_src;
    for (const int32_t s : src) out_src.push_back({s % width, s / width});
    return out_src;
  }

  // Pixels of `window` (plane, columns modulo 4 faces) lying in `cell` (tiles of `size`) whose
  // source differs between the cell's transfer and the window's synthesis; `compared` counts
  // those in both.
  static size_t differing(const PixelRect& window, const std::vector<std::array<int, 2>>& expected,
                          CellId cell, size_t& compared, int size = kSize) {
    const Tile<float> source = transfer(cell, size);
    const auto first = FacePlane(default_grid()).tile_pixel(cell, size, 0, 0);
    size_t n = 0;
    for (int64_t r = 0; r < window.height; ++r)
      for (int64_t c = 0; c < window.width; ++c) {
        const int64_t col = ((window.col0 + c) % (4 * kFace) + 4 * kFace) % (4 * kFace) - first[0];
        const int64_t row = window.row0 + r - first[1];
        if (col < 0 || col >= size || row < 0 || row >= size) continue;
        ++compared;
        const auto& e = expected[size_t(r * window.width + c)];
        n += source.at(int(col), int(row), 0) != float(e[0]) ||
             source.at(int(col), int(row), 1) != float(e[1]);
      }
    return n;
  }

  // Every pixel of `window` equals one synthesis of it across the edge, read from the cells on
  // both sides (tiles of kSize), which together cover the window.
  static void expect_one_synthesis(const PixelRect& window, std::initializer_list<CellId> cells) {
    const auto expected = whole(window);
    size_t compared = 0;
    for (const CellId cell : cells)
      EXPECT_EQ(differing(window, expected, cell, compared), 0u) << cell.ToText();
    EXPECT_EQ(compared, size_t(window.width * window.height));
  }

  static inline fs::path* dir_ = nullptr;
  static inline OperatorRegistry* registry_ = nullptr;
  static inline const Operator* operator_ = nullptr;
  static inline json* params_ = nullptr;
};

}  // namespace maquette::synthesis::seams
