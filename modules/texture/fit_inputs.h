// The per-pixel samples texture.fit and texture.assess read from a cell: the quantities of the
// model at the inputs' resolution, computed exactly as texture.procedural computes them at
// refine 0 (B-spline of the DEM, slope from it), so a fitted model sees what it was fitted on;
// the categorical land cover as it is (texture.procedural interpolates each layer's table values
// through the input pixels, categorical_values.h: at refine 0 they are read back within 3 %).
#pragma once

#include <set>
#include <string>
#include <vector>

#include "field.h"
#include "runtime/operator.h"

namespace maquette::texture {

// The input port a quantity is computed from: "dem" for "height" and "slope", else its own name.
std::string quantity_port(const std::string& quantity);

// Throws maquette::Error naming `op` and the first of `quantities` whose port is not `mapped`.
void check_quantity_inputs(const std::vector<std::string>& quantities,
                           const std::set<std::string>& mapped, const std::string& op);

// One plane (ring 0) per name in `quantities` ("height", "slope" or an input port name).
// Throws naming `op` and the quantity when its input is not mapped.
std::vector<Plane> quantity_planes(const CellContext& ctx, const CellData& data,
                                   const std::vector<std::string>& quantities,
                                   const std::string& op);

}  // namespace maquette::texture
