#include "gdal/pixel_map.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace maquette {
namespace {

// How far the lattice bends at each node along its rows (`along_rows`) or its columns: twice the
// distance, in source pixels, of the node from the chord of its two neighbours (the second
// difference for equal intervals); NaN at the lattice's edges and next to a failed transform.
// Along a lattice interval whose map is linear on each side of a kink, bilinear interpolation
// is off by at most the second difference at either end (the kink's jump in slope times its
// distance from the other end, times less than one), whatever the kink's place.
std::vector<double> bends(const std::vector<int>& ticks, const std::vector<double>& lx,
                          const std::vector<double>& ly, bool along_rows) {
  const size_t m = ticks.size();
  std::vector<double> out(m * m, std::numeric_limits<double>::quiet_NaN());
  for (size_t j = 0; j < m; ++j)
    for (size_t i = 1; i + 1 < m; ++i) {
      const size_t k = along_rows ? j * m + i : i * m + j, step = along_rows ? 1 : m;
      const double h0 = ticks[i] - ticks[i - 1], h1 = ticks[i + 1] - ticks[i];
      const auto off = [&](const std::vector<double>& v) {
        return v[k] - (h1 * v[k - step] + h0 * v[k + step]) / (h0 + h1);
      };
      out[k] = 2 * std::hypot(off(lx), off(ly));
    }
  return out;
}

// The bound above for the lattice interval between nodes a and b: the smaller of their bends
// (NaN ones unknown), 0 when neither is known.
double interval_bound(const std::vector<double>& bend, size_t a, size_t b) {
  const double u = bend[a], v = bend[b];
  if (std::isnan(u)) return std::isnan(v) ? 0 : v;
  return std::isnan(v) ? u : std::min(u, v);
}

}  // namespace

void PixelMapper::exact(CellId cell, int size, std::vector<double>& x, std::vector<double>& y) {
  // In: tile sample coordinates (col, row); out: source pixel coordinates.
  const PlaneSquare sq = grid_.plane_square(cell);
  const double d = sq.side / size;
  for (size_t i = 0; i < x.size(); ++i) {
    const LonLat p = grid_.inverse({sq.x_min + (x[i] + 0.5) * d, sq.y_max - (y[i] + 0.5) * d});
    x[i] = p.lon;
    y[i] = p.lat;
  }
  transform_.to_pixel(x, y);
}

void PixelMapper::map(CellId cell, int size, PixelMap& out) {
  out.size = size;
  const size_t n = size_t(size) * size_t(size);
  out.x.resize(n);  // every sample is written below
  out.y.resize(n);
  // Lattice columns/rows: 0, kStep, 2 kStep, ..., and the last sample.
  std::vector<int> ticks;
  for (int t = 0; t < size - 1; t += kStep) ticks.push_back(t);
  ticks.push_back(size - 1);
  const size_t m = ticks.size();
  std::vector<double> lx(m * m), ly(m * m);
  for (size_t j = 0; j < m; ++j)
    for (size_t i = 0; i < m; ++i) {
      lx[j * m + i] = ticks[i];
      ly[j * m + i] = ticks[j];
    }
  exact(cell, size, lx, ly);
  const std::vector<double> row_bend = bends(ticks, lx, ly, true),
                            column_bend = bends(ticks, lx, ly, false);

  // The blocks, and the exact transform of the centre of each one that interpolation may fill
  // (corners valid, wider than one sample), all in one call: PROJ's set-up per call costs more
  // than a point.
  struct Block {
    int c0, c1, r0, r1;
    size_t k00, k01, k10, k11;
    bool smooth;  // its edges' interpolation is within kMaxError (see bends)
    bool check;   // its centre is checked against the exact transform
  };
  std::vector<Block> blocks;
  std::vector<double> cx, cy;
  for (size_t j = 0; j + 1 < std::max<size_t>(m, 2); ++j)
    for (size_t i = 0; i + 1 < std::max<size_t>(m, 2); ++i) {
      const int c0 = ticks[std::min(i, m - 1)], c1 = ticks[std::min(i + 1, m - 1)];
      const int r0 = ticks[std::min(j, m - 1)], r1 = ticks[std::min(j + 1, m - 1)];
      const size_t k00 = std::min(j, m - 1) * m + std::min(i, m - 1);
      const size_t k01 = k00 + (c1 > c0), k10 = k00 + (r1 > r0) * m, k11 = k10 + (c1 > c0);
      // A block whose edges may be off by more than kMaxError (a polar face's diagonal crosses
      // it: rows of samples turn there by ~50 degrees on the ground) is transformed exactly.
      const bool smooth =
          std::max({interval_bound(row_bend, k00, k01), interval_bound(row_bend, k10, k11),
                    interval_bound(column_bend, k00, k10),
                    interval_bound(column_bend, k01, k11)}) <= kMaxError;
      const bool check =
          smooth && !std::isnan(lx[k00] + lx[k01] + lx[k10] + lx[k11]) && c1 - c0 > 1;
      if (check) {
        cx.push_back(0.5 * (c0 + c1));
        cy.push_back(0.5 * (r0 + r1));
      }
      blocks.push_back({c0, c1, r0, r1, k00, k01, k10, k11, smooth, check});
    }
  if (!cx.empty()) exact(cell, size, cx, cy);
  std::vector<double> bx, by;
  size_t centre = 0;
  for (const Block& b : blocks) {
    const auto [c0, c1, r0, r1, k00, k01, k10, k11, smooth, check] = b;
    // (k00 = k00, ...: clang 14, the fuzz build's compiler, cannot capture a structured binding)
    const auto interp = [k00 = k00, k01 = k01, k10 = k10, k11 = k11](const std::vector<double>& v,
                                                                     double fc, double fr) {
      return (1 - fr) * ((1 - fc) * v[k00] + fc * v[k01]) + fr * ((1 - fc) * v[k10] + fc * v[k11]);
    };
    // Interpolation fills the block when it is within kMaxError of the exact centre.
    bool linear = smooth && !std::isnan(lx[k00] + lx[k01] + lx[k10] + lx[k11]);
    if (check) {
      linear = std::abs(cx[centre] - interp(lx, 0.5, 0.5)) <= kMaxError &&
               std::abs(cy[centre] - interp(ly, 0.5, 0.5)) <= kMaxError;
      ++centre;
    }
    // The block's samples: [c0, c1] x [r0, r1], the last column/row only at the tile's edge.
    const int ce = c1 == size - 1 ? c1 + 1 : c1, re = r1 == size - 1 ? r1 + 1 : r1;
    if (linear) {
      // Bilinear interpolation, stepped along each row from its two ends: the ends and steps of
      // all rows first (their divisions pipeline, one row's do not wait for the previous
      // row's), then the rows.
      const double wc = std::max(1, c1 - c0), wr = std::max(1, r1 - r0);
      const double x00 = lx[k00], x01 = lx[k01], x10 = lx[k10], x11 = lx[k11];
      const double y00 = ly[k00], y01 = ly[k01], y10 = ly[k10], y11 = ly[k11];
      const int rows = re - r0;
      double xl[kStep + 1], yl[kStep + 1], dx[kStep + 1], dy[kStep + 1];
      for (int k = 0; k < rows; ++k) {
        const double fr = k / wr;
        xl[k] = (1 - fr) * x00 + fr * x10;
        yl[k] = (1 - fr) * y00 + fr * y10;
        dx[k] = ((1 - fr) * x01 + fr * x11 - xl[k]) / wc;
        dy[k] = ((1 - fr) * y01 + fr * y11 - yl[k]) / wc;
      }
      for (int k = 0; k < rows; ++k) {
        double* ox = out.x.data() + size_t(r0 + k) * size_t(size);
        double* oy = out.y.data() + size_t(r0 + k) * size_t(size);
        for (int c = c0; c < ce; ++c) {
          ox[c] = xl[k] + (c - c0) * dx[k];
          oy[c] = yl[k] + (c - c0) * dy[k];
        }
      }
      continue;
    }
    bx.clear();
    by.clear();
    for (int r = r0; r < re; ++r)
      for (int c = c0; c < ce; ++c) {
        bx.push_back(c);
        by.push_back(r);
      }
    exact(cell, size, bx, by);
    size_t q = 0;
    for (int r = r0; r < re; ++r)
      for (int c = c0; c < ce; ++c, ++q) {
        const size_t k = size_t(r) * size_t(size) + size_t(c);
        out.x[k] = bx[q];
        out.y[k] = by[q];
      }
  }
}

}  // namespace maquette
