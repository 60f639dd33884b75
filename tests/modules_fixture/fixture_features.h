// The fixture module's operators on features layers (fixture_features.cpp).
#pragma once

#include <memory>

#include "runtime/operator.h"

// Reach of their features ports.
inline constexpr double kFixtureReachM = 1000;
// fixture.content's volumes: a level-set sphere at the first point a cell owns.
inline constexpr double kSphereRadiusM = 4;
inline constexpr double kSphereVoxelM = 0.5;

std::unique_ptr<maquette::Operator> make_near_features();
std::unique_ptr<maquette::Operator> make_region_features();
std::unique_ptr<maquette::Operator> make_features_total();
std::unique_ptr<maquette::Operator> make_content();         // fixture_content.cpp
std::unique_ptr<maquette::Operator> make_region_content();  // fixture_content.cpp
