#include "clone.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "core/error.h"
#include "masked_pyramid.h"

namespace maquette::synthesis {
std::array<double, 4> foreshortening(double from_deg, double to_deg, double aspect_deg) {
  const double k =
      std::cos(to_deg * std::numbers::pi / 180) / std::cos(from_deg * std::numbers::pi / 180);
  const double ux = std::cos(aspect_deg * std::numbers::pi / 180);
  const double uy = std::sin(aspect_deg * std::numbers::pi / 180);
  // I + (k - 1) u u^T: k along u, 1 across it.
  return {1 + (k - 1) * ux * ux, (k - 1) * ux * uy, (k - 1) * ux * uy, 1 + (k - 1) * uy * uy};
}

PatchImage clone(const PatchImage& image, const std::vector<uint8_t>& source,
                 const CloneParams& params, const NearestFieldSearch& search) {
  const int w = image.width, h = image.height;
  if (source.size() != size_t(w) * h) {
    throw Error("clone: the source mask has " + std::to_string(source.size()) +
                " pixels, the image " + std::to_string(size_t(w) * h));
  }
  int x0 = w, y0 = h, x1 = -1, y1 = -1;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      if (source[size_t(y) * w + x] == 0) continue;
      x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
    }
  }
  if (x1 < 0) throw Error("clone: the source region is empty");
  const auto [a, b, c, d] = params.linear;
  const double det = a * d - b * c;
  if (!(std::abs(det) > 1e-9)) throw Error("clone: the map is singular");
  const double cx = (x0 + x1) / 2.0, cy = (y0 + y1) / 2.0;
  const double tx = cx + params.offset_x, ty = cy + params.offset_y;
  // Each pixel whose centre maps back into the source takes the source's value there.
  PatchImage copied = image;
  std::vector<uint8_t> destination(source.size(), 0);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const double u = x - tx, v = y - ty;
      const double sx = cx + (d * u - b * v) / det, sy = cy + (-c * u + a * v) / det;
      const long rx = std::lround(sx), ry = std::lround(sy);
      if (rx < 0 || ry < 0 || rx >= w || ry >= h || source[size_t(ry) * w + rx] == 0) continue;
      destination[size_t(y) * w + x] = 1;
      sample_bilinear(image, sx, sy, copied.pixel(x, y));
    }
  }
  // The band across the destination's edge: within fill.band of it, on either side.
  std::vector<uint8_t> outside(destination.size());
  for (size_t i = 0; i < outside.size(); ++i) outside[i] = destination[i] == 0;
  const auto to_destination = chessboard_distance(destination, w, h);
  const auto to_outside = chessboard_distance(outside, w, h);
  std::vector<uint8_t> band(destination.size(), 0);
  for (size_t i = 0; i < band.size(); ++i) {
    band[i] = destination[i] != 0 ? to_outside[i] <= params.fill.band
                                  : to_destination[i] <= params.fill.band;
  }
  InpaintParams fill = params.fill;
  fill.band = 0;  // the band is the hole here
  return inpaint(copied, band, fill, search);
}

}  // namespace maquette::synthesis
