// Pipeline JSON (runtime/pipeline.h): parse_pipeline with the fixture operators
// (tests/modules_fixture) as the registry, relative paths resolved in a scratch directory.
// Anything else than a pipeline or maquette::Error is a finding.
#include <filesystem>

#include "core/error.h"
#include "fuzz_input.h"
#include "runtime/operator_registry.h"
#include "runtime/pipeline.h"

using namespace maquette;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const OperatorRegistry registry = OperatorRegistry::load({MAQUETTE_FIXTURE_MODULES});
  static const std::string base_dir =
      std::filesystem::path(fuzz::scratch_path("fuzz.json")).parent_path().string();
  try {
    parse_pipeline(fuzz::as_text(data, size), "fuzz.json", base_dir, registry);
  } catch (const Error&) {
  }
  return 0;
}
