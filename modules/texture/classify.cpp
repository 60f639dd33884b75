// texture.classify: surface types of an RGB image in hue-saturation space (paper 5.2.1), with
// the snow rule (snow below a minimal altitude is cloud, paper 6) and exclusions by land cover or
// by the polygons of a features layer.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "core/error.h"
#include "feature_mask.h"
#include "hs_classes.h"
#include "illumination.h"
#include "majority_filter.h"
#include "operators.h"
#include "runtime/params_schema.h"

namespace maquette::texture {
namespace {

json range_schema(double lo, double hi) {
  return {{"type", "array"},
          {"items", {{"type", "number"}, {"minimum", lo}, {"maximum", hi}}},
          {"minItems", 2},
          {"maxItems", 2},
          {"description", "[lo, hi]"}};
}

// The classes of params, their errors prefixed with the operator like its other errors.
HsClassifier classifier_of(const json& params) {
  try {
    return HsClassifier::from_params(params);
  } catch (const Error& e) {
    throw Error(std::string("texture.classify: ") + e.what());
  }
}

OperatorSpec classify_spec() {
  OperatorSpec s;
  s.name = "texture.classify";
  s.description =
      "Classes of an RGB image from boxes, polygons or cluster centres in hue-saturation "
      "space (or centres in CIELAB), grey pixels given a hue, snow below a minimal altitude, "
      "excluded land cover and "
      "the polygons of a features layer removed";
  s.kind = OperatorKind::Cell;
  s.inputs = {{.name = "rgb", .description = "RGB image, 0..255", .channels = {3}},
              {"dem", "elevation in metres (snow rule)", true},
              {"landcover", "land-cover classes (exclusion)", true},
              {"hillshade",
               "terrain.derive's hillshade at the image's sun (1 + 254 cos i; illumination "
               "correction)",
               true}};
  s.outputs = {{"classes", "surface type (255: none or excluded)", DType::U8, 1,
                Semantics::Categorical, "", 255.0}};
  const json box = {{"type", "object"},
                    {"additionalProperties", false},
                    {"required", {"id"}},
                    {"properties",
                     {{"id", {{"type", "integer"}, {"minimum", 0}, {"maximum", 254}}},
                      {"name", {{"type", "string"}}},
                      {"hue", range_schema(0, 360)},
                      {"saturation", range_schema(0, 1)},
                      {"value", range_schema(0, 1)}}}};
  // Points are checked further by HsClassifier::from_params (count, hue and saturation ranges).
  const json polygon = {
      {"type", "object"},
      {"additionalProperties", false},
      {"required", {"id", "points"}},
      {"properties",
       {{"id", {{"type", "integer"}, {"minimum", 0}, {"maximum", 254}}},
        {"name", {{"type", "string"}}},
        {"points",
         {{"type", "array"},
          {"items", {{"type", "array"}, {"items", {{"type", "number"}}}}},
          {"description",
           "[hue degrees, saturation] vertices, at least 3, joined by straight lines on "
           "texture.cluster's plot (s cos h, s sin h)"}}}}}};
  const json centre = {{"type", "object"},
                       {"additionalProperties", false},
                       {"required", {"id"}},
                       {"properties",
                        {{"id", {{"type", "integer"}, {"minimum", 0}, {"maximum", 254}}},
                         {"name", {{"type", "string"}}},
                         {"hue", {{"type", "number"}, {"minimum", 0}, {"maximum", 360}}},
                         {"saturation", {{"type", "number"}, {"minimum", 0}, {"maximum", 1}}},
                         {"value", {{"type", "number"}, {"minimum", 0}, {"maximum", 1}}},
                         {"L", {{"type", "number"}, {"minimum", 0}, {"maximum", 100}}},
                         {"a", {{"type", "number"}}},
                         {"b", {{"type", "number"}}},
                         {"pixels", {{"type", "integer"}}}}}};
  s.halo = kMaxMajorityRadius;
  s.params_schema = {
      {"type", "object"},
      {"additionalProperties", false},
      {"properties",
       {{"majority_radius",
         integer_param(0, kMaxMajorityRadius, 0,
                       "each class pixel takes the most frequent class of the (2r+1)^2 window "
                       "around it (minimum mapping unit; 0: none)")},
        {"boxes", {{"type", "array"}, {"items", box}, {"default", json::array()}}},
        {"polygons", {{"type", "array"}, {"items", polygon}, {"default", json::array()}}},
        {"centres", {{"type", "array"}, {"items", centre}, {"default", json::array()}}},
        {"snow_class", {{"type", "integer"}, {"minimum", -1}, {"maximum", 254}, {"default", -1}}},
        {"snow_min_altitude_m", {{"type", "number"}, {"default", 0}}},
        {"exclude_landcover",
         {{"type", "array"}, {"items", {{"type", "integer"}}}, {"default", json::array()}}},
        {"exclude_features",
         {{"type", "string"},
          {"default", ""},
          {"description",
           "features layer of the store whose polygons are removed (pixel centres inside); "
           "empty: none"}}}}}};
  s.params_schema["properties"].update(grey_params_schema());
  s.params_schema["properties"].update(illumination_params_schema());
  s.check_params = [](const json& p, const std::set<std::string>& mapped) {
    if (p.at("boxes").empty() && p.at("polygons").empty() && p.at("centres").empty())
      throw Error(
          "texture.classify: params: give \"boxes\", \"polygons\" or \"centres\" (e.g. "
          "from texture.cluster)");
    classifier_of(p);
    check_illumination_params(p, mapped.count("hillshade") > 0, "texture.classify");
  };
  return s;
}

class Classify : public CellOperator {
 public:
  const OperatorSpec& spec() const override { return spec_; }

  void run(const CellContext& ctx, CellData& data) const override {
    const json& p = *ctx.params;
    const HsClassifier classifier = classifier_of(p);
    const Tile<float>& rgb = data.input("rgb");
    const Tile<float>* dem = data.inputs.count("dem") ? &data.inputs.at("dem") : nullptr;
    const Tile<float>* lc = data.inputs.count("landcover") ? &data.inputs.at("landcover") : nullptr;
    const int snow = p.at("snow_class").get<int>();
    const double snow_min = p.at("snow_min_altitude_m").get<double>();
    std::vector<int> excluded = p.at("exclude_landcover").get<std::vector<int>>();
    if (!excluded.empty() && !lc)
      throw Error("texture.classify: params.exclude_landcover needs inputs.landcover");
    if (snow >= 0 && !dem) throw Error("texture.classify: params.snow_class needs inputs.dem");
    const std::optional<Illumination> light = illumination_of(p, data, "texture.classify");
    // Classes of the tile and a ring of `radius` pixels (-1: none), then the majority filter.
    const int radius = p.at("majority_radius").get<int>(), n = ctx.tile_size;
    const int side = n + 2 * radius;
    for (const auto& [port, tile] : data.inputs)  // every input is read in the ring
      if (tile.halo() < radius)
        throw Error("texture.classify: inputs." + port + ": halo " + std::to_string(tile.halo()) +
                    " is narrower than params.majority_radius " + std::to_string(radius));
    std::vector<uint8_t> in_features;  // side x side when params.exclude_features is given
    if (const std::string layer = p.at("exclude_features"); !layer.empty()) {
      const std::string where = "texture.classify: params.exclude_features";
      if (!ctx.store) throw Error(where + ": no store (the layer is read from the run's store)");
      in_features = features_mask(*ctx.store, layer, where, *ctx.grid, ctx.cell, n, radius);
    }
    std::vector<int> cls(size_t(side) * size_t(side), -1);
    for (int r = -radius; r < n + radius; ++r)
      for (int c = -radius; c < n + radius; ++c) {
        const size_t i = size_t(r + radius) * size_t(side) + size_t(c + radius);
        std::array<float, 3> colour = {rgb.at(c, r, 0), rgb.at(c, r, 1), rgb.at(c, r, 2)};
        if (std::isnan(colour[0]) || std::isnan(colour[1]) || std::isnan(colour[2])) continue;
        if (!in_features.empty() && in_features[i]) continue;
        if (!excluded.empty() &&
            (std::isnan(lc->at(c, r)) ||
             std::find(excluded.begin(), excluded.end(), int(lc->at(c, r))) != excluded.end()))
          continue;
        if (light) colour = light->corrected(colour, c, r);
        const int k = classifier.classify(colour[0], colour[1], colour[2]);
        if (k < 0) continue;
        if (k == snow && !(dem->at(c, r) >= snow_min)) continue;  // cloud, or unknown height
        cls[i] = k;
      }
    const std::vector<int> filtered = majority_filter(cls, n, radius);
    Tile<float>& out = data.output("classes") = Tile<float>(n, 1, 0, NAN);
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < n; ++c)
        if (const int k = filtered[size_t(r) * size_t(n) + size_t(c)]; k >= 0)
          out.at(c, r) = float(k);
  }

 private:
  OperatorSpec spec_ = classify_spec();
};

}  // namespace

std::unique_ptr<Operator> make_classify() { return std::make_unique<Classify>(); }

}  // namespace maquette::texture
