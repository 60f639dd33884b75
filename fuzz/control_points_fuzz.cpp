// A painting's control points (render fit: formats/render/painting_fit_points.h). Anything else
// than points or maquette::Error is a finding.
#include "core/error.h"
#include "fuzz_input.h"
#include "render/painting_fit_points.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    maquette::parse_painting_points(std::string(maquette::fuzz::as_text(data, size)),
                                    "points.json");
  } catch (const maquette::Error&) {
  }
  return 0;
}
