#include "runtime/input_halo.h"

#include "core/error.h"

namespace maquette {

const Tile<float>& input_with_halo(const std::string& op, const CellContext& ctx,
                                   const CellData& data, const std::string& port, int halo) {
  const Tile<float>& tile = data.input(port);
  if (tile.halo() < halo || tile.size() != ctx.tile_size)
    throw Error(op + ": input '" + port + "' of cell " + ctx.cell.ToText() + " needs a halo of " +
                std::to_string(halo) + (halo == 1 ? " pixel" : " pixels") + " and tile size " +
                std::to_string(ctx.tile_size));
  return tile;
}

}  // namespace maquette
