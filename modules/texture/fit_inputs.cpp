#include "fit_inputs.h"

#include "core/error.h"
#include "model.h"

namespace maquette::texture {

std::string quantity_port(const std::string& quantity) {
  return quantity == "height" || quantity == "slope" ? "dem" : quantity;
}

void check_quantity_inputs(const std::vector<std::string>& quantities,
                           const std::set<std::string>& mapped, const std::string& op) {
  for (const std::string& q : quantities)
    if (const std::string port = quantity_port(q); !mapped.count(port))
      throw Error(op + ": params.quantities: '" + (port == "dem" ? "height/slope" : port) +
                  "' has no input (map inputs." + port + ")");
}

std::vector<Plane> quantity_planes(const CellContext& ctx, const CellData& data,
                                   const std::vector<std::string>& quantities,
                                   const std::string& op) {
  std::set<std::string> mapped;
  for (const auto& [port, tile] : data.inputs) mapped.insert(port);
  check_quantity_inputs(quantities, mapped, op);
  std::vector<Plane> out;
  const auto input = [&](const std::string& q) -> const Tile<float>& {
    return data.inputs.at(quantity_port(q));
  };
  for (const std::string& q : quantities) {
    if (q == "slope") {
      const double pixel_m = ctx.grid->level_info(ctx.cell.level(), ctx.tile_size).pixel_m;
      out.push_back(slope_degrees(upsample(input(q), 0, 1), pixel_m));
    } else {
      out.push_back(is_categorical(q) ? nearest(input(q), 0, 0) : upsample(input(q), 0, 0));
    }
  }
  return out;
}

}  // namespace maquette::texture
