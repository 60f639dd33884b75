// Factories of the climate module's operators (listed in module.cpp).
#pragma once

#include <memory>

#include "runtime/operator.h"

namespace maquette::climate {

std::unique_ptr<Operator> make_fit_stations();
std::unique_ptr<Operator> make_regionalize();
std::unique_ptr<Operator> make_solar();
std::unique_ptr<Operator> make_orographic();

}  // namespace maquette::climate
