// texture.assess (reduce): agreement between a classified image and a model's dominant class
// per pixel (confusion matrix, accuracy, Cohen's kappa, class-area proportions), and the
// CIEDE2000 difference between the image and the synthesized texture after a Gaussian blur (the
// noise's detail is not meant to match pixel by pixel), and per class the mean colour and colour
// spread of the image's pixels of the class and of the texture's. Prints a table to stdout.
// Optionally the predicted classes are compared after the majority filter of texture.classify
// (the observed map's minimum mapping unit), the agreement of the classes as rendered reported
// beside it.
#include <algorithm>
#include <cmath>
#include <iostream>

#include "assessment.h"
#include "colour.h"
#include "core/error.h"
#include "illumination.h"
#include "majority_filter.h"
#include "operators.h"
#include "runtime/params_schema.h"

namespace maquette::texture {
namespace {

constexpr double kSigma = 4;  // pixels: the texture's noise detail is not meant to match
constexpr int kBlur = 3 * int(kSigma);

OperatorSpec assess_spec() {
  OperatorSpec s;
  s.name = "texture.assess";
  s.description =
      "Confusion matrix, accuracy, Cohen's kappa and class areas between classified image and "
      "model's dominant class; CIEDE2000 after a Gaussian blur (sigma 4 px); each class's mean "
      "colour and colour spread in the image and in the texture";
  s.kind = OperatorKind::Reduce;
  s.inputs = {
      {"classes", "observed surface types (texture.classify)", false},
      {"predicted", "dominant class of the model (texture.procedural classes)", false},
      {.name = "rgb", .description = "the observed image", .optional = true, .channels = {3}},
      {"synthesized", "the synthesized image (texture.procedural imagery)", true},
      {"hillshade",
       "terrain.derive's hillshade at the image's sun: the image compared with its "
       "illumination removed (as texture.fit's colours)",
       true},
      {"colour_classes",
       "each pixel's own class (as texture.fit's): a class's image colour from its "
       "pixels whose own class it is",
       true}};
  s.outputs = {{"report", "assessment (JSON)", DType::U8, 1, Semantics::Continuous, "", {}}};
  s.halo = std::max(kBlur, kMaxMajorityRadius);
  s.params_schema = {
      {"type", "object"},
      {"additionalProperties", false},
      {"properties",
       {{"predicted_majority_radius",
         integer_param(
             0, kMaxMajorityRadius, 0,
             "the predicted classes compared after texture.classify's majority filter "
             "of this radius (the observed map's minimum mapping unit; 0: as they are)")}}}};
  s.params_schema["properties"].update(illumination_params_schema());
  s.check_params = [](const json& p, const std::set<std::string>& mapped) {
    check_illumination_params(p, mapped.count("hillshade") > 0, "texture.assess");
  };
  s.params_schema["properties"].update(colour_incidence_param());
  return s;
}

// The n x n pixels of `t` (3 channels, halo >= kBlur) after a Gaussian blur of kSigma,
// separable, truncated at kBlur; NaN where a sample of the window is missing.
std::vector<std::array<double, 3>> blurred(const Tile<float>& t, int n) {
  std::array<double, 2 * kBlur + 1> w{};
  double sum = 0;
  for (int d = -kBlur; d <= kBlur; ++d)
    sum += w[size_t(d + kBlur)] = std::exp(-d * d / (2 * kSigma * kSigma));
  for (double& v : w) v /= sum;
  const int side = n + 2 * kBlur;
  std::vector<std::array<double, 3>> rows(size_t(side) * size_t(n));  // along rows first
  for (int r = -kBlur; r < n + kBlur; ++r)
    for (int c = 0; c < n; ++c) {
      std::array<double, 3> acc{};
      for (int d = -kBlur; d <= kBlur; ++d)
        for (int k = 0; k < 3; ++k) acc[size_t(k)] += w[size_t(d + kBlur)] * t.at(c + d, r, k);
      rows[size_t(r + kBlur) * size_t(n) + size_t(c)] = acc;
    }
  std::vector<std::array<double, 3>> out(size_t(n) * size_t(n));
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) {
      std::array<double, 3> acc{};
      for (int d = -kBlur; d <= kBlur; ++d)
        for (size_t k = 0; k < 3; ++k)
          acc[k] += w[size_t(d + kBlur)] * rows[size_t(r + d + kBlur) * size_t(n) + size_t(c)][k];
      out[size_t(r) * size_t(n) + size_t(c)] = acc;  // NaN propagates
    }
  return out;
}

// Colour moments of a set of pixels: [n, sum R, G, B, sum of squares R, G, B].
void add_moments(json& m, const std::array<float, 3>& x) {
  if (m.is_null()) m = std::vector<double>(7, 0.0);
  m[0] = m[0].get<double>() + 1;
  for (size_t k = 0; k < 3; ++k) {
    m[1 + k] = m[1 + k].get<double>() + x[k];
    m[4 + k] = m[4 + k].get<double>() + double(x[k]) * x[k];
  }
}

// The n x n predicted classes compared with the observed ones (-1: none): as they are, or after
// the majority filter of `radius` (the tile has a halo >= radius).
std::vector<int> compared_classes(const Tile<float>& pred, int n, int radius) {
  const int side = n + 2 * radius;
  std::vector<int> cls(size_t(side) * size_t(side));
  for (int r = -radius; r < n + radius; ++r)
    for (int c = -radius; c < n + radius; ++c) {
      const float p = pred.at(c, r);
      cls[size_t(r + radius) * size_t(side) + size_t(c + radius)] = std::isnan(p) ? -1 : int(p);
    }
  return majority_filter(cls, n, radius);
}

class Assess : public ReduceOperator {
 public:
  const OperatorSpec& spec() const override { return spec_; }

  json map(const CellContext& ctx, const CellData& data) const override {
    const Tile<float>& obs = data.input("classes");
    const Tile<float>& pred = data.input("predicted");
    const bool colour = data.inputs.count("rgb") && data.inputs.count("synthesized");
    const Tile<float>* own =
        data.inputs.count("colour_classes") ? &data.inputs.at("colour_classes") : nullptr;
    const int n = ctx.tile_size;
    std::map<std::string, uint64_t> confusion;
    double de = 0;
    uint64_t de_n = 0;
    json moments = json::object();  // class -> {"image": moments, "texture": moments}
    Tile<float> scene;              // the image, its illumination removed when asked
    std::vector<std::array<double, 3>> a, b;
    // Only the colour comparison needs the illumination (a kappa-only assessment takes no
    // hillshade).
    const auto light = colour ? illumination_of(*ctx.params, data, "texture.assess") : std::nullopt;
    const double lit_cos = colour ? colour_incidence(*ctx.params, light, "texture.assess") : 0;
    if (colour) {
      scene = data.inputs.at("rgb");
      if (light)
        for (int r = -kBlur; r < n + kBlur; ++r)
          for (int c = -kBlur; c < n + kBlur; ++c) {
            const auto x =
                light->corrected({scene.at(c, r, 0), scene.at(c, r, 1), scene.at(c, r, 2)}, c, r);
            for (int k = 0; k < 3; ++k) scene.at(c, r, k) = x[size_t(k)];
          }
      a = blurred(scene, n), b = blurred(data.inputs.at("synthesized"), n);
    }
    const auto pixel = [](const Tile<float>& t, int c, int r) {
      return std::array<float, 3>{t.at(c, r, 0), t.at(c, r, 1), t.at(c, r, 2)};
    };
    const auto known = [](const std::array<float, 3>& x) {
      return !std::isnan(x[0]) && !std::isnan(x[1]) && !std::isnan(x[2]);
    };
    const int radius = ctx.params->at("predicted_majority_radius").get<int>();
    if (pred.halo() < radius)
      throw Error("texture.assess: inputs.predicted: halo " + std::to_string(pred.halo()) +
                  " is narrower than params.predicted_majority_radius " + std::to_string(radius));
    const std::vector<int> compared = compared_classes(pred, n, radius);
    std::map<std::string, uint64_t> unfiltered;  // with the filter: the classes as rendered
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < n; ++c) {
        const float o = obs.at(c, r), p = pred.at(c, r);
        if (!std::isnan(o)) {
          const std::string observed = std::to_string(int(o)) + ",";
          ++confusion[observed + std::to_string(compared[size_t(r) * size_t(n) + size_t(c)])];
          if (radius > 0) ++unfiltered[observed + (std::isnan(p) ? "-1" : std::to_string(int(p)))];
        }
        if (!colour) continue;
        const auto& u = a[size_t(r) * size_t(n) + size_t(c)];
        const auto& v = b[size_t(r) * size_t(n) + size_t(c)];
        const auto as_float = [](const std::array<double, 3>& x) {
          return std::array<float, 3>{float(x[0]), float(x[1]), float(x[2])};
        };
        // A class's colour from all its pixels ("image") and, when colour_min_incidence_cos is
        // set, from its lit pixels as texture.fit takes them ("image_lit": the albedo where the
        // correction holds); after the blur from all of them (the blur mixes lit and shaded
        // neighbours anyway).
        if (const auto x = pixel(scene, c, r);
            !std::isnan(o) && known(x) && (!own || own->at(c, r) == o)) {
          add_moments(moments[std::to_string(int(o))]["image"], x);
          if (light && lit_cos > 0 && light->lit(c, r, lit_cos))
            add_moments(moments[std::to_string(int(o))]["image_lit"], x);
          if (known(as_float(u)))
            add_moments(moments[std::to_string(int(o))]["image_blurred"], as_float(u));
        }
        if (const auto x = pixel(data.inputs.at("synthesized"), c, r); !std::isnan(p) && known(x)) {
          add_moments(moments[std::to_string(int(p))]["texture"], x);
          if (known(as_float(v)))
            add_moments(moments[std::to_string(int(p))]["texture_blurred"], as_float(v));
        }
        if (std::isnan(u[0] + u[1] + u[2] + v[0] + v[1] + v[2])) continue;
        de += ciede2000(srgb_to_lab(u[0], u[1], u[2]), srgb_to_lab(v[0], v[1], v[2]));
        ++de_n;
      }
    if (confusion.empty() && de_n == 0) return nullptr;
    json out = {{"confusion", confusion}, {"de_sum", de}, {"de_n", de_n}, {"moments", moments}};
    if (radius > 0) out["confusion_unfiltered"] = unfiltered;
    return out;
  }

  json merge(const json& a, const json& b) const override {
    if (a.is_null()) return b;
    if (b.is_null()) return a;
    json out = a;
    for (const char* counts : {"confusion", "confusion_unfiltered"}) {
      if (!b.contains(counts)) continue;
      for (const auto& [k, n] : b.at(counts).items())
        out[counts][k] = out[counts].value(k, uint64_t(0)) + n.get<uint64_t>();
    }
    out["de_sum"] = a["de_sum"].get<double>() + b["de_sum"].get<double>();
    out["de_n"] = a["de_n"].get<uint64_t>() + b["de_n"].get<uint64_t>();
    for (const auto& [k, sets] : b.at("moments").items())
      for (const auto& [which, m] : sets.items()) {
        json& o = out["moments"][k][which];
        if (o.is_null()) o = std::vector<double>(7, 0.0);
        for (size_t i = 0; i < 7; ++i) o[i] = o[i].get<double>() + m[i].get<double>();
      }
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
