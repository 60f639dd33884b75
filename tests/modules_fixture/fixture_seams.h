// The fixture module's operators for region mosaics across face seams (fixture_seams.cpp).
#pragma once

#include <memory>

#include "runtime/operator.h"

std::unique_ptr<maquette::Operator> make_pixel_lonlat();
std::unique_ptr<maquette::Operator> make_region_seams();
