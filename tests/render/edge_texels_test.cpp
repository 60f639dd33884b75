// The imagery carried past its edge (formats/render/edge_texels.h) against a search written for
// the test: on a 3 x 3 block of cells (one without a tile) of uint8 RGB imagery with no-data
// holes of every size inside the tiles (scattered texels, and a disc wider than the reach across
// four tiles), every lattice texel within the reach of the cells resolved by looking at every
// offset of the reach in the contract's order (rings, then each ring's rows and columns) and the
// least squared distance kept, and random points read bilinearly from the four texels around
// them, the weights renormalized over those with a value: the same values (and no value exactly
// where the search finds none) at reaches 5 and 33 (blocks of 64 and of 66 texels), the texels'
// random colours making a wrong tie a wrong value.
#include "render/edge_texels.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/grid.h"
#include "store/store.h"
#include "test_tiles.h"

namespace maquette {
namespace {

constexpr int kLevel = 4, kSize = 32, kFace = 1, kCol0 = 5, kRow0 = 6;
// Lattice texels kept around the cells: the points' reach + 1 and the search's reach (33) more.
constexpr int64_t kMargin = 72;

uint32_t mix(uint64_t x) {  // a hash of a texel's face pixel, for its colour and its holes
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return uint32_t(x ^ (x >> 31));
}

// Whether the face pixel (col, row) of the tiles' level holds no data: one in five at random,
// and a disc of 40 pixels' radius around the corner the middle cell shares with its lower right
// neighbour.
bool hole(int64_t col, int64_t row) {
  const double dx = double(col - (kCol0 + 2) * kSize) + 0.5,
               dy = double(row - (kRow0 + 2) * kSize) + 0.5;
  return mix(uint64_t(col) * 1000003u + uint64_t(row)) % 5 == 0 || dx * dx + dy * dy < 40.0 * 40.0;
}

struct Imagery {
  std::string path = (std::filesystem::temp_directory_path() /
                      ("maquette-edge-texels-" + std::to_string(::getpid()) + ".mqt"))
                         .string();
  LayerInfo layer = test::layer_info("rgb", DType::U8, 3, kSize, kLevel);
  double texel = 0;
  // The lattice texels (x right, y up, as edge_texels.h) from (x0, y0), w a side: their colours
  // (NaN: none), the cells' and kMargin around them.
  int64_t x0 = 0, y0 = 0, w = 0;
  std::vector<std::array<float, 3>> colour;

  Imagery() {
    const Grid& grid = default_grid();
    layer.nodata = 0;
    std::filesystem::remove(path);
    auto store = Store::open(path, Store::Mode::Create);
    store->create_layer(layer);
    texel = grid.plane_square(CellId::FromFace(0)).side / double(1 << kLevel) / kSize;
    const PlaneSquare first =
        grid.plane_square(CellId::FromFaceColRow(kFace, kLevel, kCol0, kRow0));
    x0 = int64_t(std::floor(first.x_min / texel)) - kMargin;
    y0 = int64_t(std::floor(first.y_max / texel)) - 3 * kSize - kMargin;
    w = 3 * kSize + 2 * kMargin;
    colour.assign(size_t(w * w), {NAN, NAN, NAN});
    Store::Batch batch(*store);
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) {
        if (r == 0 && c == 2) continue;  // a cell without a tile
        const CellId cell = CellId::FromFaceColRow(kFace, kLevel, kCol0 + c, kRow0 + r);
        auto value = [&](const test::TileSample& s, int k) {
          if (hole(s.col, s.row)) return 0u;
          const uint32_t v =
              1 + mix(uint64_t(s.col) * 7919u + uint64_t(s.row) * 31u + uint64_t(k)) % 255;
          const int64_t x = int64_t(std::floor(s.plane.x / texel)) - x0,
                        y = int64_t(std::floor(s.plane.y / texel)) - y0;
          colour[size_t(y * w + x)][size_t(k)] = float(v);
          return v;
        };
        batch.put_tile("rgb", cell, test::make_tile<uint8_t>(grid, cell, kSize, 3, value));
      }
    batch.commit();
  }
  ~Imagery() {
    for (const char* suffix : {"", "-wal", "-shm"}) std::filesystem::remove(path + suffix);
  }
  const std::array<float, 3>& at(int64_t x, int64_t y) const {
    return colour[size_t((y - y0) * w + x - x0)];
  }
};

// The lattice texel (x, y)'s own colour or its nearest's within `reach`: every offset looked at,
// ring by ring, each ring in the contract's order, the first of the least squared distance kept.
std::array<float, 3> searched(const Imagery& im, int64_t x, int64_t y, int reach) {
  std::array<float, 3> best = im.at(x, y);
  if (!std::isnan(best[0])) return best;
  int64_t least = int64_t(reach) * reach + 1;
  auto look = [&](int64_t dx, int64_t dy) {
    const int64_t d2 = dx * dx + dy * dy;
    const auto& c = im.at(x + dx, y + dy);
    if (d2 < least && !std::isnan(c[0])) least = d2, best = c;
  };
  for (int64_t r = 1; r <= reach; ++r) {
    for (int64_t d = -r; d <= r; ++d) look(d, -r), look(d, r);
    for (int64_t d = -r + 1; d < r; ++d) look(-r, d), look(r, d);
  }
  return best;
}

TEST(EdgeTexels, EachTexelTakesItsNearestWithDataWithinTheReach) {
  const Imagery im;
  const auto store = Store::open(im.path, Store::Mode::ReadOnly);
  for (const int reach : {5, 33}) {
    EdgeTexels edge(LayerSampler::shared_tiles(*store, default_grid(), im.layer, im.layer.level),
                    default_grid(), im.layer, reach);
    // Points over the cells and `reach` + 1 texels around them.
    const int64_t lo_x = im.x0 + kMargin - reach - 1, lo_y = im.y0 + kMargin - reach - 1;
    const int64_t span = 3 * kSize + 2 * reach + 1;
    std::mt19937_64 random{uint64_t(reach)};
    std::uniform_int_distribution<int64_t> texel(0, span - 1);
    std::uniform_real_distribution<double> within(0.05, 0.95);
    int with_value = 0, without = 0, filled = 0;
    for (int i = 0; i < 40000; ++i) {
      const int64_t x = lo_x + texel(random), y = lo_y + texel(random);
      const double fx = within(random), fy = within(random);
      const double weights[4] = {(1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy};
      double sum[3] = {0, 0, 0}, weight = 0;
      for (int j = 0; j < 4; ++j) {
        const auto t = searched(im, x + (j & 1), y + (j >> 1), reach);
        if (std::isnan(t[0])) continue;
        for (int b = 0; b < 3; ++b) sum[b] += weights[j] * t[size_t(b)];
        weight += weights[j];
      }
      float got[3] = {-1, -1, -1};
      const bool found =
          edge.sample({(double(x) + 0.5 + fx) * im.texel, (double(y) + 0.5 + fy) * im.texel}, got);
      ASSERT_EQ(found, weight > 0) << "texel " << x << ", " << y << " reach " << reach;
      if (!found) {
        ++without;
        continue;
      }
      ++with_value;
      filled += std::isnan(im.at(x, y)[0]);
      for (int b = 0; b < 3; ++b)
        ASSERT_NEAR(got[b], sum[b] / weight, 1e-3)
            << "texel " << x << ", " << y << " band " << b << " reach " << reach;
    }
    // Each kind of point is there: none within the reach, values, and texels without data filled.
    EXPECT_GT(without, 1000) << reach;
    EXPECT_GT(with_value, 10000) << reach;
    EXPECT_GT(filled, 3000) << reach;
  }
}

// Tiles of another level (or layer) than the texture's are refused, naming both.
TEST(EdgeTexels, RefusesTilesOfAnotherLevelNamingBoth) {
  const Imagery im;
  const auto store = Store::open(im.path, Store::Mode::ReadOnly);
  const auto coarser = LayerSampler::shared_tiles(*store, default_grid(), im.layer, kLevel - 1);
  try {
    EdgeTexels edge(coarser, default_grid(), im.layer, 5);
    FAIL() << "accepted tiles of level " << kLevel - 1;
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(),
                 "EdgeTexels: the tiles are layer 'rgb' at level 3, not the texture "
                 "'rgb' at its level 4");
  }
}

}  // namespace
}  // namespace maquette
