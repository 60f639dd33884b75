// structures.prism's clicks in a photo (modules/structures/prism_strokes.h), read from a file as
// maquette-prism reads them. Anything else than strokes or maquette::Error is a finding.
#include "core/error.h"
#include "fuzz_input.h"
#include "prism_strokes.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    maquette::structures::read_prism_strokes(
        maquette::fuzz::scratch_file("strokes.json", maquette::fuzz::as_text(data, size)));
  } catch (const maquette::Error&) {
  }
  return 0;
}
