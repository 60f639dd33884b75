#include "store/normal_oct.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "core/error.h"

namespace maquette {
namespace {

double sign_not_zero(double v) { return v >= 0 ? 1.0 : -1.0; }

// Euclidean length (std::hypot's care for overflow is not needed here: components of floats or
// of the unit square, squared in double).
double length(double x, double y, double z) { return std::sqrt(x * x + y * y + z * z); }

// The point of the square [-1, 1]^2 for integers (a, b), unfolded onto the octahedron.
std::array<double, 3> octahedron_point(int a, int b) {
  const double u = double(a) / kOctMax, v = double(b) / kOctMax;
  const double z = 1 - std::abs(u) - std::abs(v);
  if (z >= 0) return {u, v, z};
  return {(1 - std::abs(v)) * sign_not_zero(u), (1 - std::abs(u)) * sign_not_zero(v), z};
}

// Cosine of the angle between `n` (unit) and the direction of `p`.
double cosine(const std::array<double, 3>& n, const std::array<double, 3>& p) {
  return (n[0] * p[0] + n[1] * p[1] + n[2] * p[2]) / length(p[0], p[1], p[2]);
}

// Wrapping differences, zigzag-mapped, and back.
uint16_t zigzag(int code, int prediction) {
  const auto d = int16_t(uint16_t(code - prediction));
  return uint16_t(uint16_t(d) << 1) ^ uint16_t(d >> 15);
}
int16_t unzigzag(uint16_t z, int prediction) {
  const auto d = uint16_t((z >> 1) ^ uint16_t(-(z & 1)));
  return int16_t(uint16_t(d + uint16_t(prediction)));
}

// The prediction of the code at (col, row) of one plane of codes (row-major, `size` wide), from
// codes already known in raster order.
int predict(const int16_t* plane, int size, int col, int row) {
  if (row == 0) return col == 0 ? 0 : plane[col - 1];
  const int16_t* above = plane + size_t(row - 1) * size_t(size);
  if (col == 0) return above[0];
  return plane[size_t(row) * size_t(size) + size_t(col) - 1] + above[col] - above[col - 1];
}

}  // namespace

std::array<int16_t, 2> oct_encode(std::array<float, 3> normal) {
  if (std::isnan(normal[0]) || std::isnan(normal[1]) || std::isnan(normal[2]))
    return {kOctMissing, kOctMissing};
  const double norm = length(normal[0], normal[1], normal[2]);
  if (!(norm > 0) || std::isinf(norm))
    throw Error("normal (" + std::to_string(normal[0]) + ", " + std::to_string(normal[1]) + ", " +
                std::to_string(normal[2]) + ") has no direction");
  const std::array<double, 3> n = {normal[0] / norm, normal[1] / norm, normal[2] / norm};
  const double l1 = std::abs(n[0]) + std::abs(n[1]) + std::abs(n[2]);
  double u = n[0] / l1, v = n[1] / l1;
  if (n[2] < 0) {
    const double folded_u = (1 - std::abs(v)) * sign_not_zero(u);
    v = (1 - std::abs(u)) * sign_not_zero(v);
    u = folded_u;
  }
  const int a0 = int(std::floor(u * kOctMax)), b0 = int(std::floor(v * kOctMax));
  std::array<int16_t, 2> best{};
  double best_cosine = -2;
  for (int a = a0; a <= a0 + 1; ++a)
    for (int b = b0; b <= b0 + 1; ++b) {
      const int ca = std::clamp(a, -kOctMax, kOctMax), cb = std::clamp(b, -kOctMax, kOctMax);
      const double c = cosine(n, octahedron_point(ca, cb));
      if (c > best_cosine) {
        best_cosine = c;
        best = {int16_t(ca), int16_t(cb)};
      }
    }
  return best;
}

std::array<float, 3> oct_decode(std::array<int16_t, 2> code) {
  if (code[0] == kOctMissing && code[1] == kOctMissing) {
    constexpr float nan = std::numeric_limits<float>::quiet_NaN();
    return {nan, nan, nan};
  }
  if (std::abs(code[0]) > kOctMax || std::abs(code[1]) > kOctMax)
    throw Error("octahedral normal (" + std::to_string(code[0]) + ", " + std::to_string(code[1]) +
                ") out of [-" + std::to_string(kOctMax) + ", " + std::to_string(kOctMax) + "]");
  const std::array<double, 3> p = octahedron_point(code[0], code[1]);
  const double norm = length(p[0], p[1], p[2]);
  return {float(p[0] / norm), float(p[1] / norm), float(p[2] / norm)};
}

void oct_encode_tile(std::span<const float> normals, int size, std::span<uint16_t> out) {
  const size_t pixels = size_t(size) * size_t(size);
  std::vector<int16_t> codes(2 * pixels);  // the u plane, then the v plane
  for (size_t i = 0; i < pixels; ++i) {
    const auto code = oct_encode({normals[3 * i], normals[3 * i + 1], normals[3 * i + 2]});
    codes[i] = code[0];
    codes[pixels + i] = code[1];
  }
  for (size_t k = 0; k < 2; ++k) {
    const int16_t* plane = codes.data() + k * pixels;
    for (int row = 0; row < size; ++row)
      for (int col = 0; col < size; ++col) {
        const size_t i = size_t(row) * size_t(size) + size_t(col);
        out[k * pixels + i] = zigzag(plane[i], predict(plane, size, col, row));
      }
  }
}

void oct_decode_tile(std::span<const uint16_t> in, int size, std::span<float> normals) {
  const size_t pixels = size_t(size) * size_t(size);
  std::vector<int16_t> codes(2 * pixels);
  for (size_t k = 0; k < 2; ++k) {
    int16_t* plane = codes.data() + k * pixels;
    for (int row = 0; row < size; ++row)
      for (int col = 0; col < size; ++col) {
        const size_t i = size_t(row) * size_t(size) + size_t(col);
        plane[i] = unzigzag(in[k * pixels + i], predict(plane, size, col, row));
      }
  }
  for (size_t i = 0; i < pixels; ++i) {
    const auto n = oct_decode({codes[i], codes[pixels + i]});
    std::copy(n.begin(), n.end(), normals.begin() + std::ptrdiff_t(3 * i));
  }
}

}  // namespace maquette
