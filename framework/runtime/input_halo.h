// The check a cell operator makes of a raster input it reads beyond its cell (a neighbourhood, a
// horizon): the tile has the halo the operator needs and the run's tile size. The runner gives
// each input the halo its port declares (InputSpec); this names the cell and the port when an
// operator is run otherwise (e.g. by a test or another operator).
#pragma once

#include <string>

#include "runtime/operator.h"

namespace maquette {

// data.input(port), after checking that it has at least `halo` pixels of halo and ctx.tile_size
// samples a side. Throws maquette::Error "OP: input 'PORT' of cell C needs a halo of N pixels
// and tile size S" otherwise (`op`: the operator's name).
const Tile<float>& input_with_halo(const std::string& op, const CellContext& ctx,
                                   const CellData& data, const std::string& port, int halo);

}  // namespace maquette
