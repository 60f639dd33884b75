#include "image/mosaic.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"
#include "image/layer_cells.h"
#include "image/layer_sampler.h"

namespace maquette {
namespace {

constexpr float kNan = std::numeric_limits<float>::quiet_NaN();

// Crops the raster to the rows and columns holding data: cells are often much larger than the
// data in them.
void crop_to_data(PictureRaster& r) {
  int c0 = r.width, c1 = -1, r0 = r.height, r1 = -1;
  for (int row = 0; row < r.height; ++row)
    for (int col = 0; col < r.width; ++col)
      if (std::isfinite(r.at(col, row))) {
        c0 = std::min(c0, col), c1 = std::max(c1, col);
        r0 = std::min(r0, row), r1 = std::max(r1, row);
      }
  if (c1 < 0) return;  // no data at all: keep the frame
  std::vector<float> values;
  values.reserve(size_t(c1 - c0 + 1) * size_t(r1 - r0 + 1) * size_t(r.channels));
  for (int row = r0; row <= r1; ++row)
    for (int col = c0; col <= c1; ++col)
      for (int k = 0; k < r.channels; ++k) values.push_back(r.at(col, row, k));
  PictureFrame& f = *r.frame;
  f.left += c0 * f.x_step;
  f.top -= r0 * f.y_step;
  r.width = f.width = c1 - c0 + 1;
  r.height = f.height = r1 - r0 + 1;
  r.values = std::move(values);
}

}  // namespace

PictureRaster mosaic_layer(const Store& store, const Grid& grid, const std::string& layer,
                           std::vector<CellId> cells, const MosaicSpec& spec) {
  const LayerInfo info = store.require_layer(layer);
  std::sort(cells.begin(), cells.end());
  if (cells.empty()) throw Error("layer '" + layer + "' in " + store.path() + " has no tiles");

  int doublings = 0;
  const PictureFrame frame =
      frame_for(grid, {spec.bbox, cells}, spec.projection,
                grid.level_info(info.level, info.tile_size).pixel_m, spec.max_side, doublings);
  const int level = std::max(0, info.level - doublings);
  const std::vector<CellId> region = cells_at_level(cells, level);

  PictureRaster r;
  r.width = frame.width, r.height = frame.height, r.channels = info.channels, r.frame = frame;
  r.values.assign(size_t(r.width) * size_t(r.height) * size_t(r.channels), kNan);
  LayerSampler sampler(
      store, grid, info, level,
      spec.bilinear ? LayerSampler::Read::kBilinear : LayerSampler::Read::kNearest);
  const FramePixels pixels(frame);
  std::vector<LonLat> points;
  std::vector<char> inside;
  std::vector<CellId> ids;
  for (int row = 0; row < r.height; ++row) {
    pixels.row(row, points);
    inside.assign(points.size(), 0);
    for (size_t c = 0; c < points.size(); ++c) {
      inside[c] = std::isfinite(points[c].lat) && (!spec.bbox || in_bbox(*spec.bbox, points[c]));
      if (!inside[c]) points[c] = {0, 0};  // any valid point; not drawn
    }
    ids.resize(points.size());
    grid.cells_from_points(points, level, ids);
    for (size_t c = 0; c < points.size(); ++c) {
      if (!inside[c] || !std::binary_search(region.begin(), region.end(), ids[c])) continue;
      sampler.sample(points[c], ids[c],
                     r.values.data() + (size_t(row) * size_t(r.width) + c) * size_t(r.channels));
    }
  }
  if (!spec.bbox) crop_to_data(r);
  return r;
}

}  // namespace maquette
