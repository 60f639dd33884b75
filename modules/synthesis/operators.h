// Factories of the synthesis module's operators (listed in module.cpp).
#pragma once

#include <memory>

#include "runtime/operator.h"

namespace maquette::synthesis {

std::unique_ptr<Operator> make_transfer();
std::unique_ptr<Operator> make_assess();
std::unique_ptr<Operator> make_inpaint();
std::unique_ptr<Operator> make_clone();
std::unique_ptr<Operator> make_apply();

}  // namespace maquette::synthesis
