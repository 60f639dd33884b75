// Factories of the structures module's operators (listed in module.cpp).
#pragma once

#include <memory>

#include "runtime/operator.h"

namespace maquette::structures {

std::unique_ptr<Operator> make_buildings();

}  // namespace maquette::structures
