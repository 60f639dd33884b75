// GeoJSON regions (a pipeline's "region": {"geojson": ...}, maquette cells --geojson): parsed,
// their polygons read, their size checked and covered at a coarse level. Anything else than
// cells or maquette::Error is a finding.
#include "core/error.h"
#include "core/geojson.h"
#include "core/json_file.h"
#include "fuzz_input.h"

using namespace maquette;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  constexpr int kLevel = 5;  // 6,144 cells on the sphere: the cover stays fast
  try {
    const auto polygons =
        geojson_polygons(parse_json(fuzz::as_text(data, size), "fuzz.geojson"), "fuzz.geojson");
    check_cover_size(polygons, kLevel, "fuzz.geojson");
    cover_geojson(default_grid(), polygons, kLevel, Containment::Overlap);
  } catch (const Error&) {
  }
  return 0;
}
