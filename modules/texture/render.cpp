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
  const PixelPositions position(grid, cell, size, refine, in.height.ring + kNoiseLatticeReach);
  in.position = &position;
  in.col0 = global_col(cell, m, 0);
  in.row0 = global_row(cell, m, 0);
  in.pixel_m = pixel_m;
  const Surface s = evaluate(model, in);

  // The interior, a row at a time (no zero-filled buffers to overwrite).
  Rendered out{m, {}, {}, normals(s.height, pixel_m), {}};
  const size_t n = size_t(m) * size_t(m);
  out.rgb.reserve(3 * n);
  out.height.reserve(n);
  out.classes.reserve(n);
  for (int r = 0; r < m; ++r) {
    const size_t i = size_t(r + 1) * size_t(m + 2) + 1;
    out.rgb.insert(out.rgb.end(), s.rgb.begin() + ptrdiff_t(3 * i),
                   s.rgb.begin() + ptrdiff_t(3 * (i + size_t(m))));
    out.height.insert(out.height.end(), s.height.v.begin() + ptrdiff_t(i),
                      s.height.v.begin() + ptrdiff_t(i + size_t(m)));
    out.classes.insert(out.classes.end(), s.dominant_class.v.begin() + ptrdiff_t(i),
                       s.dominant_class.v.begin() + ptrdiff_t(i + size_t(m)));
  }
  return out;
}

}  // namespace maquette::texture
