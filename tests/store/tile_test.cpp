// Conversions between RawTile and typed tiles (core/tile.cpp).
#include <cmath>

#include "core/error.h"
#include "store_test_util.h"

namespace maquette {
namespace {

TEST(Tile, DTypeNames) {
  for (DType t :
       {DType::U8, DType::U16, DType::I16, DType::U32, DType::I32, DType::F32, DType::F64})
    EXPECT_EQ(parse_dtype(dtype_name(t)), t);
  EXPECT_EQ(dtype_size(DType::I16), 2u);
  EXPECT_EQ(dtype_size(DType::F64), 8u);
  EXPECT_THROW(parse_dtype("float16"), Error);
  EXPECT_EQ(log2_tile_size(256), 8);
  EXPECT_EQ(log2_tile_size(1), 0);
  EXPECT_THROW(log2_tile_size(0), Error);
  EXPECT_THROW(log2_tile_size(96), Error);
  EXPECT_THROW(log2_tile_size(8192), Error);
}

TEST(Tile, ToFloatMapsNodataToNaN) {
  const double nodata = -9999;
  const RawTile raw = test::raw_tile<int16_t>(2, 1, {1, -9999, 300, -4});
  const Tile<float> t = to_tile<float>(raw, &nodata);
  EXPECT_EQ(t.at(0, 0), 1.0f);
  EXPECT_TRUE(std::isnan(t.at(1, 0)));
  EXPECT_EQ(t.at(0, 1), 300.0f);
  EXPECT_EQ(t.at(1, 1), -4.0f);
}

TEST(Tile, FromFloatRoundsClampsAndMapsNaNToNodata) {
  Tile<float> t(2, 1);
  t.at(0, 0) = 2.5f;
  t.at(1, 0) = NAN;
  t.at(0, 1) = 70000.0f;
  t.at(1, 1) = -3.4f;
  const double nodata = 65535;
  const auto v = test::values_of<uint16_t>(from_tile(t, DType::U16, &nodata));
  EXPECT_EQ(v, (std::vector<uint16_t>{3, 65535, 65535, 0}));
}

TEST(Tile, FromTileDropsTheHalo) {
  Tile<double> t(2, 2, 1, -1.0);
  for (int r = 0; r < 2; ++r)
    for (int c = 0; c < 2; ++c)
      for (int k = 0; k < 2; ++k) t.at(c, r, k) = 10 * r + c + 0.5 * k;
  const RawTile raw = from_tile(t, DType::F64);
  EXPECT_EQ(raw.size, 2);
  EXPECT_EQ(test::values_of<double>(raw),
            (std::vector<double>{0, 0.5, 1, 1.5, 10, 10.5, 11, 11.5}));
  const Tile<double> back = to_tile<double>(raw);
  EXPECT_EQ(back.at(1, 1, 1), 11.5);
}

TEST(Tile, UninitializedHasTheShapeOfAFilledTile) {
  Tile<float> t = Tile<float>::uninitialized(4, 3, 2);
  const Tile<float> filled(4, 3, 2, 0.0f);
  EXPECT_EQ(t.size(), 4);
  EXPECT_EQ(t.channels(), 3);
  EXPECT_EQ(t.halo(), 2);
  EXPECT_EQ(t.stride(), 8);
  EXPECT_EQ(t.data().size(), filled.data().size());
  EXPECT_EQ(t.data().size(), 8u * 8u * 3u);
  t.at(-2, -2, 0) = 1;  // the halo's corners are addressable
  t.at(5, 5, 2) = 2;
  EXPECT_EQ(t.data().front(), 1.0f);
  EXPECT_EQ(t.data().back(), 2.0f);
}

TEST(Tile, RejectsWrongByteCount) {
  RawTile raw{DType::F32, 4, 1, std::vector<std::byte>(10)};
  EXPECT_THROW(to_tile<float>(raw), Error);
}

}  // namespace
}  // namespace maquette
