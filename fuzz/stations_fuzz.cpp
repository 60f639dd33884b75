// Stations CSV (maquette ingest --as stations, formats/vector) into an artifact of a real store,
// then the artifact read as climate.fit_stations reads it (modules/climate/stations.h). Anything
// else than stations or maquette::Error is a finding.
#include "core/error.h"
#include "fuzz_input.h"
#include "stations.h"
#include "store/store.h"
#include "vector/vector_ingest.h"

using namespace maquette;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::unique_ptr<Store> store =
      Store::open(fuzz::scratch_path("stations.mqt"), Store::Mode::Create);
  const std::string csv = fuzz::scratch_file("stations.csv", fuzz::as_text(data, size));
  StationsIngestOptions options;
  options.layer = "stations";
  try {
    ingest_stations(*store, csv, options);
    const auto artifact = store->get_artifact("stations");
    climate::parse_stations(nlohmann::json::parse(artifact->text()), "stations");
  } catch (const Error&) {
  }
  return 0;
}
