// texture.fit (reduce): per class and quantity, 256-bin histograms over the quantity's range
// (paper 5.2.3), merged in cell-id order; finished into a model document (hierarchy.h).
#include <algorithm>
#include <cmath>

#include "calibration.h"
#include "core/error.h"
#include "core/output_file.h"
#include "fit_inputs.h"
#include "hierarchy.h"
#include "illumination.h"
#include "operators.h"
#include "runtime/params_schema.h"

namespace maquette::texture {
namespace {

const char* kOp = "texture.fit";

std::vector<Quantity> quantities(const json& params) {
  std::vector<Quantity> out;
  const json& ranges = params.at("ranges");
  for (const std::string& name : params.at("quantities").get<std::vector<std::string>>()) {
    const std::string path = std::string(kOp) + ": params.ranges." + name;
    json r = ranges.contains(name)  ? ranges.at(name)
             : name == "slope"      ? json{0, 90}
             : is_categorical(name) ? json{kCategoricalLo, kCategoricalHi}
                                    : json();
    if (r.is_null()) throw Error(path + ": missing (give [lo, hi] of the region's values)");
    if (!r.is_array() || r.size() != 2 || !r[0].is_number() || !r[1].is_number() ||
        !(r[1].get<double>() > r[0].get<double>()))
      throw Error(path + ": expected [lo, hi] with lo < hi, got " + r.dump());
    if (is_categorical(name) && r != json{kCategoricalLo, kCategoricalHi})
      throw Error(path +
                  ": the categorical quantity has the range [-0.5, 255.5] (a bin per "
                  "code), got " +
                  r.dump());
    out.push_back({name, r[0].get<double>(), r[1].get<double>()});
  }
  return out;
}

OperatorSpec fit_spec() {
  OperatorSpec s;
  s.name = kOp;
  s.description =
      "Fits a surface-layer model to a classified image: constraint functions from per-class "
      "histograms of height, slope and any named raster; layer hierarchy of paper 001 5.2.2";
  s.kind = OperatorKind::Reduce;
  s.inputs = {{"classes", "surface types (texture.classify)", false},
              {.name = "rgb",
               .description = "the image the classes come from (layer colours)",
               .channels = {3}},
              {"dem", "elevation in metres", false},
              {"hillshade",
               "terrain.derive's hillshade at the image's sun: colours fitted on the image with "
               "its illumination removed (as texture.classify's correction)",
               true},
              {"colour_classes",
               "each pixel's own class (texture.classify without the majority filter): a class's "
               "colours from its pixels whose own class it is, not from the other types its "
               "majority filter took in",
               true}};
  for (const std::string& q : kRasterPorts)
    s.inputs.push_back({q, "raster of the quantity '" + q + "'", true});
  s.outputs = {{"model", "model document (JSON)", DType::U8, 1, Semantics::Continuous, "", {}}};
  s.halo = kInputHalo;
  s.params_schema = {
      {"type", "object"},
      {"additionalProperties", false},
      {"required", {"ranges"}},
      {"properties",
       {{"quantities",
         {{"type", "array"},
          {"items",
           {{"type", "string"},
            {"enum",
             {"height", "slope", "temperature", "rainfall", "radiation", "extra", "landcover"}}}},
          {"default", {"height", "slope"}}}},
        {"ranges",
         {{"type", "object"},
          {"description",
           "quantity -> [lo, hi]: its values are scaled to [0, 1) over this (landcover: "
           "[-0.5, 255.5], a bin per code)"}}},
        {"classes",
         {{"type", "array"},
          {"items", {{"type", "integer"}, {"minimum", 0}, {"maximum", 254}}},
          {"default", json::array()},
          {"description", "classes that must have pixels (others found are fitted too)"}}},
        {"noise_scale", {{"type", "number"}, {"default", 0.1}}},
        {"noise_wavelength_m", {{"type", "number"}, {"minimum", 0.001}, {"default", 200}}},
        {"noise_octaves", {{"type", "integer"}, {"minimum", 1}, {"maximum", 12}, {"default", 3}}},
        {"noise_persistence",
         number_param(0.05, 1, 0.5,
                      "amplitude ratio between successive octaves of the level-1 and variation "
                      "noise (larger: more of the variation at finer scales)")},
        {"variation",
         {{"type", "boolean"},
          {"default", true},
          {"description",
           "each class drawn between two colours on its principal colour axis, mixed by a "
           "noise child, with the class's mean and standard deviation along that axis"}}},
        {"variation_noise_scale",
         number_param(0.01, 10, 1.5, "noise scale of the variation child's coverage")},
        {"seed", {{"type", "integer"}, {"minimum", 0}, {"default", 1}}},
        {"constraints",
         {{"type", "string"},
          {"enum", {"density", "odds"}},
          {"default", "density"},
          {"description",
           "constraint functions: the class histogram scaled to mean 0.5 (paper 5.2.3), or the "
           "class's odds per bin scaled to a maximum of 1 (prior-aware)"}}},
        {"calibrate",
         {{"type", "boolean"},
          {"default", false},
          {"description",
           "choose level-1 biases so that each class dominates as much land as it is observed "
           "on (calibration.h)"}}},
        {"coverage_power",
         number_param(1, 16, 1,
                      "level-1 tables raised to this power, biases adjusted so that the same "
                      "pixels reach coverage 0.5: sharper class edges (calibration.h)")},
        {"sample_step",
         integer_param(1, 64, 4, "calibration sample: every n-th pixel of every n-th row")},
        {"out", named_param(NamedKind::OutputFile, "",
                            "also write the model document to this file (for model_file)")}}}};
  s.params_schema["properties"].update(illumination_params_schema());
  s.check_params = [](const json& p, const std::set<std::string>& mapped) {
    quantities(p);
    check_quantity_inputs(p.at("quantities").get<std::vector<std::string>>(), mapped, kOp);
    check_illumination_params(p, mapped.count("hillshade") > 0, kOp);
  };
  s.params_schema["properties"].update(colour_incidence_param());
  return s;
}

int bin(float v, const Quantity& q) {
  return std::clamp(int(std::floor((v - q.lo) / (q.hi - q.lo) * kBins)), 0, kBins - 1);
}

class Fit : public ReduceOperator {
 public:
  const OperatorSpec& spec() const override { return spec_; }

  // Partial: {"<class>": {"n": pixels, "colour_n": pixels of the colour sums, "pixel_m": the
  // level's pixel size, "sum": [3], "sum_sq": [3], "sum_cross": [RG, RB, GB], "hist": [[256] per
  // quantity], "sample": [bins of the calibration sample's pixels, one per quantity, pixel after
  // pixel]}}.
  json map(const CellContext& ctx, const CellData& data) const override {
    const std::vector<Quantity> qs = quantities(*ctx.params);
    std::vector<std::string> names;
    for (const Quantity& q : qs) names.push_back(q.name);
    const std::vector<Plane> planes = quantity_planes(ctx, data, names, kOp);
    const Tile<float>& cls = data.input("classes");
    const Tile<float>& rgb = data.input("rgb");
    const Tile<float>* own =
        data.inputs.count("colour_classes") ? &data.inputs.at("colour_classes") : nullptr;
    const std::optional<Illumination> light = illumination_of(*ctx.params, data, kOp);
    const double lit_cos = colour_incidence(*ctx.params, light, kOp);
    std::map<int, ClassStats> stats;
    std::map<int, std::vector<int>> sample;
    const int step =
        ctx.params->at("calibrate").get<bool>() ? ctx.params->at("sample_step").get<int>() : 0;
    for (int r = 0; r < ctx.tile_size; ++r)
      for (int c = 0; c < ctx.tile_size; ++c) {
        const float k = cls.at(c, r);
        if (std::isnan(k) || std::isnan(rgb.at(c, r, 0))) continue;
        bool valid = true;
        for (const Plane& p : planes) valid = valid && !std::isnan(p.at(c, r));
        if (!valid) continue;  // a pixel counts only with every quantity known
        ClassStats& s = stats[int(k)];
        if (s.hist.empty()) s.hist.resize(qs.size(), {});
        ++s.pixels;
        const bool colour = (!own || own->at(c, r) == k) && (!light || light->lit(c, r, lit_cos));
        std::array<float, 3> x = {rgb.at(c, r, 0), rgb.at(c, r, 1), rgb.at(c, r, 2)};
        if (light) x = light->corrected(x, c, r);
        s.colour_pixels += colour;
        for (size_t ch = 0; ch < 3 && colour; ++ch) {
          const double v = x[ch];
          s.sum[ch] += v, s.sum_sq[ch] += v * v;
          s.sum_cross[ch] += double(x[kCrossPairs[ch][0]]) * double(x[kCrossPairs[ch][1]]);
        }
        const bool sampled = step > 0 && r % step == 0 && c % step == 0;
        for (size_t q = 0; q < qs.size(); ++q) {
          const int b = bin(planes[q].at(c, r), qs[q]);
          ++s.hist[q][size_t(b)];
          if (sampled) sample[int(k)].push_back(b);
        }
      }
    if (stats.empty()) return nullptr;
    const double pixel_m = ctx.grid->level_info(ctx.cell.level(), ctx.tile_size).pixel_m;
    json out = json::object();
    for (const auto& [id, s] : stats)
      out[std::to_string(id)] = {{"n", s.pixels},      {"colour_n", s.colour_pixels},
                                 {"pixel_m", pixel_m}, {"sum", s.sum},
                                 {"sum_sq", s.sum_sq}, {"sum_cross", s.sum_cross},
                                 {"hist", s.hist},     {"sample", sample[id]}};
    return out;
  }

  json merge(const json& a, const json& b) const override {
    if (a.is_null()) return b;
    if (b.is_null()) return a;
    json out = a;
    for (const auto& [id, s] : b.items()) {
      if (!out.contains(id)) {
        out[id] = s;
        continue;
      }
      json& o = out[id];
      o["n"] = o["n"].get<uint64_t>() + s["n"].get<uint64_t>();
      o["colour_n"] = o["colour_n"].get<uint64_t>() + s["colour_n"].get<uint64_t>();
      for (size_t ch = 0; ch < 3; ++ch) {
        o["sum"][ch] = o["sum"][ch].get<double>() + s["sum"][ch].get<double>();
        o["sum_sq"][ch] = o["sum_sq"][ch].get<double>() + s["sum_sq"][ch].get<double>();
        o["sum_cross"][ch] = o["sum_cross"][ch].get<double>() + s["sum_cross"][ch].get<double>();
      }
      for (const json& b : s.at("sample")) o["sample"].push_back(b);
      for (size_t q = 0; q < s["hist"].size(); ++q)
        for (size_t i = 0; i < size_t(kBins); ++i)
          o["hist"][q][i] = o["hist"][q][i].get<uint64_t>() + s["hist"][q][i].get<uint64_t>();
    }
    return out;
  }

  Artifact finish(const json& merged, const StepContext& ctx) const override {
    const json& params = *ctx.params;
    const std::vector<Quantity> qs = quantities(params);
    std::vector<ClassStats> classes;
    std::vector<Sample> samples;
    if (!merged.is_null())
      for (const auto& [id, s] : merged.items()) {
        ClassStats c;
        c.id = std::stoi(id);
        c.pixels = s.at("n").get<uint64_t>();
        c.colour_pixels = s.at("colour_n").get<uint64_t>();
        if (c.colour_pixels == 0)
          throw Error(std::string(kOp) + ": class " + id +
                      ": no pixel whose own class (inputs.colour_classes) it is" +
                      (params.at("colour_min_incidence_cos").get<double>() > 0
                           ? ", lit at params.colour_min_incidence_cos"
                           : "") +
                      ": no colour");
        c.sum = s.at("sum").get<std::array<double, 3>>();
        c.sum_sq = s.at("sum_sq").get<std::array<double, 3>>();
        c.sum_cross = s.at("sum_cross").get<std::array<double, 3>>();
        c.hist = s.at("hist").get<std::vector<std::array<uint64_t, kBins>>>();
        const std::vector<uint8_t> bins = s.at("sample").get<std::vector<uint8_t>>();
        for (size_t i = 0; i + qs.size() <= bins.size(); i += qs.size())
          samples.push_back(
              {c.id, std::vector<uint8_t>(bins.begin() + std::ptrdiff_t(i),
                                          bins.begin() + std::ptrdiff_t(i + qs.size()))});
        classes.push_back(std::move(c));
      }
    std::sort(classes.begin(), classes.end(), [](auto& a, auto& b) { return a.id < b.id; });
    for (const int id : params.at("classes").get<std::vector<int>>())
      if (std::none_of(classes.begin(), classes.end(), [&](auto& c) { return c.id == id; }))
        throw Error(std::string(kOp) + ": params.classes: class " + std::to_string(id) +
                    " has no pixels with every quantity known");
    if (classes.empty())
      throw Error(std::string(kOp) +
                  ": no classified pixel with every quantity known in the region (inputs.classes "
                  "empty, or the quantities missing)");
    HierarchyParams h;
    h.noise_scale = params.at("noise_scale").get<double>();
    h.noise.wavelength_m = params.at("noise_wavelength_m").get<double>();
    h.noise.octaves = params.at("noise_octaves").get<int>();
    h.noise.persistence = params.at("noise_persistence").get<double>();
    h.variation = params.at("variation").get<bool>();
    h.variation_noise_scale = params.at("variation_noise_scale").get<double>();
    h.pixel_m = merged.is_null() ? 0 : merged.begin()->value("pixel_m", 0.0);
    h.seed = params.at("seed").get<uint64_t>();
    h.odds = params.at("constraints").get<std::string>() == "odds";
    Model model = build_model(qs, classes, h);
    if (params.at("calibrate").get<bool>()) calibrate_biases(model, samples);
    sharpen_coverage(model, params.at("coverage_power").get<double>());
    json doc = model_to_json(model);
    json summary = json::array();
    for (const ClassStats& c : classes) summary.push_back({{"class", c.id}, {"pixels", c.pixels}});
    doc["fitted_classes"] = summary;
    const std::string text = doc.dump(1);
    if (const std::string out = params.at("out"); !out.empty()) {
      try {
        write_file_whole(out, text + '\n');  // whole or not at all
      } catch (const Error& e) {
        throw Error(std::string(kOp) + ": params.out: " + e.what());
      }
    }
    return Artifact::FromText(
        "model", text,
        {{"format", doc["format"]}, {"version", doc["version"]}, {"classes", summary}});
  }

 private:
  OperatorSpec spec_ = fit_spec();
};

}  // namespace

std::unique_ptr<Operator> make_fit() { return std::make_unique<Fit>(); }

}  // namespace maquette::texture
