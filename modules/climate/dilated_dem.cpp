#include "dilated_dem.h"

#include <algorithm>

namespace maquette::climate {
namespace {

enum class Axis { Col, Row };

// The larger of two samples, leaving out one without data.
float max_of_data(float a, float b) { return b > a || a != a ? b : a; }

// Maximum of `in` at (col ± shift, row) or (col, row ± shift) (those inside the tile and its
// halo): runs of half-width r in `in` along the axis become runs of half-width r + shift (no
// pixel is skipped while shift <= 2 r + 1).
Tile<float> shifted_maximum(const Tile<float>& in, Axis axis, int shift) {
  const int h = in.halo(), n = in.size();
  const int dc = axis == Axis::Col ? shift : 0, dr = axis == Axis::Row ? shift : 0;
  Tile<float> out = Tile<float>::uninitialized(n, 1, h);
  for (int r = -h; r < n + h; ++r)
    for (int c = -h; c < n + h; ++c) {
      float m = in.at(c, r);
      if (c - dc >= -h && r - dr >= -h) m = max_of_data(m, in.at(c - dc, r - dr));
      if (c + dc < n + h && r + dr < n + h) m = max_of_data(m, in.at(c + dc, r + dr));
      out.at(c, r) = m;
    }
  return out;
}

// The maxima over squares of half-width r + shift from those of half-width r: rows, then columns.
Tile<float> shifted_square_maximum(const Tile<float>& in, int shift) {
  return shifted_maximum(shifted_maximum(in, Axis::Col, shift), Axis::Row, shift);
}

}  // namespace

DilatedDem::DilatedDem(const Tile<float>& dem, int levels) : dem_(dem) {
  // Half-widths 1, 2, 4, ...: each level shifts the previous one by its half-width.
  for (int l = 1; l <= levels; ++l)
    maxima_.push_back(shifted_square_maximum(level(l - 1), l == 1 ? 1 : 1 << (l - 2)));
}

}  // namespace maquette::climate
