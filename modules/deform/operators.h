// Factories of the deform module's operators (listed in module.cpp).
#pragma once

#include <memory>

#include "runtime/operator.h"

namespace maquette::deform {

std::unique_ptr<Operator> make_features();
// deform.water: the bodies of water of closed strokes (tool "water"), a region operator (a lake
// spans cells); deform.water_bodies: each body's level, area and volume from deform.water's
// depth, as an artifact (a reduce operator: region operators have no artifact output).
std::unique_ptr<Operator> make_water();
std::unique_ptr<Operator> make_water_bodies();

}  // namespace maquette::deform
