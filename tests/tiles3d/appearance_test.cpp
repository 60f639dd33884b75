// How exported terrain looks: single-sided materials whose skirts face outwards (a double-sided
// material lights a skirt seen from behind with its normal reversed: the dark dotted lines along
// every tile seam of issue 13), and textures with the display stretch of `export png` (2-98 % of
// each band), or as stored with --no-stretch; texels beyond the texture's data padded with the
// data's colours (a skirt along the data's edge drew them black).
#include <gdal_priv.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>

#include "glb_reader.h"
#include "run_cli.h"
#include "test_tiles.h"
#include "tiles3d_fixture.h"

namespace maquette::test {
namespace {

using Vec = std::array<double, 3>;

Vec sub(const Vec& a, const Vec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec unit_cross(const Vec& a, const Vec& b) {
  const Vec c = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  const double n = std::sqrt(dot(c, c));
  return {c[0] / n, c[1] / n, c[2] / n};
}

// The grey PNG texture `i` of `glb`, decoded by GDAL (empty if it is not one).
std::vector<uint8_t> grey_texture(const Glb& glb, int i) {
  GDALAllRegister();
  const std::vector<char> png = glb.image(i);
  const std::string mem = "/vsimem/appearance_" + std::to_string(i) + ".png";
  VSIFCloseL(VSIFileFromMemBuffer(mem.c_str(), (GByte*)png.data(), png.size(), FALSE));
  GDALDatasetUniquePtr ds(GDALDataset::Open(mem.c_str(), GDAL_OF_RASTER));
  std::vector<uint8_t> px(size_t(kTileSize) * kTileSize);
  if (!ds || ds->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, kTileSize, kTileSize, px.data(),
                                            kTileSize, kTileSize, GDT_Byte, 0, 0) != CE_None)
    px.clear();
  ds.reset();
  VSIUnlink(mem.c_str());
  return px;
}

// A store with `dem` (0 m) and `grey` (uint8, value(sample), nodata 0) on the fixture's block.
std::string grey_store(const std::function<int(const TileSample&, int)>& value) {
  const Grid& grid = default_grid();
  const std::string store = temp_dir() + "/grey.maquette";
  auto st = Store::open(store, Store::Mode::Create);
  st->create_layer(layer_info("dem", DType::F32, 1, kTileSize, kLevel));
  LayerInfo grey = layer_info("grey", DType::U8, 1, kTileSize, kLevel);
  grey.nodata = 0;
  st->create_layer(grey);
  Store::Batch batch(*st);
  for (CellId c : tiles3d_fixture().block) {
    batch.put_tile("dem", c, make_tile<float>(grid, c, kTileSize, 1, [](auto&, int) { return 0; }));
    batch.put_tile("grey", c, make_tile<uint8_t>(grid, c, kTileSize, 1, value));
  }
  batch.commit();
  return store;
}

TEST(Appearance, SingleSidedSkirtsFaceOutwards) {
  const auto& f = tiles3d_fixture();
  const std::string out = temp_dir() + "/cells.glb";
  const CellId cell = f.block[0];
  ASSERT_EQ(run_maquette("export glb " + f.store_path + " " + out + " --dem dem --texture rgb " +
                         "--cells " + cell.ToText())
                .exit_code,
            0);
  const Glb glb = read_glb(out);
  EXPECT_FALSE(glb.json["materials"][0].value("doubleSided", false));
  const DecodedPrimitive& p = glb.primitives.at(0);
  Vec centre{};
  for (const auto& v : p.positions)
    for (int k = 0; k < 3; ++k) centre[k] += v[k] / double(p.positions.size());
  // The frame is centred on the cell: up is +y (glTF), to within the cell's curvature.
  size_t surface = 0, skirt = 0;
  for (const auto& t : p.faces) {
    const auto& a = p.positions[t[0]];
    const Vec n = unit_cross(sub(p.positions[t[1]], a), sub(p.positions[t[2]], a));
    if (n[1] > 0.5) {
      ++surface;  // counter-clockwise seen from above
      continue;
    }
    ++skirt;
    const Vec out_of_cell = sub(a, centre);
    EXPECT_LT(std::abs(n[1]), 0.1) << "a skirt is vertical";
    EXPECT_GT(n[0] * out_of_cell[0] + n[2] * out_of_cell[2], 0) << "a skirt faces outwards";
  }
  EXPECT_EQ(surface, size_t(2 * kTileSize * kTileSize));
  EXPECT_EQ(skirt, size_t(8 * kTileSize));  // two triangles per edge segment
}

// A grey layer of dark values 40..79 on the fixture's block: its texture is stretched so that
// the 2nd and 98th percentiles of the values become 0 and 255 (PNG: lossless).
TEST(Appearance, TexturesHaveTheDisplayStretch) {
  const Grid& grid = default_grid();
  const auto& f = tiles3d_fixture();
  auto value = [](const TileSample& s, int) { return 40 + (s.col * 7 + s.row * 3) % 40; };
  const std::string store = grey_store(value);
  // The oracle: the 2nd and 98th percentiles of every value of the cells, by a full sort.
  std::vector<int> all;
  for (CellId c : f.block)
    for (const TileSample& s : tile_samples(grid, c, kTileSize)) all.push_back(value(s, 0));
  std::sort(all.begin(), all.end());
  const double lo = all[size_t(0.02 * double(all.size() - 1))];
  const double hi = all[size_t(0.98 * double(all.size() - 1))];
  std::string cells;
  for (CellId c : f.block) cells += " " + c.ToText();

  for (const bool stretch : {true, false}) {
    const std::string out = temp_dir() + "/grey.glb";
    const auto r =
        run_maquette("export glb " + store + " " + out + " --dem dem --texture grey --cells" +
                     cells + (stretch ? "" : " --no-stretch"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Glb glb = read_glb(out);
    for (size_t i = 0; i < f.block.size(); ++i) {
      const std::vector<uint8_t> px = grey_texture(glb, int(i));
      ASSERT_EQ(px.size(), size_t(kTileSize) * kTileSize) << "texture " << i << " is not a PNG";
      const auto samples = tile_samples(grid, f.block[i], kTileSize);
      for (size_t k = 0; k < px.size(); ++k) {
        const double v = value(samples[k], 0);
        const double want =
            stretch ? std::round(255 * std::clamp((v - lo) / (hi - lo), 0.0, 1.0)) : v;
        ASSERT_EQ(px[k], want) << "cell " << i << " pixel " << k << " value " << v;
      }
    }
  }
}

// The grey layer's left half of every tile is no data (0): the texture there takes the colours of
// the data (40..79), not black; the data's texels are unchanged.
TEST(Appearance, TexturesArePaddedBeyondTheirData) {
  const auto& f = tiles3d_fixture();
  auto value = [](const TileSample& s, int) {
    return s.col % kTileSize < kTileSize / 2 ? 0 : 40 + (s.col * 7 + s.row * 3) % 40;
  };
  const std::string store = grey_store(value);
  std::string cells;
  for (CellId c : f.block) cells += " " + c.ToText();
  const std::string out = temp_dir() + "/padded.glb";
  const auto r = run_maquette("export glb " + store + " " + out +
                              " --dem dem --texture grey --no-stretch --cells" + cells);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Glb glb = read_glb(out);
  for (size_t i = 0; i < f.block.size(); ++i) {
    const std::vector<uint8_t> px = grey_texture(glb, int(i));
    ASSERT_EQ(px.size(), size_t(kTileSize) * kTileSize) << "texture " << i << " is not a PNG";
    const auto samples = tile_samples(default_grid(), f.block[i], kTileSize);
    for (size_t k = 0; k < px.size(); ++k) {
      const int v = value(samples[k], 0);
      if (v != 0)
        ASSERT_EQ(px[k], v) << "cell " << i << " pixel " << k;
      else
        ASSERT_TRUE(px[k] >= 40 && px[k] <= 79)
            << "cell " << i << " pixel " << k << ": " << int(px[k]);
    }
  }
}

}  // namespace
}  // namespace maquette::test
