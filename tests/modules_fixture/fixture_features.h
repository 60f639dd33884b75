// The fixture module's operators on features layers (fixture_features.cpp).
#pragma once

#include <memory>

#include "runtime/operator.h"

// Reach of their features ports.
inline constexpr double kFixtureReachM = 1000;

std::unique_ptr<maquette::Operator> make_near_features();
std::unique_ptr<maquette::Operator> make_region_features();
std::unique_ptr<maquette::Operator> make_features_total();
std::unique_ptr<maquette::Operator> make_mesh_out();
