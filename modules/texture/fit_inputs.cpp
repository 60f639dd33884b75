#include "fit_inputs.h"

#include "core/error.h"
#include "model.h"

namespace maquette::texture {

std::vector<Plane> quantity_planes(const CellContext& ctx, const CellData& data,
                                   const std::vector<std::string>& quantities,
                                   const std::string& op) {
  std::vector<Plane> out;
  const auto input = [&](const std::string& port) -> const Tile<float>& {
    if (!data.inputs.count(port))
      throw Error(op + ": params.quantities: '" + (port == "dem" ? "height/slope" : port) +
                  "' has no input (map inputs." + port + ")");
    return data.inputs.at(port);
  };
  for (const std::string& q : quantities) {
    if (q == "slope") {
      const double pixel_m = ctx.grid->level_info(ctx.cell.level(), ctx.tile_size).pixel_m;
      out.push_back(slope_degrees(upsample(input("dem"), 0, 1), pixel_m));
    } else {
      out.push_back(is_categorical(q) ? nearest(input(q), 0, 0)
                                      : upsample(input(q == "height" ? "dem" : q), 0, 0));
    }
  }
  return out;
}

}  // namespace maquette::texture
