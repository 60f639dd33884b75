// Strokes as features layers hold them (a GeoJSON or other OGR source ingested: WKB geometry and
// JSON attributes, fuzz_input.h's split): the geometry parsed (core/geometry.h), then read by
// every stroke parser: deform.features' feature strokes, deform.water's polygons,
// structures.bridge's edges and structures.vegetation's polygons. Anything else than strokes
// or maquette::Error is a finding.
#include "bridge_stroke.h"
#include "core/error.h"
#include "fuzz_input.h"
#include "stroke.h"
#include "vegetation_stroke.h"
#include "water_stroke.h"

using namespace maquette;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const fuzz::FeatureBytes bytes = fuzz::split_feature(data, size);
  VectorFeature feature;
  feature.id = 1;
  // The store holds attributes as a JSON object it wrote itself: other text is no stroke.
  feature.attributes = nlohmann::json::parse(bytes.attributes, nullptr, false);
  if (!feature.attributes.is_object()) return 0;
  try {
    feature.geometry = parse_wkb(bytes.wkb, "feature 1");
  } catch (const Error&) {
    return 0;
  }
  const FeatureList features = {&feature};
  try {
    deform::feature_strokes(features, "strokes");
  } catch (const Error&) {
  }
  try {
    if (deform::is_water_stroke(feature)) deform::stroke_polygon(feature);
  } catch (const Error&) {
  }
  try {
    if (structures::is_bridge_stroke(feature)) structures::bridge_stroke(feature, 1);
  } catch (const Error&) {
  }
  try {
    structures::vegetation_strokes(features, "strokes");
  } catch (const Error&) {
  }
  return 0;
}
