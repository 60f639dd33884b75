#include "render/edge_texels.h"

#include <cmath>

namespace maquette {

EdgeTexels::EdgeTexels(const Store& store, const Grid& grid, const LayerInfo& texture, int reach)
    : sampler_(store, grid, texture, texture.level, false),
      channels_(texture.channels),
      reach_(reach),
      tile_size_(texture.tile_size) {
  faces_.reserve(size_t(grid.num_faces()));
  for (int face = 0; face < grid.num_faces(); ++face)
    faces_.push_back(grid.plane_square(CellId::FromFace(face)));
  texel_ = faces_.front().side / double(int64_t(1) << texture.level) / texture.tile_size;
}

bool EdgeTexels::read(Key k, Texel& out) {
  const PlanePoint centre{(double(k.x) + 0.5) * texel_, (double(k.y) + 0.5) * texel_};
  bool on_plane = false;
  for (const PlaneSquare& sq : faces_)
    on_plane = on_plane || (centre.x > sq.x_min && centre.x < sq.x_min + sq.side &&
                            centre.y < sq.y_max && centre.y > sq.y_max - sq.side);
  float texel[4];
  if (!on_plane || !sampler_.sample(centre, texel)) return false;
  for (int b = 0; b < 3; ++b) out[size_t(b)] = texel[channels_ < 3 ? 0 : b];
  return true;
}

bool EdgeTexels::data(Key k, Texel& out) {
  return read(k, out) && !std::isnan(out[0]) && !std::isnan(out[1]) && !std::isnan(out[2]);
}

bool EdgeTexels::tiles_near(Key k) {
  auto cell_of = [this](int64_t t) {
    return t >= 0 ? t / tile_size_ : -((-t - 1) / tile_size_) - 1;  // floor division
  };
  const Key cell{cell_of(k.x), cell_of(k.y)};
  auto [it, fresh] = tiles_near_.try_emplace(cell, false);
  if (!fresh) return it->second;
  // The cells are read at points n = tile_size texels apart, so every cell holding a texel within
  // the reach holds one of them (one more: the cells' lattice is the texels' shifted at level 0).
  const int64_t m = (reach_ + tile_size_ - 1) / tile_size_ + 1, half = tile_size_ / 2;
  Texel ignored;
  for (int64_t dy = -m; dy <= m && !it->second; ++dy)
    for (int64_t dx = -m; dx <= m && !it->second; ++dx)
      it->second =
          read({(cell.x + dx) * tile_size_ + half, (cell.y + dy) * tile_size_ + half}, ignored);
  return it->second;
}

const EdgeTexels::Texel& EdgeTexels::resolved(Key k) {
  auto [it, fresh] = resolved_.try_emplace(k, Texel{NAN, NAN, NAN});
  Texel& value = it->second;
  if (!fresh || data(k, value)) return value;
  value = {NAN, NAN, NAN};
  if (!tiles_near(k)) return value;
  // Rings of growing Chebyshev radius r; a ring's texels are at least r from k, so the search
  // stops once r * r reaches the nearest squared distance found.
  int64_t best = int64_t(reach_) * reach_ + 1;  // beyond the reach: none
  Texel found;
  auto consider = [&](int64_t dx, int64_t dy) {
    const int64_t d2 = dx * dx + dy * dy;
    if (d2 < best && data({k.x + dx, k.y + dy}, found)) best = d2, value = found;
  };
  for (int64_t r = 1; r <= reach_ && r * r < best; ++r) {
    for (int64_t d = -r; d <= r; ++d) consider(d, -r), consider(d, r);
    for (int64_t d = -r + 1; d < r; ++d) consider(-r, d), consider(r, d);
  }
  return value;
}

bool EdgeTexels::sample(PlanePoint q, float* out) {
  const double u = q.x / texel_ - 0.5, v = q.y / texel_ - 0.5;
  const double x0 = std::floor(u), y0 = std::floor(v), fx = u - x0, fy = v - y0;
  const double weights[4] = {(1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy};
  double sum[3] = {0, 0, 0}, weight = 0;
  for (int j = 0; j < 4; ++j) {
    const Texel& t = resolved({int64_t(x0) + (j & 1), int64_t(y0) + (j >> 1)});
    if (std::isnan(t[0])) continue;
    for (int b = 0; b < 3; ++b) sum[b] += weights[j] * t[size_t(b)];
    weight += weights[j];
  }
  if (weight == 0) return false;
  for (int b = 0; b < 3; ++b) out[b] = float(sum[b] / weight);
  return true;
}

}  // namespace maquette
