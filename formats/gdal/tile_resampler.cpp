#include "gdal/tile_resampler.h"

#include <immintrin.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace maquette {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The source window's bounds: the smallest and largest x - rx, x + rx, y - ry, y + ry of the
// samples to fill.
struct Bounds {
  double x0 = kInf, y0 = kInf, x1 = -kInf, y1 = -kInf;
};

// The window pass of TileResampler::sample over samples [0, n) (n a multiple of 4) of a tile
// that no source has filled yet, four at a time: unusable samples get x = NaN, the others
// extend `b` by their radius (hx + 1, hy + 1 with footprints, else 2). Minima and maxima are
// exact, so the bounds are those of the one-by-one loop.
__attribute__((target("avx2"))) void window_bounds4(double* x, const double* y, const double* hx,
                                                    const double* hy, size_t n, double W, double H,
                                                    bool wraps, Bounds& b) {
  const __m256d zero = _mm256_setzero_pd(), w = _mm256_set1_pd(W), h = _mm256_set1_pd(H),
                inf = _mm256_set1_pd(kInf), ninf = _mm256_set1_pd(-kInf), two = _mm256_set1_pd(2),
                one = _mm256_set1_pd(1),
                nan = _mm256_set1_pd(std::numeric_limits<double>::quiet_NaN());
  __m256d x0 = inf, y0 = inf, x1 = ninf, y1 = ninf;
  for (size_t i = 0; i < n; i += 4) {
    const __m256d xi = _mm256_loadu_pd(x + i), yi = _mm256_loadu_pd(y + i);
    const __m256d in_y =
        _mm256_and_pd(_mm256_cmp_pd(yi, zero, _CMP_GE_OQ), _mm256_cmp_pd(yi, h, _CMP_LE_OQ));
    const __m256d in_x = wraps ? _mm256_cmp_pd(xi, xi, _CMP_ORD_Q)
                               : _mm256_and_pd(_mm256_cmp_pd(xi, zero, _CMP_GE_OQ),
                                               _mm256_cmp_pd(xi, w, _CMP_LE_OQ));
    const __m256d ok = _mm256_and_pd(in_x, in_y);
    if (_mm256_movemask_pd(ok) != 0xF) _mm256_storeu_pd(x + i, _mm256_blendv_pd(nan, xi, ok));
    const __m256d rx = hx ? _mm256_add_pd(_mm256_loadu_pd(hx + i), one) : two;
    const __m256d ry = hy ? _mm256_add_pd(_mm256_loadu_pd(hy + i), one) : two;
    x0 = _mm256_min_pd(x0, _mm256_blendv_pd(inf, _mm256_sub_pd(xi, rx), ok));
    x1 = _mm256_max_pd(x1, _mm256_blendv_pd(ninf, _mm256_add_pd(xi, rx), ok));
    y0 = _mm256_min_pd(y0, _mm256_blendv_pd(inf, _mm256_sub_pd(yi, ry), ok));
    y1 = _mm256_max_pd(y1, _mm256_blendv_pd(ninf, _mm256_add_pd(yi, ry), ok));
  }
  alignas(32) double v[4][4];
  _mm256_store_pd(v[0], x0);
  _mm256_store_pd(v[1], y0);
  _mm256_store_pd(v[2], x1);
  _mm256_store_pd(v[3], y1);
  for (int l = 0; l < 4; ++l) {
    b.x0 = std::min(b.x0, v[0][l]);
    b.y0 = std::min(b.y0, v[1][l]);
    b.x1 = std::max(b.x1, v[2][l]);
    b.y1 = std::max(b.y1, v[3][l]);
  }
}

}  // namespace

struct TileResampler::Source {
  const RasterSource& info;
  SourceReader reader;
  PixelMapper mapper;
  Source(const Grid& grid, const RasterSource& s) : info(s), reader(s), mapper(grid, s) {}
};

TileResampler::TileResampler(const Grid& grid, const std::vector<RasterSource>& sources,
                             Resampling resampling, bool categorical)
    : resampling_(resampling), categorical_(categorical) {
  for (const RasterSource& s : sources) sources_.push_back(std::make_unique<Source>(grid, s));
}

TileResampler::~TileResampler() = default;

bool TileResampler::make(CellId cell, int size, Tile<float>& tile) {
  const int channels = int(sources_.front()->info.bands.size());
  if (tile.size() == size && tile.channels() == channels && tile.halo() == 0)
    std::ranges::fill(tile.data(), std::numeric_limits<float>::quiet_NaN());
  else
    tile = Tile<float>(size, channels, 0, std::numeric_limits<float>::quiet_NaN());
  for (size_t k = 0; k < sources_.size(); ++k) sample(*sources_[k], cell, tile, k == 0);
  for (float v : tile.data())
    if (!std::isnan(v)) return true;
  return false;
}

void TileResampler::sample(Source& s, CellId cell, Tile<float>& tile, bool fresh) {
  s.mapper.map(cell, tile.size(), map_);
  const int n = tile.size(), channels = tile.channels();
  const double W = s.info.width, H = s.info.height;
  auto& x = map_.x;
  auto& y = map_.y;
  // A tile across the seam of a wrapping raster: take its columns into one continuous range.
  if (s.info.wraps) {
    double lo = W, hi = 0;
    for (double v : x)
      if (!std::isnan(v)) lo = std::min(lo, v), hi = std::max(hi, v);
    if (hi - lo > W / 2)
      for (double& v : x)
        if (v < W / 2) v += W;
  }
  const bool area = resampling_ == Resampling::Average || resampling_ == Resampling::Mode;
  const std::span<const float> values = tile.data();
  const auto missing = [&](size_t i) {
    for (int k = 0; k < channels; ++k)
      if (std::isnan(values[i * size_t(channels) + size_t(k)])) return true;
    return false;
  };
  // In the raster (NaN fails every comparison), as locals: the loop below writes x.
  const bool wraps = s.info.wraps;
  const auto usable = [W, H, wraps](double xi, double yi) {
    return yi >= 0 && yi <= H && (wraps ? !std::isnan(xi) : xi >= 0 && xi <= W);
  };
  // Half-sizes of each sample's footprint in source pixels (area kernels only).
  std::vector<double> hx, hy;  // float precision (as the kernels have always seen them)
  if (area) {
    hx.assign(x.size(), 0.5);
    hy.assign(x.size(), 0.5);
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < n; ++c) {
        const size_t i = size_t(r) * n + c;
        const size_t cl = size_t(r) * n + std::max(c - 1, 0),
                     cr = size_t(r) * n + std::min(c + 1, n - 1);
        const size_t ru = size_t(std::max(r - 1, 0)) * n + c,
                     rd = size_t(std::min(r + 1, n - 1)) * n + c;
        const double dc = std::max(1, std::min(c + 1, n - 1) - std::max(c - 1, 0));
        const double dr = std::max(1, std::min(r + 1, n - 1) - std::max(r - 1, 0));
        const double xc = (x[cr] - x[cl]) / dc, yc = (y[cr] - y[cl]) / dc;
        const double xr = (x[rd] - x[ru]) / dr, yr = (y[rd] - y[ru]) / dr;
        const double ax = 0.5 * (std::abs(xc) + std::abs(xr)),
                     ay = 0.5 * (std::abs(yc) + std::abs(yr));
        // Beyond a seam the differences are meaningless: keep one pixel there.
        if (std::isfinite(ax) && std::isfinite(ay) && ax < W / 4 && ay < H / 4) {
          hx[i] = double(float(ax));
          hy[i] = double(float(ay));
        }
      }
  }
  // The source window the samples to fill need (usable, some channel still missing); unusable
  // samples get x = NaN, which the kernels skip.
  Bounds b;
  double* const xs = x.data();
  const double* const ys = y.data();
  size_t i = 0;
  if (fresh && __builtin_cpu_supports("avx2"))
    window_bounds4(xs, ys, area ? hx.data() : nullptr, area ? hy.data() : nullptr,
                   i = x.size() / 4 * 4, W, H, wraps, b);
  for (; i < x.size(); ++i) {
    const double xi = xs[i], yi = ys[i];
    if (!usable(xi, yi)) {
      xs[i] = std::numeric_limits<double>::quiet_NaN();
      continue;
    }
    if (!fresh && !missing(i)) continue;
    const double rx = area ? hx[i] + 1 : 2, ry = area ? hy[i] + 1 : 2;
    b.x0 = std::min(b.x0, xi - rx);
    b.x1 = std::max(b.x1, xi + rx);
    b.y0 = std::min(b.y0, yi - ry);
    b.y1 = std::max(b.y1, yi + ry);
  }
  auto [x0, y0, x1, y1] = b;
  if (!(x0 < x1)) return;
  if (!s.info.wraps) x0 = std::max(x0, 0.0), x1 = std::min(x1, W);
  y0 = std::max(y0, 0.0);
  y1 = std::min(y1, H);
  const int64_t ix0 = int64_t(std::floor(x0)), iy0 = int64_t(std::floor(y0));
  const int64_t span =
      std::max<int64_t>(int64_t(std::ceil(x1)) - ix0, int64_t(std::ceil(y1)) - iy0);
  const int step = int(std::max<int64_t>(1, (span + kMaxWindow - 1) / kMaxWindow));
  const int ww = int((int64_t(std::ceil(x1)) - ix0 + step - 1) / step);
  const int wh = int((int64_t(std::ceil(y1)) - iy0 + step - 1) / step);
  if (ww <= 0 || wh <= 0) return;
  s.reader.read(ix0, iy0, ww, wh, step, categorical_, window_);
  resample(window_, resampling_, {x, y, hx, hy}, tile.data());
}

}  // namespace maquette
