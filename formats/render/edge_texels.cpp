#include "render/edge_texels.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>
#include <tuple>
#include <utility>

#include "core/error.h"

namespace maquette {
namespace {

int64_t floor_div(int64_t a, int64_t b) { return a >= 0 ? a / b : -((-a - 1) / b) - 1; }

// The search order of offset (dx, dy) among those of its Chebyshev ring r (edge_texels.h): the
// ring's rows dy = -r and r, x ascending, each column's two in that order; then its columns
// dx = -r and r, y ascending (corners excluded), likewise.
int64_t ring_order(int64_t dx, int64_t dy, int64_t r) {
  if (std::abs(dy) == r) return 2 * (dx + r) + (dy > 0);
  return 2 * (2 * r + 1) + 2 * (dy + r - 1) + (dx > 0);
}

}  // namespace

EdgeTexels::EdgeTexels(std::shared_ptr<LayerSampler::Tiles> tiles, const Grid& grid,
                       const LayerInfo& texture, int reach)
    : sampler_(std::move(tiles), LayerSampler::Read::kNearest),
      channels_(texture.channels),
      reach_(reach),
      tile_size_(texture.tile_size),
      block_(std::max(64, 2 * reach)) {
  if (sampler_.layer().name != texture.name || sampler_.level() != texture.level)
    throw Error("EdgeTexels: the tiles are layer '" + sampler_.layer().name + "' at level " +
                std::to_string(sampler_.level()) + ", not the texture '" + texture.name +
                "' at its level " + std::to_string(texture.level));
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

bool EdgeTexels::tiles_near(Key b) {
  // The cells are read at points tile_size texels apart, so every cell holding a texel within the
  // reach holds one of them (one more each side: the cells' lattice is the texels' shifted at
  // level 0).
  const int64_t n = block_, t = tile_size_, half = t / 2;
  const int64_t x0 = floor_div(b.x * n - reach_, t) - 1,
                x1 = floor_div(b.x * n + n - 1 + reach_, t) + 1;
  const int64_t y0 = floor_div(b.y * n - reach_, t) - 1,
                y1 = floor_div(b.y * n + n - 1 + reach_, t) + 1;
  for (int64_t y = y0; y <= y1; ++y)
    for (int64_t x = x0; x <= x1; ++x) {
      auto it = has_tile_.find({x, y});
      if (it == has_tile_.end()) {
        Texel ignored;
        it = has_tile_.emplace(Key{x, y}, read({x * t + half, y * t + half}, ignored)).first;
      }
      if (it->second) return true;
    }
  return false;
}

EdgeTexels::Block EdgeTexels::resolve_block(Key b) {
  Block out;
  if (!tiles_near(b)) return out;
  // The window: the block and its reach around it, w texels a side from texel (x0, y0).
  const int64_t n = block_, reach = reach_, w = n + 2 * reach, x0 = b.x * n - reach,
                y0 = b.y * n - reach;
  std::vector<Texel> window(size_t(w * w));
  std::vector<uint8_t> has(size_t(w * w));
  for (int64_t y = 0; y < w; ++y)
    for (int64_t x = 0; x < w; ++x) {
      Texel& t = window[size_t(y * w + x)];
      has[size_t(y * w + x)] =
          read({x0 + x, y0 + y}, t) && !std::isnan(t[0]) && !std::isnan(t[1]) && !std::isnan(t[2]);
    }
  // below / above [x * n + j]: rows from the block's row j (the window's reach + j) down / up to
  // the nearest texel with data in the window's column x; reach + 1 where none within the reach.
  const int64_t none = reach + 1;
  std::vector<int64_t> below(size_t(w * n), none), above(size_t(w * n), none);
  for (int64_t x = 0; x < w; ++x) {
    for (int64_t y = 0, last = -2 * w; y < reach + n; ++y) {
      if (has[size_t(y * w + x)]) last = y;
      if (y >= reach) below[size_t(x * n + y - reach)] = std::min(none, y - last);
    }
    for (int64_t y = w - 1, last = 3 * w; y >= reach; --y) {
      if (has[size_t(y * w + x)]) last = y;
      if (y < reach + n) above[size_t(x * n + y - reach)] = std::min(none, last - y);
    }
  }
  // The nearest texel with data of a texel is, in its column, the column's nearest to its row:
  // among those 2 (2 reach + 1), the least squared distance, ties by the rings' order.
  out.resize(size_t(n * n));
  for (int64_t j = 0; j < n; ++j)
    for (int64_t i = 0; i < n; ++i) {
      const size_t at = size_t((reach + j) * w + reach + i);
      Texel& value = out[size_t(j * n + i)];
      value = has[at] ? window[at] : Texel{NAN, NAN, NAN};
      if (has[at]) continue;
      int64_t best = reach * reach + 1, best_dx = 0, best_dy = 0;  // beyond the reach: none
      for (int64_t dx = -reach; dx <= reach; ++dx) {
        const size_t column = size_t((reach + i + dx) * n + j);
        for (const int64_t dy : {-below[column], above[column]}) {
          const int64_t d2 = dx * dx + dy * dy;
          if (d2 > best || d2 > reach * reach) continue;
          if (d2 == best) {
            const int64_t r = std::max(std::abs(dx), std::abs(dy));
            const int64_t best_r = std::max(std::abs(best_dx), std::abs(best_dy));
            if (std::tuple(r, ring_order(dx, dy, r)) >=
                std::tuple(best_r, ring_order(best_dx, best_dy, best_r)))
              continue;
          }
          best = d2, best_dx = dx, best_dy = dy;
          value = window[size_t((reach + j + dy) * w + reach + i + dx)];
        }
      }
    }
  return out;
}

const EdgeTexels::Texel& EdgeTexels::resolved(Key k) {
  static const Texel kNone{NAN, NAN, NAN};
  const Key b{floor_div(k.x, block_), floor_div(k.y, block_)};
  auto it = blocks_.find(b);
  if (it == blocks_.end()) it = blocks_.emplace(b, resolve_block(b)).first;
  if (it->second.empty()) return kNone;
  return it->second[size_t((k.y - b.y * block_) * block_ + k.x - b.x * block_)];
}

void EdgeTexels::forget_unused() {
  sampler_.start_run();
  blocks_.clear();
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
