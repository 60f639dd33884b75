// texture.assess (reduce): agreement between a classified image and a model's dominant class
// per pixel (confusion matrix, accuracy, Cohen's kappa, class-area proportions), and the
// CIEDE2000 difference between the image and the synthesized texture after a 5 x 5 box blur
// (the noise's detail is not meant to match pixel by pixel). Prints a table to stdout.
#include <algorithm>
#include <cmath>
#include <iostream>

#include "assessment.h"
#include "colour.h"
#include "core/error.h"
#include "operators.h"

namespace maquette::texture {
namespace {

constexpr int kBlur = 2;

OperatorSpec assess_spec() {
  OperatorSpec s;
  s.name = "texture.assess";
  s.description =
      "Confusion matrix, accuracy, Cohen's kappa and class areas between classified image and "
      "model's dominant class; CIEDE2000 after a 5x5 blur";
  s.kind = OperatorKind::Reduce;
  s.inputs = {{"classes", "observed surface types (texture.classify)", false},
              {"predicted", "dominant class of the model (texture.procedural classes)", false},
              {"rgb", "the observed image", true},
              {"synthesized", "the synthesized image (texture.procedural imagery)", true}};
  s.outputs = {{"report", "assessment (JSON)", DType::U8, 1, Semantics::Continuous, "", {}}};
  s.halo = kBlur;
  s.params_schema = {
      {"type", "object"}, {"additionalProperties", false}, {"properties", json::object()}};
  return s;
}

// Box mean of the 5 x 5 window; false when a sample is missing.
bool blurred(const Tile<float>& t, int c, int r, std::array<double, 3>& out) {
  out = {0, 0, 0};
  for (int dr = -kBlur; dr <= kBlur; ++dr)
    for (int dc = -kBlur; dc <= kBlur; ++dc)
      for (int k = 0; k < 3; ++k) {
        const float v = t.at(c + dc, r + dr, k);
        if (std::isnan(v)) return false;
        out[size_t(k)] += v;
      }
  for (double& v : out) v /= (2 * kBlur + 1) * (2 * kBlur + 1);
  return true;
}

class Assess : public ReduceOperator {
 public:
  const OperatorSpec& spec() const override { return spec_; }

  json map(const CellContext& ctx, const CellData& data) const override {
    const Tile<float>& obs = data.input("classes");
    const Tile<float>& pred = data.input("predicted");
    const bool colour = data.inputs.count("rgb") && data.inputs.count("synthesized");
    std::map<std::string, uint64_t> confusion;
    double de = 0;
    uint64_t de_n = 0;
    for (int r = 0; r < ctx.tile_size; ++r)
      for (int c = 0; c < ctx.tile_size; ++c) {
        if (!std::isnan(obs.at(c, r)))
          ++confusion[std::to_string(int(obs.at(c, r))) + "," +
                      (std::isnan(pred.at(c, r)) ? "-1" : std::to_string(int(pred.at(c, r))))];
        std::array<double, 3> a, b;
        if (colour && blurred(data.inputs.at("rgb"), c, r, a) &&
            blurred(data.inputs.at("synthesized"), c, r, b)) {
          de += ciede2000(srgb_to_lab(a[0], a[1], a[2]), srgb_to_lab(b[0], b[1], b[2]));
          ++de_n;
        }
      }
    if (confusion.empty() && de_n == 0) return nullptr;
    return {{"confusion", confusion}, {"de_sum", de}, {"de_n", de_n}};
  }

  json merge(const json& a, const json& b) const override {
    if (a.is_null()) return b;
    if (b.is_null()) return a;
    json out = a;
    for (const auto& [k, n] : b.at("confusion").items())
      out["confusion"][k] = out["confusion"].value(k, uint64_t(0)) + n.get<uint64_t>();
    out["de_sum"] = a["de_sum"].get<double>() + b["de_sum"].get<double>();
    out["de_n"] = a["de_n"].get<uint64_t>() + b["de_n"].get<uint64_t>();
    return out;
  }

  Artifact finish(const json& merged, const StepContext&) const override {
    if (merged.is_null() || merged.at("confusion").empty())
      throw Error("texture.assess: no classified pixel in the region (inputs.classes empty)");
    const json report = assessment(merged);
    std::cout << assessment_table(report) << std::flush;
    const std::string text = report.dump(1);
    return Artifact::FromText("report", text,
                              {{"kappa", report["kappa"]}, {"accuracy", report["accuracy"]}});
  }

 private:
  OperatorSpec spec_ = assess_spec();
};

}  // namespace

std::unique_ptr<Operator> make_assess() { return std::make_unique<Assess>(); }

}  // namespace maquette::texture
