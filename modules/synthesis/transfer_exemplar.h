// synthesis.transfer's exemplar from its step's params: the painting read, labelled (a hand
// class image, else segment_by_colour), its exclusions applied, shrunk and analysed; built once
// per process for each distinct set of those params (the cells waiting for it join the work)
// and shared by the cells.
#pragma once

#include <memory>
#include <nlohmann/json.hpp>

#include "exemplar_pyramid.h"

namespace maquette::synthesis {

struct TransferExemplar {
  int scale = 1;            // painting pixels per exemplar pixel (a side)
  ExemplarPyramid pyramid;  // of the shrunk painting: levels[0] is what the output copies
};

// From the validated params (README: synthesis.transfer): "painting", "labels" or "classes",
// "exclusion", "exclude_classes", "painting_altitude", "painting_distance" (maquette-paint's),
// "exemplar_scale", "k". Throws
// maquette::Error naming the op, field and file at fault.
std::shared_ptr<const TransferExemplar> transfer_exemplar(const nlohmann::json& params);

}  // namespace maquette::synthesis
