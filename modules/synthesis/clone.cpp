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

namespace {

// Moves the copied heights by the mean difference, over the destination's samples within `band`
// of its edge, between the heights there before and the copy's (NaNs skipped): the copy meets its
// surroundings on average and keeps its own relief (a Poisson blend would bend it to match every
// edge sample; the band's resynthesis smooths what difference is left across the edge).
void meet_surrounding_heights(const PatchImage& before, const std::vector<uint8_t>& destination,
                              const std::vector<int32_t>& to_outside, int band,
                              PatchImage& copied) {
  double sum = 0;
  size_t count = 0;
  for (size_t i = 0; i < destination.size(); ++i) {
    if (destination[i] == 0 || to_outside[i] > std::max(band, 1)) continue;
    const double difference = double(before.values[i]) - copied.values[i];
    if (std::isnan(difference)) continue;
    sum += difference;
    ++count;
  }
  if (count == 0) return;
  const auto offset = float(sum / double(count));
  for (size_t i = 0; i < destination.size(); ++i) {
    if (destination[i] != 0) copied.values[i] += offset;
  }
}

}  // namespace

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
      if (params.fill.values == LayerValues::Classes) {  // classes copied whole, never mixed
        std::copy_n(image.pixel(int(rx), int(ry)), image.channels, copied.pixel(x, y));
      } else {
        sample_bilinear(image, sx, sy, copied.pixel(x, y));
      }
    }
  }
  // The band across the destination's edge: within fill.band of it, on either side.
  std::vector<uint8_t> outside(destination.size());
  for (size_t i = 0; i < outside.size(); ++i) outside[i] = destination[i] == 0;
  const auto to_destination = chessboard_distance(destination, w, h);
  const auto to_outside = chessboard_distance(outside, w, h);
  if (params.fill.values == LayerValues::Heights) {
    meet_surrounding_heights(image, destination, to_outside, params.fill.band, copied);
  }
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
