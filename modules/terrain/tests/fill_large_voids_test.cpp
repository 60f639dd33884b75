// terrain.fill_voids on voids larger than its halo, filled through the overview pyramid of a real
// store: a linear field (an exact solution of the membrane) is recovered in a disc of 201 pixels
// and a strip of 320, nothing is extrapolated beyond the data's edge, and tilings of 64- and
// 128-pixel tiles give the same bits (so no seams between tiles either); with the data's
// footprint recorded, the void open to the data's edge is filled too; a void across the seam of
// faces P and N is filled with no step across the seam.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <limits>
#include <map>
#include <set>
#include <tuple>

#include "core/data_footprint.h"
#include "core/ecef.h"
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

// The lon/lat outline of the data's square: its pixels' outer edges, each point midway between
// the centres of a pixel on the square's border and of the pixel beyond it (every 8 pixels:
// straight edges in degrees stay well within half a pixel of the square's).
DataFootprint square_footprint() {
  std::vector<LonLat> ring;
  const auto centre = [](int64_t c, int64_t r) {
    return pixel_centre(default_grid(), FaceCoord{kFace, kOrigin + c, kOrigin + r}, 16);
  };
  const auto at = [&](int64_t c, int64_t r) {  // (c, r) beyond the square, next to it
    const LonLat a = centre(c, r), b = centre(std::clamp<int64_t>(c, 0, kSide - 1),
                                              std::clamp<int64_t>(r, 0, kSide - 1));
    ring.push_back({(a.lon + b.lon) / 2, (a.lat + b.lat) / 2});
  };
  for (int64_t i = -1; i < kSide; i += 8) at(i, -1);
  for (int64_t i = -1; i < kSide; i += 8) at(kSide, i);
  for (int64_t i = kSide; i > -1; i -= 8) at(i, kSide);
  for (int64_t i = kSide; i > -1; i -= 8) at(-1, i);
  ring.push_back(ring.front());
  return DataFootprint({{ring}}, {});
}

// A layer of `size`-pixel tiles holding sample() over the data's square, with its overviews, and
// the square's footprint in its provenance if `footprint`.
LayerInfo write_layer(Store& store, const std::string& name, int size, bool footprint = false) {
  const int level = 16 - log2_tile_size(size);
  LayerInfo info;
  info.name = name;
  info.tile_size = size;
  info.level = level;
  info.units = "m";
  if (footprint) info.provenance["footprint"] = square_footprint().to_json();
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

// The operator's output over the layer's tiles, by global pixel of a face, as the runner
// computes it (`visit` sees every tile).
void fill_tiles(const Store& store, const LayerInfo& layer,
                const std::function<void(CellId, const Tile<float>&)>& visit) {
  const CellOperator& op = terrain_test::terrain_operator("terrain.fill_voids");
  const json params = validate_params(op.spec().params_schema, {{"pyramid", layer.name}}, "fill");
  const int size = layer.tile_size;
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
    visit(cell, data.outputs.at("dem"));
  }
}

// The output over the data's square (one face), by global pixel.
std::map<std::pair<int64_t, int64_t>, float> fill(const Store& store, const LayerInfo& layer) {
  std::map<std::pair<int64_t, int64_t>, float> out;
  const int size = layer.tile_size;
  fill_tiles(store, layer, [&](CellId cell, const Tile<float>& tile) {
    for (int r = 0; r < size; ++r)
      for (int c = 0; c < size; ++c)
        out[{global_col(cell, size, c), global_row(cell, size, r)}] = tile.at(c, r);
  });
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

// With the footprint, the notch open to the data's edge is filled to the edge, within the range
// of the heights around it (a membrane's maximum principle; its border along the data's edge is
// free, so it does not continue the field's slope there); the other voids are filled as closely
// as without (the footprint moves the coarse levels' fixed samples along the data's edge).
TEST_F(FillLargeVoids, FillsToTheFootprintsEdge) {
  EXPECT_TRUE(square_footprint().contains(
      pixel_centre(default_grid(), FaceCoord{kFace, kOrigin, kOrigin + 80}, 16)));
  EXPECT_FALSE(square_footprint().contains(
      pixel_centre(default_grid(), FaceCoord{kFace, kOrigin - 1, kOrigin + 80}, 16)));
  const auto with = fill(*store_, write_layer(*store_, "with", 64, true));
  // The notch's border: columns 0..40 of rows 59 and 120, and column 40 between them.
  const float low = linear(kOrigin, kOrigin + 120), high = linear(kOrigin + 40, kOrigin + 59);
  int notch_samples = 0;
  for (const auto& [xy, v] : with) {
    const int64_t c = xy.first - kOrigin, r = xy.second - kOrigin;
    if (disc(c, r) || strip(c, r)) {
      ASSERT_LT(std::abs(v - linear(xy.first, xy.second)), 0.5) << c << "," << r;
      continue;
    }
    if (!notch(c, r)) {
      ASSERT_TRUE(same_bits(v, sample(xy.first, xy.second))) << c << "," << r;
      continue;
    }
    ++notch_samples;
    ASSERT_FALSE(std::isnan(v)) << c << "," << r;
    ASSERT_TRUE(v >= low - 1 && v <= high + 1) << v << " at " << c << "," << r;
  }
  EXPECT_EQ(notch_samples, 40 * 60);
}

TEST_F(FillLargeVoids, SameBitsForAnyTiling) {
  const auto a = fill(*store_, write_layer(*store_, "dem64", 64));
  const auto b = fill(*store_, write_layer(*store_, "dem128", 128));
  ASSERT_EQ(a.size(), b.size());
  for (const auto& [xy, v] : a)
    ASSERT_TRUE(same_bits(v, b.at(xy))) << xy.first - kOrigin << "," << xy.second - kOrigin;
}

// A disc of ~25 km on the seam of faces P and N (lat 41.9 N), in a field linear in the ECEF
// position (rising ~1.6 km across the disc), with 64-pixel tiles at level 9 (~300 m pixels):
// every void sample is filled, close to the field, and the fill's error changes across the seam
// no more than between neighbours on one face.
TEST_F(FillLargeVoids, NoStepAcrossAFaceSeam) {
  constexpr int kTile = 64, kLevel = 9;
  const LonLat seam{-45, 41.9};
  const Vec3 centre = up_unit(seam), slope = up_unit({-44, 43});
  const auto field = [&](LonLat p) {
    const Vec3 u = up_unit(p);
    return 1000 + 100000 * (u[0] * slope[0] + u[1] * slope[1] + u[2] * slope[2]);
  };
  const auto in_void = [&](LonLat p) {
    const Vec3 u = up_unit(p);
    return std::acos(std::min(1.0, u[0] * centre[0] + u[1] * centre[1] + u[2] * centre[2])) <
           25000 / 6371000.0;
  };
  LayerInfo info;
  info.name = "seam";
  info.tile_size = kTile;
  info.level = kLevel;
  store_->create_layer(info);
  const std::vector<CellId> cells =
      default_grid().cover_bbox(-46.5, 40.6, -43.5, 43.2, kLevel, Containment::Overlap);
  std::set<int> faces;
  for (const CellId cell : cells) {
    faces.insert(cell.face());
    Tile<float> tile(kTile, 1);
    for (int r = 0; r < kTile; ++r)
      for (int c = 0; c < kTile; ++c) {
        const LonLat p = terrain_test::true_centre(cell, kTile, c, r);
        tile.at(c, r) = in_void(p) ? kNaN : float(field(p));
      }
    store_->put_tile("seam", cell, from_tile(tile, DType::F32));
  }
  ASSERT_EQ(faces.size(), 2u);
  store_->update_overviews("seam");

  // Error of the fill by face pixel; void samples only.
  std::map<std::tuple<int, int64_t, int64_t>, double> error;
  fill_tiles(*store_, store_->require_layer("seam"), [&](CellId cell, const Tile<float>& tile) {
    for (int r = 0; r < kTile; ++r)
      for (int c = 0; c < kTile; ++c) {
        const LonLat p = terrain_test::true_centre(cell, kTile, c, r);
        if (!in_void(p)) continue;
        ASSERT_FALSE(std::isnan(tile.at(c, r))) << cell.ToText() << " " << c << "," << r;
        error[{cell.face(), global_col(cell, kTile, c), global_row(cell, kTile, r)}] =
            tile.at(c, r) - field(p);
      }
  });
  double worst = 0, step_across = 0, step_within = 0;
  int across = 0;
  for (const CellId cell : cells) {
    for (int r = -1; r <= kTile; ++r)
      for (int c = -1; c <= kTile; ++c) {
        if (r >= 0 && r < kTile && c >= 0 && c < kTile) continue;
        // A halo pixel of this tile and its neighbour inside the tile, both void samples.
        const std::optional<FaceCoord> out = pixel_source(default_grid(), cell, kTile, c, r);
        const int ic = std::clamp(c, 0, kTile - 1), ir = std::clamp(r, 0, kTile - 1);
        if (!out || (ic != c && ir != r)) continue;
        const auto a = error.find({out->face, out->col, out->row});
        const auto b =
            error.find({cell.face(), global_col(cell, kTile, ic), global_row(cell, kTile, ir)});
        if (a == error.end() || b == error.end()) continue;
        const double step = std::abs(a->second - b->second);
        if (out->face != cell.face()) {
          step_across = std::max(step_across, step);
          ++across;
        } else {
          step_within = std::max(step_within, step);
        }
      }
  }
  for (const auto& [pixel, e] : error) worst = std::max(worst, std::abs(e));
  std::cout << error.size() << " void samples, largest error " << worst
            << " m; largest change of the error between neighbours: " << step_across
            << " m across the seam (" << across << " pairs), " << step_within
            << " m across tile edges within a face\n";
  EXPECT_GT(across, 50);
  EXPECT_LT(worst, 5);  // of ~1600 m across the disc
  EXPECT_LT(step_across, 2 * step_within + 0.01);
}

}  // namespace
}  // namespace maquette::terrain
