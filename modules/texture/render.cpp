#include "render.h"

#include <algorithm>

#include "categorical_values.h"
#include "core/error.h"
#include "field.h"
#include "lattice_noise.h"
#include "surface.h"

namespace maquette::texture {

void render_tile(const Model& given, const Grid& grid, CellId cell, int size, int refine,
                 const Tile<float>& dem, const std::map<std::string, const Tile<float>*>& rasters,
                 const std::string& context, const RenderTargets& out) {
  const int m = size << refine;
  const double pixel_m = grid.level_info(cell.level(), m).pixel_m;
  // The planes, a few MB each, are the thread's from tile to tile: every value is overwritten,
  // so they are neither zero-filled nor page-faulted afresh.
  struct Buffers {
    Plane wide, height, slope, displaced;
    std::vector<Plane> quantities;
  };
  thread_local Buffers b;
  const CategoricalSplit split = split_categorical(given);
  const Model& model = split.model;
  upsample(dem, refine, 2, b.wide);
  SurfaceInputs in;
  in.slope = std::move(b.slope);  // lent to `in`, given back below
  in.height = std::move(b.height);
  slope_degrees(b.wide, pixel_m, in.slope);
  in.height.reshape(m, 1);
  for (int r = -1; r <= m; ++r) std::copy_n(&b.wide.at(-1, r), m + 2, &in.height.at(-1, r));
  std::vector<Plane>& planes = b.quantities;
  planes.resize(model.quantities.size());
  in.quantities.assign(model.quantities.size(), nullptr);
  const size_t first_split = model.quantities.size() - split.tables.size();
  for (size_t q = 0; q < model.quantities.size(); ++q) {
    const std::string& name =
        q < first_split ? model.quantities[q].name : split.source[q - first_split];
    if (name == "height" || name == "slope") continue;
    const auto it = rasters.find(name);
    if (it == rasters.end() || !it->second)
      throw Error(context + ": model quantity '" + name + "' has no input raster (map inputs." +
                  name + ")");
    if (q >= first_split)
      upsample(categorical_values(*it->second, split.tables[q - first_split]), refine, 1,
               planes[q]);
    else
      upsample(*it->second, refine, 1, planes[q]);
    in.quantities[q] = &planes[q];
  }
  const PixelPositions position(grid, cell, size, refine, in.height.ring + kNoiseLatticeReach);
  in.position = &position;
  in.col0 = global_col(cell, m, 0);
  in.row0 = global_row(cell, m, 0);
  in.pixel_m = pixel_m;
  // The displaced height with a ring for the normals; colour and classes straight to `out`.
  Plane& height = b.displaced;
  height.reshape(m, 1);
  evaluate(model, in, {0, out.rgb, out.classes, height.v.data()});
  if (out.normal) normals(height, pixel_m, out.normal);
  if (out.height)
    for (int r = 0; r < m; ++r)
      std::copy_n(&height.at(0, r), m, out.height + size_t(r) * size_t(m));
  b.slope = std::move(in.slope);
  b.height = std::move(in.height);
}

Rendered render_tile(const Model& model, const Grid& grid, CellId cell, int size, int refine,
                     const Tile<float>& dem,
                     const std::map<std::string, const Tile<float>*>& rasters,
                     const std::string& context) {
  const int m = size << refine;
  const size_t n = size_t(m) * size_t(m);
  Rendered r{m, std::vector<float>(3 * n), std::vector<float>(n), std::vector<float>(3 * n),
             std::vector<float>(n)};
  render_tile(model, grid, cell, size, refine, dem, rasters, context,
              {r.rgb.data(), r.height.data(), r.normal.data(), r.classes.data()});
  return r;
}

}  // namespace maquette::texture
