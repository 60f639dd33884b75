// terrain.fill_voids on voids larger than its halo, filled through the overview pyramid of a real
// store: a linear field (an exact solution of the membrane) is recovered in a disc of 201 pixels
// and a strip of 320, nothing is extrapolated beyond the data's edge, and tilings of 64- and
// 128-pixel tiles give the same bits (so no seams between tiles either).
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <limits>
#include <map>

#include "core/halo.h"
#include "store/store.h"
#include "terrain_module.h"

namespace maquette::terrain {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr int kFace = 2;
// Data over the 512 x 512 face pixels at pixel level 16 (~150 m) from (kOrigin, kOrigin).
constexpr int64_t kOrigin = 40960, kSide = 512;

bool disc(int64_t c, int64_t r) { return (c - 200) * (c - 200) + (r - 260) * (r - 260) <= 10000; }
bool strip(int64_t c, int64_t r) { return c >= 100 && c < 420 && r >= 430 && r < 434; }
bool notch(int64_t c, int64_t r) { return c < 40 && r >= 60 && r < 120; }  // open to the edge

float linear(int64_t x, int64_t y) { return float(1500 + 0.75 * x - 0.5 * y); }

float sample(int64_t x, int64_t y) {
  const int64_t c = x - kOrigin, r = y - kOrigin;
  return disc(c, r) || strip(c, r) || notch(c, r) ? kNaN : linear(x, y);
}

bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// A layer of `size`-pixel tiles holding sample() over the data's square, with its overviews.
LayerInfo write_layer(Store& store, const std::string& name, int size) {
  const int level = 16 - log2_tile_size(size);
  LayerInfo info;
  info.name = name;
  info.tile_size = size;
  info.level = level;
  info.units = "m";
  store.create_layer(info);
  for (int64_t row = kOrigin / size; row < (kOrigin + kSide) / size; ++row)
    for (int64_t col = kOrigin / size; col < (kOrigin + kSide) / size; ++col) {
      const CellId cell = CellId::FromFaceColRow(kFace, level, uint32_t(col), uint32_t(row));
      Tile<float> tile(size, 1);
      for (int r = 0; r < size; ++r)
        for (int c = 0; c < size; ++c) tile.at(c, r) = sample(col * size + c, row * size + r);
      store.put_tile(name, cell, from_tile(tile, DType::F32));
    }
  store.update_overviews(name);
  return info;
}

// The operator's output over the data's square, by global pixel, as the runner computes it.
std::map<std::pair<int64_t, int64_t>, float> fill(const Store& store, const LayerInfo& layer) {
  const CellOperator& op = terrain_test::terrain_operator("terrain.fill_voids");
  const json params = validate_params(op.spec().params_schema, {{"pyramid", layer.name}}, "fill");
  const int size = layer.tile_size;
  std::map<std::pair<int64_t, int64_t>, float> out;
  for (const CellId cell : store.tile_cells(layer.name)) {
    CellData data;
    data.inputs.emplace("dem", assemble_halo(default_grid(), cell, size, op.spec().halo,
                                             [&](CellId c) -> std::optional<Tile<float>> {
                                               const auto raw = store.get_tile(layer.name, c);
                                               if (!raw) return std::nullopt;
                                               return to_tile<float>(*raw);
                                             }));
    data.outputs.emplace("dem", Tile<float>(size, 1));
    op.run({.cell = cell,
            .tile_size = size,
            .grid = &default_grid(),
            .params = &params,
            .store = &store},
           data);
    for (int r = 0; r < size; ++r)
      for (int c = 0; c < size; ++c)
        out[{global_col(cell, size, c), global_row(cell, size, r)}] =
            data.outputs.at("dem").at(c, r);
  }
  return out;
}

class FillLargeVoids : public testing::Test {
 protected:
  void SetUp() override {
    path_ = std::filesystem::temp_directory_path() /
            ("fill_large_voids_" + std::to_string(::getpid()) + ".mqt");
    std::filesystem::remove(path_);
    store_ = Store::open(path_.string(), Store::Mode::Create);
  }
  void TearDown() override {
    store_.reset();
    for (const char* suffix : {"", "-wal", "-shm"})
      std::filesystem::remove(path_.string() + suffix);
  }
  std::filesystem::path path_;
  std::unique_ptr<Store> store_;
};

TEST_F(FillLargeVoids, RecoversALinearFieldAndStopsAtTheDataEdge) {
  const auto out = fill(*store_, write_layer(*store_, "dem64", 64));
  ASSERT_EQ(out.size(), size_t(kSide * kSide));
  double worst = 0;
  int filled = 0;
  for (const auto& [xy, v] : out) {
    const int64_t c = xy.first - kOrigin, r = xy.second - kOrigin;
    if (disc(c, r) || strip(c, r)) {
      ASSERT_FALSE(std::isnan(v)) << c << "," << r;
      worst = std::max(worst, double(std::abs(v - linear(xy.first, xy.second))));
      ++filled;
    } else if (notch(c, r)) {
      // The notch's column on the data's edge has no data beyond it at any level.
      if (c == 0) {
        ASSERT_TRUE(std::isnan(v)) << c << "," << r;
      }
    } else {
      ASSERT_TRUE(same_bits(v, sample(xy.first, xy.second))) << c << "," << r;
    }
  }
  std::cout << filled << " samples filled, largest error " << worst << " m\n";
  RecordProperty("largest_error_m", std::to_string(worst));
  // The field rises 270 m across the disc: the membrane's solution is the field itself.
  EXPECT_LT(worst, 0.5);
}

TEST_F(FillLargeVoids, SameBitsForAnyTiling) {
  const auto a = fill(*store_, write_layer(*store_, "dem64", 64));
  const auto b = fill(*store_, write_layer(*store_, "dem128", 128));
  ASSERT_EQ(a.size(), b.size());
  for (const auto& [xy, v] : a)
    ASSERT_TRUE(same_bits(v, b.at(xy))) << xy.first - kOrigin << "," << xy.second - kOrigin;
}

}  // namespace
}  // namespace maquette::terrain
