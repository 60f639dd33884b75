// The normal_oct codec (store/normal_oct.h, store/codec.h): the angular error over the whole
// sphere against the float normals encoded (angles in double precision), stable re-encoding,
// missing normals, bad input, tiles through encode_tile/decode_tile, and overviews of a normal_oct
// layer that do not depend on how its tiles were batched.
#include "store/normal_oct.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numbers>

#include "core/error.h"
#include "store/codec.h"
#include "store/store.h"
#include "store_test_util.h"

namespace maquette {
namespace {

using test::raw_tile;
using test::TempDir;
using test::values_of;

// The angle in degrees between two vectors (atan2 of |a x b| and a . b: accurate for tiny
// angles, where acos of the cosine is not).
double angle_degrees(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  const double cx = a[1] * b[2] - a[2] * b[1], cy = a[2] * b[0] - a[0] * b[2],
               cz = a[0] * b[1] - a[1] * b[0];
  const double dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  return std::atan2(std::hypot(cx, cy, cz), dot) * 180 / std::numbers::pi;
}

std::array<double, 3> as_double(const std::array<float, 3>& v) { return {v[0], v[1], v[2]}; }

// n directions spread evenly over the sphere (a Fibonacci lattice), as float normals.
std::vector<std::array<float, 3>> sphere(int n) {
  std::vector<std::array<float, 3>> out;
  const double golden = std::numbers::pi * (3 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i) {
    const double z = 1 - (2 * i + 1.0) / n, r = std::sqrt(1 - z * z), a = golden * i;
    out.push_back({float(r * std::cos(a)), float(r * std::sin(a)), float(z)});
  }
  return out;
}

TEST(NormalOct, AngularErrorOverTheSphereIsUnderFourHundredthsOfADegree) {
  double max_error = 0, sum = 0;
  const auto normals = sphere(1'000'000);
  for (const auto& n : normals) {
    const std::array<float, 3> d = oct_decode(oct_encode(n));
    const double length = std::hypot(double(d[0]), double(d[1]), double(d[2]));
    ASSERT_NEAR(length, 1, 1e-6);
    const double e = angle_degrees(as_double(n), as_double(d));
    max_error = std::max(max_error, e);
    sum += e;
  }
  std::cout << "normal_oct over 1e6 directions: max " << max_error << " mean "
            << sum / double(normals.size()) << " degrees\n";
  EXPECT_LE(max_error, 0.04);  // the bound is 0.1
  EXPECT_LE(sum / double(normals.size()), 0.02);
}

TEST(NormalOct, ReEncodingADecodedNormalKeepsItsDirection) {
  // Every 5th code pair of the square (both hemispheres and the folds): a stored normal read and
  // written again (an overview, a resumed step) is stored as the same direction.
  for (int a = -kOctMax; a <= kOctMax; a += 5)
    for (int b = -kOctMax; b <= kOctMax; b += 5) {
      const std::array<float, 3> d = oct_decode({int16_t(a), int16_t(b)});
      ASSERT_EQ(oct_decode(oct_encode(d)), d) << a << ' ' << b;
    }
}

TEST(NormalOct, MissingNormalsAndVectorsOfAnyLength) {
  constexpr float nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ(oct_encode({nan, nan, nan}), (std::array<int16_t, 2>{kOctMissing, kOctMissing}));
  EXPECT_EQ(oct_encode({0.f, nan, 1.f}), (std::array<int16_t, 2>{kOctMissing, kOctMissing}));
  for (float v : oct_decode({kOctMissing, kOctMissing})) EXPECT_TRUE(std::isnan(v));
  // Only the direction is kept: a mean of normals (an overview) is stored normalized.
  EXPECT_EQ(oct_encode({0.f, 0.f, 5.f}), (std::array<int16_t, 2>{0, 0}));
  EXPECT_EQ(oct_decode({0, 0}), (std::array<float, 3>{0.f, 0.f, 1.f}));
  EXPECT_EQ(oct_decode(oct_encode({0.f, 0.f, -0.5f})), (std::array<float, 3>{0.f, 0.f, -1.f}));
  EXPECT_EQ(oct_decode(oct_encode({3.f, 0.f, 0.f})), (std::array<float, 3>{1.f, 0.f, 0.f}));
}

TEST(NormalOct, RefusesVectorsWithoutDirectionAndCodesOutOfRange) {
  EXPECT_THROW(oct_encode({0.f, 0.f, 0.f}), Error);
  EXPECT_THROW(oct_encode({INFINITY, 0.f, 1.f}), Error);
  EXPECT_THROW(oct_decode({int16_t(kOctMax + 1), 0}), Error);
  EXPECT_THROW(oct_decode({kOctMissing, 0}), Error);  // half missing: damaged
}

// A terrain-like field of normals (the normals of a sum of sines), with a missing corner.
RawTile normal_tile(int size) {
  std::vector<float> v(size_t(size) * size_t(size) * 3);
  for (int r = 0; r < size; ++r)
    for (int c = 0; c < size; ++c) {
      float* n = &v[(size_t(r) * size_t(size) + size_t(c)) * 3];
      if (r < size / 4 && c < size / 4) {
        n[0] = n[1] = n[2] = NAN;
        continue;
      }
      const double gx = 0.6 * std::cos(0.05 * c) + 0.1 * std::sin(0.3 * (c + r));
      const double gy = 0.4 * std::sin(0.07 * r) - 0.1 * std::cos(0.2 * c);
      const double k = 1 / std::sqrt(1 + gx * gx + gy * gy);
      n[0] = float(-gx * k);
      n[1] = float(-gy * k);
      n[2] = float(k);
    }
  return raw_tile<float>(size, 3, v);
}

TEST(NormalOct, TilesRoundTripWithinTheBoundInAFractionOfZstdsBytes) {
  const RawTile in = normal_tile(256);
  const auto blob = encode_tile(in, parse_codec("normal_oct"));
  const RawTile out = decode_tile(blob);
  EXPECT_EQ(out.dtype, DType::F32);
  EXPECT_EQ(out.size, 256);
  EXPECT_EQ(out.channels, 3);
  const auto a = values_of<float>(in), b = values_of<float>(out);
  ASSERT_EQ(a.size(), b.size());
  double max_error = 0;
  for (size_t i = 0; i < a.size(); i += 3) {
    ASSERT_EQ(std::isnan(a[i]), std::isnan(b[i]) && std::isnan(b[i + 1]) && std::isnan(b[i + 2]));
    if (std::isnan(a[i])) continue;
    max_error =
        std::max(max_error, angle_degrees({a[i], a[i + 1], a[i + 2]}, {b[i], b[i + 1], b[i + 2]}));
  }
  EXPECT_LE(max_error, 0.04);
  EXPECT_GT(max_error, 0);  // lossy: not the float32 values themselves
  // Decoding is deterministic and encoding what was decoded gives the same blob.
  EXPECT_EQ(encode_tile(out, parse_codec("normal_oct")), blob);
  const size_t zstd = encode_tile(in, parse_codec("zstd")).size();
  EXPECT_LT(blob.size() * 8, zstd) << blob.size() << " vs " << zstd;
}

TEST(NormalOct, CodecNamesLevelsAndTheLayersItHolds) {
  EXPECT_EQ(parse_codec("normal_oct").kind, Codec::Kind::NormalOct);
  EXPECT_EQ(parse_codec("normal_oct").level, Codec::kNormalOctLevel);
  EXPECT_EQ(parse_codec("normal_oct:-1").level, -1);
  EXPECT_FALSE(parse_codec("normal_oct").lossless());
  EXPECT_TRUE(parse_codec("zstd").lossless());
  for (const char* bad : {"normal_oct:0", "normal_oct:", "normal_oct16", "normal_oct:99"})
    EXPECT_THROW(parse_codec(bad), Error) << bad;
  EXPECT_THROW(encode_tile(test::smooth_tile(8), parse_codec("normal_oct")), Error);  // 1 channel

  TempDir dir;
  auto store = Store::open(dir.file("s.mqs"), Store::Mode::Create);
  LayerInfo l;
  l.name = "n";
  l.channels = 1;
  l.codec = "normal_oct";
  try {
    store->create_layer(l);
    FAIL() << "a float32 x 1 layer accepted codec normal_oct";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("layer 'n': codec normal_oct holds unit normals"),
              std::string::npos)
        << e.what();
  }
}

TEST(NormalOct, DamagedPayloadIsRefused) {
  auto blob = encode_tile(normal_tile(32), parse_codec("normal_oct"));
  blob[blob.size() / 2] ^= std::byte{0x40};
  EXPECT_THROW(decode_tile(blob), Error);  // zstd's checksum
  auto header = encode_tile(normal_tile(32), parse_codec("normal_oct"));
  header[12] = std::byte{1};  // 1 channel: not what normal_oct holds
  EXPECT_THROW(decode_tile(header), Error);
}

// A batch writing all four children builds their parent's overview from the tiles as stored
// (decoded), as update_overviews does from the store: the same overview either way.
TEST(NormalOct, OverviewsDoNotDependOnHowTilesWereBatched) {
  TempDir dir;
  LayerInfo l;
  l.name = "normal";
  l.channels = 3;
  l.tile_size = 64;
  l.level = 2;
  l.codec = "normal_oct";
  const CellId parent = *CellId::FromText("Q1");
  std::vector<std::byte> built_by_batch, built_by_update;  // the overview's decoded floats
  for (bool one_batch : {true, false}) {
    auto store = Store::open(dir.file(one_batch ? "a.mqs" : "b.mqs"), Store::Mode::Create);
    store->create_layer(l);
    Store::Batch batch(*store);
    for (int k = 0; k < 4; ++k) {
      if (one_batch)
        batch.put_tile("normal", parent.child(k), normal_tile(64));
      else
        store->put_tile("normal", parent.child(k), normal_tile(64));
    }
    batch.commit();
    store->update_overviews("normal");
    const auto overview = store->get_overview("normal", parent);
    ASSERT_TRUE(overview);
    (one_batch ? built_by_batch : built_by_update) = overview->bytes;
  }
  EXPECT_EQ(built_by_batch, built_by_update);
}

}  // namespace
}  // namespace maquette
