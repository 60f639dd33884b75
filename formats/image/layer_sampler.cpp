#include "image/layer_sampler.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <mutex>
#include <optional>
#include <utility>

#include "core/halo.h"
#include "core/round_half_away.h"

namespace maquette {
namespace {

// The nearest sample of a halo tile to (u, v), in pixels from the centre of pixel (0, 0): its
// column and row.
std::pair<int, int> nearest_sample(const Tile<float>& t, double u, double v) {
  const int n = t.size();
  return {std::clamp(int(round_half_away(u)), 0, n - 1),
          std::clamp(int(round_half_away(v)), 0, n - 1)};
}

// std::clamp(int(std::floor(x)), -1, n - 1), for x not NaN: the floor of x clamped first (the
// same, as the bounds are whole), by truncation (x >= -1) and a step down where it rounded up.
int floor_within(double x, int n) {
  const double clamped = std::clamp(x, -1.0, double(n - 1));
  const int whole = int(clamped);
  return whole - int(double(whole) > clamped);
}

// Reads `channels` channels (kChannels when not 0: the loops unrolled) of a halo tile bilinearly
// at (u, v) into out[0 .. channels - 1], leaving out samples not finite (the weights
// renormalized), or the nearest's NaN when it is not finite: the places and weights found once
// for all the channels.
template <int kChannels>
void bilinear(const Tile<float>& t, double u, double v, int channels, float* out) {
  if constexpr (kChannels > 0) channels = kChannels;
  const int n = t.size();
  const int c0 = floor_within(u, n), r0 = floor_within(v, n);
  const double fx = std::clamp(u - c0, 0.0, 1.0), fy = std::clamp(v - r0, 0.0, 1.0);
  const double w[4] = {(1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy};
  // The corners (c0, r0), (c0 + 1, r0), (c0, r0 + 1), (c0 + 1, r0 + 1), each `channels` floats.
  const float* const top = &t.at(c0, r0);
  const float* const bottom = &t.at(c0, r0 + 1);
  const float* const corner[4] = {top, top + channels, bottom, bottom + channels};
  const double weight = 0.0 + w[0] + w[1] + w[2] + w[3];
  for (int k = 0; k < channels; ++k) {
    // With the four samples finite (imagery without nodata near), the sum of all four: what the
    // loop below gives then, in the same order. A sample not finite makes the sum not finite
    // (its product with any weight, 0 too, is infinite or NaN).
    const double all =
        0.0 + w[0] * corner[0][k] + w[1] * corner[1][k] + w[2] * corner[2][k] + w[3] * corner[3][k];
    if (std::isfinite(all)) {
      out[k] = float(all / weight);
      continue;
    }
    // Missing samples near: left out, or the nearest's NaN.
    const auto [nc, nr] = nearest_sample(t, u, v);
    if (const float nearest = t.at(nc, nr, k); !std::isfinite(nearest)) {
      out[k] = nearest;
      continue;
    }
    double sum = 0, partial = 0;
    for (int j = 0; j < 4; ++j)
      if (const float s = corner[j][k]; std::isfinite(s)) sum += w[j] * s, partial += w[j];
    out[k] = float(sum / partial);  // the nearest sample (a corner) is finite: some weight is not 0
  }
}

// A quadratic B-spline's three weights at offset t in [-1/2, 1/2] from the middle sample.
std::array<double, 3> quadratic_bspline(double t) {
  return {0.5 * (0.5 - t) * (0.5 - t), 0.75 - t * t, 0.5 * (0.5 + t) * (0.5 + t)};
}

// Reads each channel of a halo tile at (u, v) as LayerSampler::Read::kSmoothLabels says: the value
// of the 3 x 3 samples around the nearest whose quadratic B-spline weights sum highest.
void smooth_labels(const Tile<float>& t, double u, double v, int channels, float* out) {
  const auto [nc, nr] = nearest_sample(t, u, v);
  const auto wx = quadratic_bspline(std::clamp(u - nc, -0.5, 0.5));
  const auto wy = quadratic_bspline(std::clamp(v - nr, -0.5, 0.5));
  // The nearest sample first, so that it wins ties; then the others in row order.
  constexpr int kOrder[9][2] = {{1, 1}, {0, 0}, {1, 0}, {2, 0}, {0, 1},
                                {2, 1}, {0, 2}, {1, 2}, {2, 2}};
  for (int k = 0; k < channels; ++k) {
    std::array<float, 9> value;
    std::array<double, 9> weight;
    int distinct = 0;
    for (const auto& [i, j] : kOrder) {
      const float label = t.at(nc + i - 1, nr + j - 1, k);
      const double w = wx[size_t(i)] * wy[size_t(j)];
      int d = 0;  // missing samples (NaN) are one value
      while (d < distinct &&
             !(value[size_t(d)] == label || (std::isnan(value[size_t(d)]) && std::isnan(label))))
        ++d;
      if (d == distinct) value[size_t(distinct)] = label, weight[size_t(distinct++)] = 0;
      weight[size_t(d)] += w;
    }
    int best = 0;  // the first of the heaviest, in the order first met
    for (int d = 1; d < distinct; ++d)
      if (weight[size_t(d)] > weight[size_t(best)]) best = d;
    out[k] = value[size_t(best)];
  }
}

// Samples every channel of a halo tile at (u, v) into out[0 .. channels - 1].
void sample_tile(const Tile<float>& t, double u, double v, int channels, LayerSampler::Read read,
                 float* out) {
  if (read == LayerSampler::Read::kNearest) {
    const auto [nc, nr] = nearest_sample(t, u, v);
    for (int k = 0; k < channels; ++k) out[k] = t.at(nc, nr, k);
  } else if (read == LayerSampler::Read::kSmoothLabels) {
    smooth_labels(t, u, v, channels, out);
  } else if (channels == 3) {  // RGB imagery, the renderer's texture
    bilinear<3>(t, u, v, channels, out);
  } else {
    bilinear<0>(t, u, v, channels, out);
  }
}

}  // namespace

struct LayerSampler::Halo {
  std::once_flag made;
  std::optional<Tile<float>> tile;  // none when the cell has no tile
  CellId cell;
  PlaneSquare square;
  bool used = true;
};

class LayerSampler::Tiles {
 public:
  Tiles(const Store& store, const Grid& grid, const LayerInfo& layer, int level, bool shared)
      : store_(store), grid_(grid), layer_(layer), level_(level), shared_(shared) {}

  const Grid& grid() const { return grid_; }
  const LayerInfo& layer() const { return layer_; }
  int level() const { return level_; }

  // `cell`'s tile with its halo, assembled by the first sampler that asks.
  const Halo& halo(CellId cell) {
    Halo& h = entry(halo_, cell);
    std::call_once(h.made, [&] {
      h.cell = cell;
      h.square = grid_.plane_square(cell);
      if (raw(cell))
        h.tile =
            assemble_halo(grid_, cell, layer_.tile_size, 1, [this](CellId c) -> const Tile<float>* {
              const auto& tile = raw(c);  // in the cache: read, not copied
              return tile ? &*tile : nullptr;
            });
    });
    return h;
  }

  void forget_unused() {
    erase_unused(halo_);
    erase_unused(raw_);
  }

  // `cell`'s tile, read and decoded by the first that asks (an overview's below the layer's level).
  const std::optional<Tile<float>>& raw(CellId cell) {
    Raw& r = entry(raw_, cell);
    std::call_once(r.read, [&] {
      const auto bytes = cell.level() < layer_.level ? store_.get_overview(layer_.name, cell)
                                                     : store_.get_tile(layer_.name, cell);
      if (bytes) r.tile = to_tile<float>(*bytes, layer_.nodata ? &*layer_.nodata : nullptr);
    });
    return r.tile;
  }

 private:
  struct Raw {
    std::once_flag read;
    std::optional<Tile<float>> tile;
    bool used = true;
  };

  // `cell`'s entry of `entries`, made when missing and marked used (under the lock when shared:
  // the maps' nodes stay put, so the entry is then read and made without it).
  template <typename Map>
  typename Map::mapped_type& entry(Map& entries, CellId cell) {
    std::unique_lock<std::mutex> lock;
    if (shared_) lock = std::unique_lock(mutex_);
    auto& e = entries.try_emplace(cell).first->second;
    e.used = true;
    return e;
  }

  // Erases the entries not used since the last call and marks the others unused.
  template <typename Map>
  static void erase_unused(Map& entries) {
    for (auto it = entries.begin(); it != entries.end();)
      if (it->second.used)
        (it++)->second.used = false;
      else
        it = entries.erase(it);
  }

  const Store& store_;
  const Grid& grid_;
  const LayerInfo& layer_;
  int level_;
  bool shared_;
  std::mutex mutex_;  // the maps' structure, when shared
  std::map<CellId, Raw> raw_;
  std::map<CellId, Halo> halo_;
};

std::shared_ptr<LayerSampler::Tiles> LayerSampler::shared_tiles(const Store& store,
                                                                const Grid& grid,
                                                                const LayerInfo& layer, int level) {
  return std::make_shared<Tiles>(store, grid, layer, level, true);
}

void LayerSampler::forget_unused(Tiles& tiles) { tiles.forget_unused(); }

const Tile<float>* LayerSampler::tile(Tiles& tiles, CellId cell) {
  const auto& t = tiles.raw(cell);
  return t ? &*t : nullptr;
}

LayerSampler::LayerSampler(const Store& store, const Grid& grid, const LayerInfo& layer, int level,
                           Read read)
    : LayerSampler(std::make_shared<Tiles>(store, grid, layer, level, false), read) {}

LayerSampler::LayerSampler(std::shared_ptr<Tiles> tiles, Read read)
    : tiles_(std::move(tiles)), layer_(tiles_->layer()), read_(read) {}

int LayerSampler::level() const { return tiles_->level(); }

bool LayerSampler::sample(LonLat p, CellId cell, float* out) {
  if (!last_cell_ || last_cell_->cell != cell) last_cell_ = &tiles_->halo(cell);
  if (!last_cell_->tile) return false;
  read(*last_cell_, tiles_->grid().forward(p), out);
  return true;
}

bool LayerSampler::sample(PlanePoint q, float* out) {
  auto inside = [&q](const PlaneSquare& sq) {
    return q.x >= sq.x_min && q.x <= sq.x_min + sq.side && q.y <= sq.y_max &&
           q.y >= sq.y_max - sq.side;
  };
  if (!last_ || !inside(last_->square)) {
    const Grid& grid = tiles_->grid();
    last_ = &tiles_->halo(grid.cell_from_point(grid.inverse(q), tiles_->level()));
  }
  if (!last_->tile) return false;
  read(*last_, q, out);
  return true;
}

void LayerSampler::read(const Halo& h, PlanePoint q, float* out) const {
  const PlaneSquare& sq = h.square;
  const int n = layer_.tile_size;
  const double u = (q.x - sq.x_min) / sq.side * n - 0.5, v = (sq.y_max - q.y) / sq.side * n - 0.5;
  sample_tile(*h.tile, u, v, layer_.channels, read_, out);
}

void LayerSampler::forget_unused() {
  start_run();
  tiles_->forget_unused();
}

}  // namespace maquette
