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

// Samples around the band's box whose patches its resynthesis draws from.
constexpr int kBandContext = 48;

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

// The copy's map: a pixel's centre back to its point in the source, about the source's
// bounding-box centre moved by the offset.
class CopyMap {
 public:
  CopyMap(const std::vector<uint8_t>& source, int width, int height, const CloneParams& params)
      : source_(source), w_(width), h_(height), linear_(params.linear) {
    if (source.size() != size_t(w_) * h_) {
      throw Error("clone: the source mask has " + std::to_string(source.size()) +
                  " pixels, the image " + std::to_string(size_t(w_) * h_));
    }
    int x0 = w_, y0 = h_, x1 = -1, y1 = -1;
    for (int y = 0; y < h_; ++y) {
      for (int x = 0; x < w_; ++x) {
        if (source[size_t(y) * w_ + x] == 0) continue;
        x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
      }
    }
    if (x1 < 0) throw Error("clone: the source region is empty");
    const auto [a, b, c, d] = linear_;
    det_ = a * d - b * c;
    if (!(std::abs(det_) > 1e-9)) throw Error("clone: the map is singular");
    cx_ = (x0 + x1) / 2.0, cy_ = (y0 + y1) / 2.0;
    tx_ = cx_ + params.offset_x, ty_ = cy_ + params.offset_y;
    // The destination's box: the source's box (pixel edges) mapped, one pixel of margin.
    double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
    for (const double sx : {x0 - 0.5, x1 + 0.5}) {
      for (const double sy : {y0 - 0.5, y1 + 0.5}) {
        const double u = sx - cx_, v = sy - cy_;
        const double p[2] = {tx_ + a * u + b * v, ty_ + c * u + d * v};
        for (int k = 0; k < 2; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
      }
    }
    box_ = {int64_t(std::floor(lo[0])) - 1, int64_t(std::floor(lo[1])) - 1,
            int64_t(std::ceil(hi[0])) + 1, int64_t(std::ceil(hi[1])) + 1};
  }

  // Whether pixel (x, y) (anywhere, inside the image or not) takes a source value: its centre
  // maps back onto a source pixel, at (sx, sy).
  bool back(int64_t x, int64_t y, double& sx, double& sy) const {
    const auto [a, b, c, d] = linear_;
    const double u = double(x) - tx_, v = double(y) - ty_;
    sx = cx_ + (d * u - b * v) / det_, sy = cy_ + (-c * u + a * v) / det_;
    const long rx = std::lround(sx), ry = std::lround(sy);
    return rx >= 0 && ry >= 0 && rx < w_ && ry < h_ && source_[size_t(ry) * w_ + rx] != 0;
  }

  // The pixels that may take a source value: x0, y0, x1, y1 (inclusive).
  std::array<int64_t, 4> box() const { return box_; }

 private:
  const std::vector<uint8_t>& source_;
  int w_, h_;
  std::array<double, 4> linear_;
  double det_ = 1, cx_ = 0, cy_ = 0, tx_ = 0, ty_ = 0;
  std::array<int64_t, 4> box_{};
};

// `image` with inpaint() of `hole` run on the hole's box grown by kBandContext (clipped to the
// image): the band is resynthesized from the patches near it (the copy's inside, the
// surroundings), and the pyramid, distance transforms and searches cover that window, not the
// whole image.
PatchImage inpaint_around(PatchImage image, const std::vector<uint8_t>& hole,
                          const InpaintParams& params, const NearestFieldSearch& search) {
  const int w = image.width, h = image.height, c = image.channels;
  int x0 = w, y0 = h, x1 = -1, y1 = -1;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      if (hole[size_t(y) * w + x] == 0) continue;
      x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
    }
  }
  if (x1 < 0) return image;
  x0 = std::max(x0 - kBandContext, 0), y0 = std::max(y0 - kBandContext, 0);
  x1 = std::min(x1 + kBandContext, w - 1), y1 = std::min(y1 + kBandContext, h - 1);
  const int cw = x1 - x0 + 1, ch = y1 - y0 + 1;
  PatchImage window(cw, ch, c);
  std::vector<uint8_t> window_hole(size_t(cw) * ch);
  for (int y = 0; y < ch; ++y) {
    std::copy_n(image.pixel(x0, y0 + y), size_t(cw) * c, window.pixel(0, y));
    std::copy_n(hole.begin() + ptrdiff_t(size_t(y0 + y) * w + x0), cw,
                window_hole.begin() + ptrdiff_t(size_t(y) * cw));
  }
  const PatchImage filled = inpaint(window, window_hole, params, search);
  for (int y = 0; y < ch; ++y) {
    std::copy_n(filled.pixel(0, y), size_t(cw) * c, image.pixel(x0, y0 + y));
  }
  return image;
}

}  // namespace

CopyFootprint copy_footprint(const std::vector<uint8_t>& source, int width, int height,
                             const CloneParams& params) {
  const CopyMap map(source, width, height, params);
  CopyFootprint footprint{std::vector<uint8_t>(source.size(), 0), 0};
  const auto [x0, y0, x1, y1] = map.box();
  double sx = 0, sy = 0;
  for (int64_t y = y0; y <= y1; ++y) {
    for (int64_t x = x0; x <= x1; ++x) {
      if (!map.back(x, y, sx, sy)) continue;
      if (x < 0 || y < 0 || x >= width || y >= height) {
        ++footprint.beyond;
      } else {
        footprint.destination[size_t(y) * width + size_t(x)] = 1;
      }
    }
  }
  return footprint;
}

PatchImage clone(const PatchImage& image, const std::vector<uint8_t>& source,
                 const CloneParams& params, const NearestFieldSearch& search) {
  const int w = image.width, h = image.height;
  const CopyMap map(source, w, h, params);
  // Each pixel whose centre maps back into the source takes the source's value there.
  PatchImage copied = image;
  std::vector<uint8_t> destination(source.size(), 0);
  double sx = 0, sy = 0;
  const auto [x0, y0, x1, y1] = map.box();
  for (int y = int(std::max<int64_t>(y0, 0)); y <= std::min<int64_t>(y1, h - 1); ++y) {
    for (int x = int(std::max<int64_t>(x0, 0)); x <= std::min<int64_t>(x1, w - 1); ++x) {
      if (!map.back(x, y, sx, sy)) continue;
      destination[size_t(y) * w + x] = 1;
      if (params.fill.values == LayerValues::Classes) {  // classes copied whole, never mixed
        std::copy_n(image.pixel(int(std::lround(sx)), int(std::lround(sy))), image.channels,
                    copied.pixel(x, y));
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
  return inpaint_around(copied, band, fill, search);
}

}  // namespace maquette::synthesis
