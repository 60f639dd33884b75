#include "pyramid_fill.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/error.h"

namespace maquette::terrain {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
// How far (pixels of a level) data are looked for around a void sample: within every level's
// window, which reaches at least 9 + kPyramidSweeps pixels beyond the tile's footprint.
constexpr int kReach = 16;

// Pixels of one level in global face pixel coordinates (at that level): [x0, x1) x [y0, y1).
struct Rect {
  int64_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;

  int64_t width() const { return x1 - x0; }
  int64_t height() const { return y1 - y0; }
  Rect grown(int64_t m) const { return {x0 - m, y0 - m, x1 + m, y1 + m}; }
  // The coarser level's pixels that the bilinear upsampling of these pixels reads: fine pixel i
  // reads coarse pixels floor((i - 1) / 2) .. floor((i + 1) / 2).
  Rect coarse_cover() const { return {(x0 - 1) >> 1, (y0 - 1) >> 1, (x1 >> 1) + 1, (y1 >> 1) + 1}; }
};

// Samples of one level over a rectangle, row-major.
struct Field {
  Rect rect;
  std::vector<float> v;

  explicit Field(const Rect& r) : rect(r), v(size_t(r.width() * r.height()), kNaN) {}
  size_t index(int64_t x, int64_t y) const {
    return size_t((y - rect.y0) * rect.width() + (x - rect.x0));
  }
  float at(int64_t x, int64_t y) const { return v[index(x, y)]; }
};

// `rect` of a tile (with its halo) whose first interior pixel is global pixel (ox, oy).
Field extract(const Tile<float>& tile, int64_t ox, int64_t oy, const Rect& rect) {
  const int64_t h = tile.halo(), n = tile.size();
  if (rect.x0 - ox < -h || rect.y0 - oy < -h || rect.x1 - ox > n + h || rect.y1 - oy > n + h)
    throw Error("terrain.fill_voids: a pyramid window reaches beyond its tile's halo");
  Field f(rect);
  for (int64_t y = rect.y0; y < rect.y1; ++y)
    for (int64_t x = rect.x0; x < rect.x1; ++x)
      f.v[f.index(x, y)] = tile.at(int(x - ox), int(y - oy));
  return f;
}

// Bilinear upsampling of the coarser level at fine pixel (x, y) from its coarse samples that are
// not NaN (NaN when none is): weights 9, 3, 3, 1 for the nearest, the two side and the diagonal
// coarse pixels. The side pixels are summed first, so a window turned by a multiple of 90
// degrees (across a face seam) gives the same bits.
float upsample(const Field& coarse, int64_t x, int64_t y) {
  struct Sum {
    double value = 0, weight = 0;
    Sum(float v, double w) {
      if (!std::isnan(v)) value = w * v, weight = w;
    }
  };
  const int64_t cx = x >> 1, cy = y >> 1;      // nearest
  const int64_t sx = x & 1 ? cx + 1 : cx - 1;  // the other column and row read
  const int64_t sy = y & 1 ? cy + 1 : cy - 1;
  const Sum nearest(coarse.at(cx, cy), 9), beside(coarse.at(sx, cy), 3),
      below(coarse.at(cx, sy), 3), diagonal(coarse.at(sx, sy), 1);
  const double weight = nearest.weight + (beside.weight + below.weight) + diagonal.weight;
  if (weight == 0) return kNaN;
  return float((nearest.value + (beside.value + below.value) + diagonal.value) / weight);
}

// kPyramidSweeps Jacobi sweeps of the 5-point Laplace equation over the samples of `f` that are
// NaN in `known` (same rectangle): each becomes the mean of its 4-neighbours that have a value
// within the rectangle (opposite neighbours summed first: same bits in turned windows), so a
// sample without one gets one from its neighbours (a void wider than the coarsest level's
// pixels closes). Samples near the rectangle's edge lack neighbours: the caller reads only those
// at least kPyramidSweeps + 1 pixels inside.
void smooth(Field& f, const std::vector<char>& fixed) {
  const int64_t w = f.rect.width(), h = f.rect.height();
  std::vector<float> next = f.v;
  for (int sweep = 0; sweep < kPyramidSweeps; ++sweep) {
    for (int64_t y = 0; y < h; ++y)
      for (int64_t x = 0; x < w; ++x) {
        const size_t i = size_t(y * w + x);
        if (fixed[i]) continue;
        int count = 0;
        const auto value = [&](bool inside, size_t j) -> double {
          if (!inside || std::isnan(f.v[j])) return 0;
          ++count;
          return f.v[j];
        };
        const double across = value(x > 0, i - 1) + value(x + 1 < w, i + 1);
        const double along = value(y > 0, i - size_t(w)) + value(y + 1 < h, i + size_t(w));
        next[i] = count == 0 ? f.v[i] : float((across + along) / count);
      }
    f.v.swap(next);  // `next` keeps the fixed samples, and every free one is written again
  }
}

// One level of the pyramid as the fill uses it.
struct Level {
  Rect exact;          // where the fill of this level must be exact
  Field data;          // the level's samples over `exact` grown by kPyramidSweeps + 1
  Field fill{Rect{}};  // the fill over the same rectangle
  // Per sample of `data`: inside the footprint, or holding data (empty: no footprint, all are).
  std::vector<char> domain;

  bool in_domain(size_t i) const { return domain.empty() || domain[i]; }
  bool is_void(size_t i) const { return std::isnan(data.v[i]) && in_domain(i); }
  bool has_void(const Rect& r) const {
    for (int64_t y = r.y0; y < r.y1; ++y)
      for (int64_t x = r.x0; x < r.x1; ++x)
        if (is_void(data.index(x, y))) return true;
    return false;
  }

  // The samples the fill keeps: those with data, except, on coarser levels, those next to a void,
  // whose means mix in less of their block where it is void and so lean away from the void's
  // side; and those outside the footprint, NaN, which take no part.
  std::vector<char> fixed_samples(bool coarser) const {
    const int64_t w = data.rect.width(), h = data.rect.height();
    std::vector<char> fixed(data.v.size());
    for (int64_t y = 0; y < h; ++y)
      for (int64_t x = 0; x < w; ++x) {
        const size_t i = size_t(y * w + x);
        const auto known = [&](bool inside, size_t j) { return !inside || !is_void(j); };
        fixed[i] = !in_domain(i) ||
                   (!std::isnan(data.v[i]) &&
                    (!coarser || (known(x > 0, i - 1) && known(x + 1 < w, i + 1) &&
                                  known(y > 0, i - size_t(w)) && known(y + 1 < h, i + size_t(w)))));
      }
    return fixed;
  }
};

// The domain of a level's samples (Level::domain) over `rect`, its tile's first interior pixel
// at global pixel (ox, oy).
std::vector<char> footprint_domain(const Field& data, int levels_up, int64_t ox, int64_t oy,
                                   const FootprintTest& inside) {
  std::vector<char> domain(data.v.size());
  const Rect& r = data.rect;
  for (int64_t y = r.y0; y < r.y1; ++y)
    for (int64_t x = r.x0; x < r.x1; ++x) {
      const size_t i = data.index(x, y);
      domain[i] = !std::isnan(data.v[i]) || inside(levels_up, int(x - ox), int(y - oy));
    }
  return domain;
}

}  // namespace

PyramidTile pyramid_tile(CellId cell, int size, int levels_up) {
  if (levels_up <= cell.level()) return {cell.parent(cell.level() - levels_up), size};
  return {cell.parent(0), size >> (levels_up - cell.level())};
}

Tile<float> fill_through_pyramid(const Tile<float>& dem, CellId cell, const PyramidFetch& fetch,
                                 const FootprintTest& inside) {
  const int n = dem.size();
  const int pixel_level = cell.level() + log2_tile_size(n);
  const int top_level = std::max(0, pixel_level - kCoarsestPixelLevel);

  // Climb until a level holds no void where its fill must be exact, nor next to it on a coarser
  // level (its fill is then its data, which no sweep would change), or there is no coarser level.
  std::vector<Level> levels;
  Rect exact{int64_t(cell.col()) * n, int64_t(cell.row()) * n, int64_t(cell.col() + 1) * n,
             int64_t(cell.row() + 1) * n};
  for (int k = 0;; ++k) {
    const Rect window = exact.grown(kPyramidSweeps + 1);
    const PyramidTile t = pyramid_tile(cell, n, k);
    const int64_t ox = int64_t(t.cell.col()) * t.size, oy = int64_t(t.cell.row()) * t.size;
    levels.push_back(
        {exact, extract(k == 0 ? dem : fetch(k, kPyramidHalo), ox, oy, window), Field{Rect{}}, {}});
    Level& level = levels.back();
    if (inside) level.domain = footprint_domain(level.data, k, ox, oy, inside);
    if (!level.has_void(k == 0 ? exact : exact.grown(1)) || k == top_level) break;
    exact = window.coarse_cover();
  }

  // Down again: each level's voids start from the coarser fill and are smoothed.
  levels.back().fill = levels.back().data;
  for (size_t k = levels.size() - 1; k-- > 0;) {
    Level& level = levels[k];
    level.fill = level.data;
    const Rect& r = level.data.rect;
    for (int64_t y = r.y0; y < r.y1; ++y)
      for (int64_t x = r.x0; x < r.x1; ++x) {
        const size_t i = level.fill.index(x, y);
        if (level.is_void(i)) level.fill.v[i] = upsample(levels[k + 1].fill, x, y);
      }
    smooth(level.fill, level.fixed_samples(k > 0));
  }

  // Without a footprint, a void sample is filled where, at some coarser level, data lie within
  // kReach pixels of its own pixel there in each of the four axis directions.
  const auto data_towards = [&](const Field& data, int64_t cx, int64_t cy, int dx, int dy) {
    for (int d = 1; d <= kReach; ++d)
      if (!std::isnan(data.at(cx + d * dx, cy + d * dy))) return true;
    return false;
  };
  const auto enclosed = [&](int64_t x, int64_t y) {
    for (size_t k = 1; k < levels.size(); ++k) {
      const Field& data = levels[k].data;
      const int64_t cx = x >> k, cy = y >> k;
      if (data_towards(data, cx, cy, -1, 0) && data_towards(data, cx, cy, 1, 0) &&
          data_towards(data, cx, cy, 0, -1) && data_towards(data, cx, cy, 0, 1))
        return true;
    }
    return false;
  };
  Tile<float> out(n, 1);
  const Level& fine = levels.front();
  for (int row = 0; row < n; ++row)
    for (int col = 0; col < n; ++col) {
      const int64_t x = fine.exact.x0 + col, y = fine.exact.y0 + row;
      const float v = dem.at(col, row);
      const bool filled = inside ? fine.is_void(fine.data.index(x, y)) : enclosed(x, y);
      out.at(col, row) = std::isnan(v) && filled ? fine.fill.at(x, y) : v;
    }
  return out;
}

}  // namespace maquette::terrain
