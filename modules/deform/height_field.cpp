#include "height_field.h"

#include <algorithm>
#include <cmath>

namespace maquette::deform {

SurfacePoint locate(const HeightField& field, double col, double row) {
  const int c = int(std::floor(col)), r = int(std::floor(row));
  const double fx = col - c, fy = row - r;
  const size_t v00 = field.index(c, r), v11 = field.index(c + 1, r + 1);
  if (fx >= fy) return {{v00, field.index(c + 1, r), v11}, {1 - fx, fx - fy, fy}, {col, row}};
  return {{v00, field.index(c, r + 1), v11}, {1 - fy, fy - fx, fx}, {col, row}};
}

double height_at(const HeightField& field, const SurfacePoint& p) {
  return p.weight[0] * field.z[p.vertex[0]] + p.weight[1] * field.z[p.vertex[1]] +
         p.weight[2] * field.z[p.vertex[2]];
}

double height_at_clamped(const HeightField& field, double col, double row) {
  return height_at(field, locate(field, clamped_col(field, col), clamped_row(field, row)));
}

double clamped_col(const HeightField& field, double col) {
  return std::clamp(col, 0.0, std::nextafter(double(field.width - 1), 0.0));
}

double clamped_row(const HeightField& field, double row) {
  return std::clamp(row, 0.0, std::nextafter(double(field.height - 1), 0.0));
}

std::array<double, 6> cotangent_weights(const HeightField& field, int col, int row) {
  const size_t v = field.index(col, row);
  std::array<size_t, 6> n{};
  for (size_t k = 0; k < 6; ++k)
    n[k] = field.index(col + kNeighbours[k][0], row + kNeighbours[k][1]);
  // cot of the angle at `apex` between the edges to a and b.
  auto cot = [&](size_t apex, size_t a, size_t b) {
    const double ax = field.east[a] - field.east[apex], ay = field.north[a] - field.north[apex];
    const double bx = field.east[b] - field.east[apex], by = field.north[b] - field.north[apex];
    return (ax * bx + ay * by) / std::abs(ax * by - ay * bx);
  };
  std::array<double, 6> w{};
  for (size_t k = 0; k < 6; ++k) {
    const size_t a = n[k], b = n[(k + 1) % 6];
    w[k] += 0.5 * std::max(0.0, cot(b, v, a));
    w[(k + 1) % 6] += 0.5 * std::max(0.0, cot(a, v, b));
  }
  double sum = 0;
  for (const double x : w) sum += x;
  for (double& x : w) x /= sum;
  return w;
}

}  // namespace maquette::deform
