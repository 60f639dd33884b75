#include "feature_mask.h"

#include <map>
#include <optional>
#include <set>

#include "core/error.h"
#include "core/halo.h"
#include "core/polygon_set.h"
#include "core/wkb_polygons.h"

namespace maquette::texture {

std::vector<uint8_t> features_mask(const Store& store, const std::string& layer,
                                   const std::string& where, const Grid& grid, CellId cell,
                                   int size, int ring) {
  LayerInfo info;
  int64_t count = 0;
  try {
    info = store.require_layer(layer);
    count = store.feature_count(layer);  // throws for another kind of layer
  } catch (const Error& e) {
    throw Error(where + ": " + e.what());
  }
  if (count == 0)
    throw Error(where + ": layer '" + layer + "' in " + store.path() + " has no features");

  // Where each pixel really lies (halo pixels may come from another face), and the cells of the
  // layer's index holding those places: the layer's cells are finer (a range of ids under the
  // tile's cells) or coarser (an ancestor) than the tile's.
  const int side = size + 2 * ring, log2_size = log2_tile_size(size);
  std::vector<std::optional<FaceCoord>> sources;
  std::set<CellId> index_cells;
  for (int r = -ring; r < size + ring; ++r)
    for (int c = -ring; c < size + ring; ++c) {
      const auto& src = sources.emplace_back(pixel_source(grid, cell, size, c, r));
      if (!src) continue;
      const CellId in =
          CellId::FromFaceColRow(src->face, cell.level(), uint32_t(src->col >> log2_size),
                                 uint32_t(src->row >> log2_size));
      index_cells.insert(info.level < cell.level() ? in.parent(info.level) : in);
    }
  std::map<int64_t, std::vector<std::byte>> wkb_by_fid;  // each feature once, by fid
  for (const CellId c : index_cells)
    for (Feature& f : store.features_in(layer, c.range_min(), c.range_max()))
      wkb_by_fid.emplace(f.fid, std::move(f.wkb));
  std::vector<PolygonRings> polygons;
  for (const auto& [fid, wkb] : wkb_by_fid)
    for (PolygonRings& p :
         wkb_polygons(wkb, where + ": feature " + std::to_string(fid) + " of '" + layer + "'"))
      polygons.push_back(std::move(p));

  std::vector<uint8_t> mask(size_t(side) * size_t(side), 0);
  const PolygonSet set(polygons);
  if (set.empty()) return mask;
  const int pixel_level = cell.level() + log2_size;
  for (size_t i = 0; i < mask.size(); ++i)
    if (sources[i]) mask[i] = set.contains(pixel_centre(grid, *sources[i], pixel_level));
  return mask;
}

}  // namespace maquette::texture
