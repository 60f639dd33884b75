// texture.classify: surface types of an RGB image in hue-saturation space (paper 5.2.1), with
// the snow rule (snow below a minimal altitude is cloud, paper 6) and a land-cover exclusion.
#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "hs_classes.h"
#include "operators.h"

namespace maquette::texture {
namespace {

json range_schema(double lo, double hi) {
  return {{"type", "array"}, {"items", {{"type", "number"}, {"minimum", lo}, {"maximum", hi}}}};
}

OperatorSpec classify_spec() {
  OperatorSpec s;
  s.name = "texture.classify";
  s.description =
      "Classes of an RGB image from boxes or cluster centres in hue-saturation space, grey "
      "pixels given a hue, snow below a minimal altitude and excluded land cover removed";
  s.kind = OperatorKind::Cell;
  s.inputs = {{"rgb", "RGB image, 0..255", false},
              {"dem", "elevation in metres (snow rule)", true},
              {"landcover", "land-cover classes (exclusion)", true}};
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
  const json centre = {{"type", "object"},
                       {"additionalProperties", false},
                       {"required", {"id", "hue", "saturation"}},
                       {"properties",
                        {{"id", {{"type", "integer"}, {"minimum", 0}, {"maximum", 254}}},
                         {"name", {{"type", "string"}}},
                         {"hue", {{"type", "number"}, {"minimum", 0}, {"maximum", 360}}},
                         {"saturation", {{"type", "number"}, {"minimum", 0}, {"maximum", 1}}},
                         {"pixels", {{"type", "integer"}}}}}};
  s.params_schema = {
      {"type", "object"},
      {"additionalProperties", false},
      {"properties",
       {{"boxes", {{"type", "array"}, {"items", box}, {"default", json::array()}}},
        {"centres", {{"type", "array"}, {"items", centre}, {"default", json::array()}}},
        {"snow_class", {{"type", "integer"}, {"minimum", -1}, {"maximum", 254}, {"default", -1}}},
        {"snow_min_altitude_m", {{"type", "number"}, {"default", 0}}},
        {"exclude_landcover",
         {{"type", "array"}, {"items", {{"type", "integer"}}}, {"default", json::array()}}}}}};
  s.params_schema["properties"].update(grey_params_schema());
  return s;
}

class Classify : public CellOperator {
 public:
  const OperatorSpec& spec() const override { return spec_; }

  void run(const CellContext& ctx, CellData& data) const override {
    const json& p = *ctx.params;
    if (p.at("boxes").empty() && p.at("centres").empty())
      throw Error(
          "texture.classify: params: give \"boxes\" or \"centres\" (e.g. from "
          "texture.cluster)");
    for (const char* key : {"hue", "saturation", "value"})
      for (size_t i = 0; i < p.at("boxes").size(); ++i)
        if (p["boxes"][i].contains(key) && p["boxes"][i][key].size() != 2)
          throw Error("texture.classify: params.boxes[" + std::to_string(i) + "]." + key +
                      ": expected [lo, hi]");
    const HsClassifier classifier = HsClassifier::from_params(p);
    const Tile<float>& rgb = data.input("rgb");
    if (rgb.channels() != 3)
      throw Error("texture.classify: inputs.rgb: expected 3 channels, got " +
                  std::to_string(rgb.channels()));
    const Tile<float>* dem = data.inputs.count("dem") ? &data.inputs.at("dem") : nullptr;
    const Tile<float>* lc = data.inputs.count("landcover") ? &data.inputs.at("landcover") : nullptr;
    const int snow = p.at("snow_class").get<int>();
    const double snow_min = p.at("snow_min_altitude_m").get<double>();
    std::vector<int> excluded = p.at("exclude_landcover").get<std::vector<int>>();
    if (!excluded.empty() && !lc)
      throw Error("texture.classify: params.exclude_landcover needs inputs.landcover");
    if (snow >= 0 && !dem) throw Error("texture.classify: params.snow_class needs inputs.dem");
    Tile<float>& out = data.output("classes") = Tile<float>(ctx.tile_size, 1, 0, NAN);
    for (int r = 0; r < ctx.tile_size; ++r)
      for (int c = 0; c < ctx.tile_size; ++c) {
        const float R = rgb.at(c, r, 0), G = rgb.at(c, r, 1), B = rgb.at(c, r, 2);
        if (std::isnan(R) || std::isnan(G) || std::isnan(B)) continue;
        if (!excluded.empty() &&
            (std::isnan(lc->at(c, r)) ||
             std::find(excluded.begin(), excluded.end(), int(lc->at(c, r))) != excluded.end()))
          continue;
        const int k = classifier.classify(R, G, B);
        if (k < 0) continue;
        if (k == snow && !(dem->at(c, r) >= snow_min)) continue;  // cloud, or unknown height
        out.at(c, r) = float(k);
      }
  }

 private:
  OperatorSpec spec_ = classify_spec();
};

}  // namespace

std::unique_ptr<Operator> make_classify() { return std::make_unique<Classify>(); }

}  // namespace maquette::texture
