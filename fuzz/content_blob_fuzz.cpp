// Content blobs as the store holds them (content/content_blob.h): the envelope, then the payload
// of its kind (instances: decode_instances; mesh: the GLB's chunks). Anything else than a decoded
// blob or maquette::Error is a finding. Volumes (OpenVDB streams) are read by OpenVDB itself.
#include "content/content_blob.h"
#include "content/glb_chunks.h"
#include "content/instances_codec.h"
#include "core/error.h"
#include "fuzz_input.h"

using namespace maquette;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view blob = fuzz::as_text(data, size);
  try {
    const ContentEnvelope envelope = read_content_envelope(blob, "fuzz blob");
    const std::string_view payload = content_payload(blob);
    if (envelope.kind == ContentKind::Instances) decode_instances(payload, "fuzz blob");
    if (envelope.kind == ContentKind::Mesh) split_glb(payload, "fuzz blob");
  } catch (const Error&) {
  }
  return 0;
}
