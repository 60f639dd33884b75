// Outside models (maquette ingest --as model: formats/gltf/gltf_model.h), GLB or glTF JSON, read
// from a file as the ingest reads them; and the GLB chunks that the store and the exports split
// (content/glb_chunks.h). Anything else than a model or maquette::Error is a finding.
#include "content/glb_chunks.h"
#include "core/error.h"
#include "fuzz_input.h"
#include "gltf/gltf_model.h"

using namespace maquette;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view bytes = fuzz::as_text(data, size);
  try {
    split_glb(bytes, "fuzz.glb");
  } catch (const Error&) {
  }
  try {
    read_gltf_model(fuzz::scratch_file("model.glb", bytes));
  } catch (const Error&) {
  }
  return 0;
}
