#include "image/mosaic.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "core/error.h"
#include "core/halo.h"
#include "image/layer_cells.h"

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

// The tiles of one level, each with a one-pixel halo from its neighbours (across faces too), so
// that bilinear sampling never stops at a tile edge.
class HaloTiles {
 public:
  HaloTiles(const Store& store, const Grid& grid, const LayerInfo& info, int level)
      : store_(store), grid_(grid), info_(info), base_(level == info.level) {}

  struct Entry {
    std::optional<Tile<float>> tile;  // none when the cell has no tile
    PlaneSquare square;
  };

  const Entry& at(CellId cell) {
    auto [it, fresh] = halo_.try_emplace(cell);
    if (fresh) {
      it->second.square = grid_.plane_square(cell);
      if (raw(cell))
        it->second.tile =
            assemble_halo(grid_, cell, info_.tile_size, 1, [this](CellId c) { return raw(c); });
    }
    return it->second;
  }

 private:
  std::optional<Tile<float>> raw(CellId cell) {
    auto [it, fresh] = raw_.try_emplace(cell);
    if (fresh) {
      const auto bytes =
          base_ ? store_.get_tile(info_.name, cell) : store_.get_overview(info_.name, cell);
      if (bytes) it->second = to_tile<float>(*bytes, info_.nodata ? &*info_.nodata : nullptr);
    }
    return it->second;
  }

  const Store& store_;
  const Grid& grid_;
  const LayerInfo& info_;
  bool base_;
  std::map<CellId, std::optional<Tile<float>>> raw_;
  std::map<CellId, Entry> halo_;
};

// Samples channel k of a halo tile at (u, v), in pixels from the centre of pixel (0, 0).
float sample(const Tile<float>& t, double u, double v, int k, bool bilinear) {
  const int n = t.size();
  const int nc = std::clamp(int(std::lround(u)), 0, n - 1);
  const int nr = std::clamp(int(std::lround(v)), 0, n - 1);
  const float nearest = t.at(nc, nr, k);
  if (!bilinear || !std::isfinite(nearest)) return nearest;
  const int c0 = std::clamp(int(std::floor(u)), -1, n - 1);
  const int r0 = std::clamp(int(std::floor(v)), -1, n - 1);
  const double fx = std::clamp(u - c0, 0.0, 1.0), fy = std::clamp(v - r0, 0.0, 1.0);
  double sum = 0, weight = 0;
  for (const auto& [dc, dr, w] :
       {std::tuple{0, 0, (1 - fx) * (1 - fy)}, std::tuple{1, 0, fx * (1 - fy)},
        std::tuple{0, 1, (1 - fx) * fy}, std::tuple{1, 1, fx * fy}})
    if (const float s = t.at(c0 + dc, r0 + dr, k); std::isfinite(s)) sum += w * s, weight += w;
  return float(sum / weight);  // the nearest sample is finite, so some weight is not 0
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
  const int n = info.tile_size;
  HaloTiles tiles(store, grid, info, level);
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
      const auto& entry = tiles.at(ids[c]);
      if (!entry.tile) continue;
      const PlanePoint p = grid.forward(points[c]);
      const PlaneSquare& sq = entry.square;
      const double u = (p.x - sq.x_min) / sq.side * n - 0.5,
                   v = (sq.y_max - p.y) / sq.side * n - 0.5;
      float* out = r.values.data() + (size_t(row) * size_t(r.width) + c) * size_t(r.channels);
      for (int k = 0; k < r.channels; ++k) out[k] = sample(*entry.tile, u, v, k, spec.bilinear);
    }
  }
  if (!spec.bbox) crop_to_data(r);
  return r;
}

}  // namespace maquette
