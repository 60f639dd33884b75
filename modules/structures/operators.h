// Factories of the structures module's operators (listed in module.cpp).
#pragma once

#include <memory>

#include "runtime/operator.h"

namespace maquette::structures {

std::unique_ptr<Operator> make_buildings();
std::unique_ptr<Operator> make_vegetation();
// structures.vegetation_spacing: the spacing of strokes without spacing_m from the orthophoto
// (spacing_estimate.h), as an artifact for structures.vegetation (a reduce operator: the tiles of
// a stroke summed, whatever cell, thread or rank computed each).
std::unique_ptr<Operator> make_vegetation_spacing();
std::unique_ptr<Operator> make_place();
std::unique_ptr<Operator> make_bridge();

}  // namespace maquette::structures
