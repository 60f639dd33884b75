// Factories of the terrain module's operators (listed in module.cpp).
#pragma once

#include <memory>

#include "runtime/operator.h"

namespace maquette::terrain {

std::unique_ptr<Operator> make_synthesize();
std::unique_ptr<Operator> make_derive();
std::unique_ptr<Operator> make_fill_voids();

}  // namespace maquette::terrain
