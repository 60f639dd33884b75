// Factories of the deform module's operators (listed in module.cpp).
#pragma once

#include <memory>

#include "runtime/operator.h"

namespace maquette::deform {

std::unique_ptr<Operator> make_features();

}  // namespace maquette::deform
