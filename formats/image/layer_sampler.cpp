#include "image/layer_sampler.h"

#include <algorithm>
#include <cmath>
#include <tuple>

#include "core/halo.h"
#include "core/round_half_away.h"

namespace maquette {
namespace {

// Samples every channel of a halo tile at (u, v), in pixels from the centre of pixel (0, 0), into
// out[0 .. channels - 1]: the places and weights found once for all of them.
void sample_tile(const Tile<float>& t, double u, double v, int channels, bool bilinear,
                 float* out) {
  const int n = t.size();
  const int nc = std::clamp(int(round_half_away(u)), 0, n - 1);
  const int nr = std::clamp(int(round_half_away(v)), 0, n - 1);
  const int c0 = std::clamp(int(std::floor(u)), -1, n - 1);
  const int r0 = std::clamp(int(std::floor(v)), -1, n - 1);
  const double fx = std::clamp(u - c0, 0.0, 1.0), fy = std::clamp(v - r0, 0.0, 1.0);
  const std::tuple<int, int, double> corners[4] = {
      {0, 0, (1 - fx) * (1 - fy)}, {1, 0, fx * (1 - fy)}, {0, 1, (1 - fx) * fy}, {1, 1, fx * fy}};
  for (int k = 0; k < channels; ++k) {
    const float nearest = t.at(nc, nr, k);
    if (!bilinear || !std::isfinite(nearest)) {
      out[k] = nearest;
      continue;
    }
    double sum = 0, weight = 0;
    for (const auto& [dc, dr, w] : corners)
      if (const float s = t.at(c0 + dc, r0 + dr, k); std::isfinite(s)) sum += w * s, weight += w;
    out[k] = float(sum / weight);  // the nearest sample is finite, so some weight is not 0
  }
}

}  // namespace

LayerSampler::LayerSampler(const Store& store, const Grid& grid, const LayerInfo& layer, int level,
                           bool bilinear)
    : store_(store),
      grid_(grid),
      layer_(layer),
      level_(level),
      base_(level == layer.level),
      bilinear_(bilinear) {}

bool LayerSampler::sample(LonLat p, CellId cell, float* out) {
  const Halo& h = halo(cell);
  if (!h.tile) return false;
  read(h, grid_.forward(p), out);
  return true;
}

bool LayerSampler::sample(PlanePoint q, float* out) {
  auto inside = [&q](const PlaneSquare& sq) {
    return q.x >= sq.x_min && q.x <= sq.x_min + sq.side && q.y <= sq.y_max &&
           q.y >= sq.y_max - sq.side;
  };
  if (!last_ || !inside(last_->square))
    last_ = &halo(grid_.cell_from_point(grid_.inverse(q), level_));
  if (!last_->tile) return false;
  read(*last_, q, out);
  return true;
}

void LayerSampler::read(const Halo& h, PlanePoint q, float* out) const {
  const PlaneSquare& sq = h.square;
  const int n = layer_.tile_size;
  const double u = (q.x - sq.x_min) / sq.side * n - 0.5, v = (sq.y_max - q.y) / sq.side * n - 0.5;
  sample_tile(*h.tile, u, v, layer_.channels, bilinear_, out);
}

namespace {

// Erases the entries not used since the last call and marks the others unused.
template <typename Map>
void erase_unused(Map& entries) {
  for (auto it = entries.begin(); it != entries.end();)
    if (it->second.used)
      (it++)->second.used = false;
    else
      it = entries.erase(it);
}

}  // namespace

void LayerSampler::forget_unused() {
  last_ = nullptr;
  erase_unused(halo_);
  erase_unused(raw_);
}

const LayerSampler::Halo& LayerSampler::halo(CellId cell) {
  auto [it, fresh] = halo_.try_emplace(cell);
  Halo& h = it->second;
  h.used = true;
  if (fresh) {
    h.square = grid_.plane_square(cell);
    if (raw(cell))
      h.tile =
          assemble_halo(grid_, cell, layer_.tile_size, 1, [this](CellId c) -> const Tile<float>* {
            const auto& tile = raw(c);  // in the cache: read, not copied
            return tile ? &*tile : nullptr;
          });
  }
  return h;
}

const std::optional<Tile<float>>& LayerSampler::raw(CellId cell) {
  auto [it, fresh] = raw_.try_emplace(cell);
  Raw& r = it->second;
  r.used = true;
  if (fresh) {
    const auto bytes =
        base_ ? store_.get_tile(layer_.name, cell) : store_.get_overview(layer_.name, cell);
    if (bytes) r.tile = to_tile<float>(*bytes, layer_.nodata ? &*layer_.nodata : nullptr);
  }
  return r.tile;
}

}  // namespace maquette
