#include "render.h"

#include "core/error.h"
#include "field.h"
#include "lattice_noise.h"
#include "surface.h"

namespace maquette::texture {

Rendered render_tile(const Model& model, const Grid& grid, CellId cell, int size, int refine,
                     const Tile<float>& dem,
                     const std::map<std::string, const Tile<float>*>& rasters,
                     const std::string& context) {
  const int m = size << refine;
  const double pixel_m = grid.level_info(cell.level(), m).pixel_m;
  const Plane wide = upsample(dem, refine, 2);
  SurfaceInputs in;
  in.slope = slope_degrees(wide, pixel_m);
  in.height = Plane(m, 1);
  for (int r = -1; r <= m; ++r)
    for (int c = -1; c <= m; ++c) in.height.at(c, r) = wide.at(c, r);
  std::vector<Plane> planes(model.quantities.size());
  in.quantities.assign(model.quantities.size(), nullptr);
  for (size_t q = 0; q < model.quantities.size(); ++q) {
    const std::string& name = model.quantities[q].name;
    if (name == "height" || name == "slope") continue;
    const auto it = rasters.find(name);
    if (it == rasters.end() || !it->second)
      throw Error(context + ": model quantity '" + name + "' has no input raster (map inputs." +
                  name + ")");
    planes[q] = upsample(*it->second, refine, 1);
    in.quantities[q] = &planes[q];
  }
  in.position_ring = 1 + kNoiseLatticeReach;
  const std::vector<Vec3d> position = pixel_positions(grid, cell, size, refine, in.position_ring);
  in.position = &position;
  in.col0 = global_col(cell, m, 0);
  in.row0 = global_row(cell, m, 0);
  in.pixel_m = pixel_m;
  const Surface s = evaluate(model, in);

  Rendered out{m, std::vector<float>(size_t(m) * size_t(m) * 3),
               std::vector<float>(size_t(m) * size_t(m)), normals(s.height, pixel_m),
               std::vector<float>(size_t(m) * size_t(m))};
  for (int r = 0; r < m; ++r)
    for (int c = 0; c < m; ++c) {
      const size_t o = size_t(r) * size_t(m) + size_t(c);
      const size_t i = size_t(r + 1) * size_t(m + 2) + size_t(c + 1);
      for (size_t k = 0; k < 3; ++k) out.rgb[3 * o + k] = s.rgb[3 * i + k];
      out.height[o] = s.height.v[i];
      out.classes[o] = s.dominant_class.v[i];
    }
  return out;
}

}  // namespace maquette::texture
