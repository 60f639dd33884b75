// deform.water: the bodies of water of closed strokes (tool "water"), a region operator (a lake
// spans cells). See README-water.md.
#pragma once

#include <memory>

#include "runtime/operator.h"

namespace maquette::deform {

std::unique_ptr<Operator> make_water();

}  // namespace maquette::deform
