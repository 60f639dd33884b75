// Factories of the texture module's operators (listed in module.cpp), and the input ports of
// the geographic quantities an operator may read besides height and slope.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "runtime/operator.h"

namespace maquette::texture {

// Input rasters of model quantities; "landcover" is categorical (model.h).
inline const std::vector<std::string> kRasterPorts = {"temperature", "rainfall", "radiation",
                                                      "extra", "landcover"};

std::unique_ptr<Operator> make_procedural();
std::unique_ptr<Operator> make_classify();
std::unique_ptr<Operator> make_cluster();
std::unique_ptr<Operator> make_fit();
std::unique_ptr<Operator> make_assess();
std::unique_ptr<Operator> make_calibrate();
std::unique_ptr<Operator> make_landcover_share();

}  // namespace maquette::texture
