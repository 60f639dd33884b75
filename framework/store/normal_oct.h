// Unit normals in two small integers: the octahedral encoding of Cigolle, Donow, Evangelakos,
// Mara, McGuire and Meyer, "A Survey of Efficient Representations for Independent Unit Vectors"
// (JCGT 3(2), 2014), the payload of the store's `normal_oct` codec (codec.h, README.md).
//
// A direction (x, y, z) is projected onto the octahedron |x| + |y| + |z| = 1; the upper half
// (z >= 0) is the square |u| + |v| <= 1 of (u, v) = (x, y) / (|x| + |y| + |z|), and the lower half
// is folded over the square's corners. u and v are stored as integers in [-kOctMax, kOctMax]
// (kOctBits bits each, sign included). Of the four integer points around (u, v) * kOctMax the
// encoder keeps the one whose direction is nearest to the normal ("precise" in the paper), which
// bounds the angular error by ~0.04 degrees (0.0393 over 10^6 directions spread over the sphere,
// tests/store/normal_oct_test.cpp; rounding u and v gives up to 0.059, benchmarks/README.md).
// A missing normal (NaN) is kOctMissing in both integers.
#pragma once

#include <array>
#include <cstdint>
#include <span>

namespace maquette {

inline constexpr int kOctBits = 12;
inline constexpr int kOctMax = (1 << (kOctBits - 1)) - 1;  // 2047
inline constexpr int16_t kOctMissing = INT16_MIN;

// `normal` need not be unit length; NaN in any component makes it missing. Throws
// maquette::Error for a zero or infinite vector, which has no direction.
std::array<int16_t, 2> oct_encode(std::array<float, 3> normal);
// The unit vector of an encoded pair (NaN x 3 for kOctMissing). Throws maquette::Error for
// integers out of range (a damaged blob).
std::array<float, 3> oct_decode(std::array<int16_t, 2> code);

// A tile of N x N float normals (3 interleaved channels) as 2 * N * N uint16 values ready for
// byte shuffling and zstd: all u, then all v, each the difference between a pixel's code and its
// prediction from the left, upper and upper-left pixels' codes (a + b - c, the plane through
// them; the left or upper pixel alone on the first row and column), zigzag-mapped ((d << 1) ^
// (d >> 15)) so that small differences of either sign have a zero high byte. Differences wrap
// modulo 2^16, so any codes (kOctMissing included) round-trip exactly.
void oct_encode_tile(std::span<const float> normals, int size, std::span<uint16_t> out);
void oct_decode_tile(std::span<const uint16_t> in, int size, std::span<float> normals);

}  // namespace maquette
