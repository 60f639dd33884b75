// synthesis.transfer: paper 000's transfer of a painting onto the store's land cover (and
// altitude), cell by cell, seamless: synthesis.h over each output tile's global pixels.
#include <cmath>
#include <map>

#include "core/error.h"
#include "operators.h"
#include "runtime/input_halo.h"
#include "synthesis.h"
#include "transfer_exemplar.h"

namespace maquette::synthesis {
namespace {

OperatorSpec transfer_spec() {
  OperatorSpec s;
  s.name = "synthesis.transfer";
  s.description =
      "Paints the land cover with pieces of a painting (paper 000; Lefebvre & Hoppe 2005 "
      "parallel synthesis guided by land cover and altitude): colours and source coordinates";
  s.inputs = {{"landcover", "target land-cover classes (categorical)", false},
              {"dem", "elevation in metres, the altitude guide (with altitude_range)", true}};
  s.outputs = {
      {"rgb", "the painting's colours", DType::U8, 3, Semantics::Continuous, "", 0.0},
      {"source", "painting pixel (column, row) each output pixel was copied from", DType::F32, 2,
       Semantics::Continuous, "px", std::nullopt},  // NaN where the land cover has no data
  };
  // In input pixels: the output's synthesis_halo() at refine 0, less at finer outputs.
  s.halo = synthesis_halo();
  s.refinable = true;
  s.writes_all_samples = true;
  const auto weight = [](double fallback) {
    return json{{"type", "number"}, {"minimum", 0}, {"default", fallback}};
  };
  s.params_schema = {
      {"type", "object"},
      {"additionalProperties", false},
      {"required", {"painting", "landcover_classes"}},
      {"properties",
       {{"painting",
         {{"type", "string"},
          {"description", "the painting (8-bit image; relative to the working directory)"}}},
        {"labels",
         {{"type", "string"},
          {"description",
           "hand-drawn class image (one 8-bit band, the painting's size, classes 0..254); else "
           "classes by colour"}}},
        {"classes",
         {{"type", "integer"},
          {"minimum", 1},
          {"maximum", 254},
          {"default", 6},
          {"description", "k of the automatic segmentation by colour (k-means in CIELAB)"}}},
        {"exclusion",
         {{"type", "string"},
          {"description", "mask of the painting never copied (non-zero: excluded)"}}},
        {"exclude_classes",
         {{"type", "array"},
          {"items", {{"type", "integer"}, {"minimum", 0}, {"maximum", 254}}},
          {"default", json::array()},
          {"description", "painting classes never copied (sky, frame)"}}},
        {"landcover_classes",
         {{"type", "object"},
          {"description",
           "target land-cover value (a string key) -> painting class; other values match any "
           "class"}}},
        {"altitude_range",
         {{"type", "array"},
          {"items", {{"type", "number"}}},
          {"description", "[low, high] metres of the DEM mapped to altitude 0..1"}}},
        {"painting_altitude",
         {{"type", "string"},
          {"description",
           "the painting's altitude: a grey image (its size), or \"rows\" (high at the top)"}}},
        {"exemplar_scale",
         {{"type", "integer"},
          {"enum", {1, 2, 4, 8}},
          {"default", 2},
          {"description", "painting pixels per exemplar pixel (a side): coarser strokes, faster"}}},
        {"k",
         {{"type", "integer"},
          {"minimum", 1},
          {"maximum", 8},
          {"default", 2},
          {"description", "k-coherence candidates per neighbour"}}},
        {"w_label", weight(2.0)},
        {"w_altitude", weight(1.0)},
        {"w_repetition", weight(0.3)},
        {"coherence", weight(0.5)},
        {"jitter", {{"type", "integer"}, {"minimum", 0}, {"maximum", 4}, {"default", 1}}},
        {"seed", {{"type", "integer"}, {"minimum", 0}, {"default", 0}}}}}};
  return s;
}

// Target class value -> painting class.
std::map<int, uint8_t> class_table(const json& table, const std::string& op) {
  std::map<int, uint8_t> out;
  for (const auto& [key, value] : table.items()) {
    int target = 0;
    size_t used = 0;
    try {
      target = std::stoi(key, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != key.size() || key.empty())
      throw Error(op + ".landcover_classes: key '" + key + "' is not an integer class value");
    if (!value.is_number_integer() || value.get<int>() < 0 || value.get<int>() >= kUnknownLabel)
      throw Error(op + ".landcover_classes." + key + ": " + value.dump() +
                  " is not a painting class 0..254");
    out[target] = uint8_t(value.get<int>());
  }
  return out;
}

class Transfer : public CellOperator {
 public:
  const OperatorSpec& spec() const override { return spec_; }

  void run(const CellContext& ctx, CellData& data) const override {
    const json& params = *ctx.params;
    const auto table = class_table(params.at("landcover_classes"), spec_.name);
    const auto exemplar = transfer_exemplar(params);
    const Tile<float>& landcover = input_with_halo(spec_.name, ctx, data, "landcover", spec_.halo);
    const int halo = landcover.halo(), side = landcover.stride();

    TargetGuides guides;
    guides.rect = {global_col(ctx.cell, ctx.tile_size, -halo),
                   global_row(ctx.cell, ctx.tile_size, -halo), side, side};
    guides.shift = ctx.refine;
    guides.labels.resize(size_t(side) * size_t(side));
    for (int r = 0; r < side; ++r)
      for (int c = 0; c < side; ++c) {
        const float v = landcover.at(c - halo, r - halo);
        const auto it = std::isnan(v) ? table.end() : table.find(int(std::lround(v)));
        guides.labels[size_t(r) * size_t(side) + size_t(c)] =
            it == table.end() ? kUnknownLabel : it->second;
      }
    if (params.contains("altitude_range") && data.inputs.count("dem")) {
      const auto range = params.at("altitude_range").get<std::vector<double>>();
      if (range.size() != 2 || !(range[1] > range[0]))
        throw Error(spec_.name + ".altitude_range: expected [low, high] with high > low, got " +
                    params.at("altitude_range").dump());
      const Tile<float>& dem = input_with_halo(spec_.name, ctx, data, "dem", spec_.halo);
      guides.altitude.resize(guides.labels.size());
      for (int r = 0; r < side; ++r)
        for (int c = 0; c < side; ++c)
          guides.altitude[size_t(r) * size_t(side) + size_t(c)] = float(std::clamp(
              (double(dem.at(c - halo, r - halo)) - range[0]) / (range[1] - range[0]), 0.0, 1.0));
    }

    SynthesisParams sp;
    sp.w_label = params.at("w_label").get<double>();
    sp.w_altitude = params.at("w_altitude").get<double>();
    sp.w_repetition = params.at("w_repetition").get<double>();
    sp.coherence = params.at("coherence").get<double>();
    sp.jitter = params.at("jitter").get<int>();
    sp.seed = params.at("seed").get<uint64_t>();
    const int n = ctx.tile_size << ctx.refine;
    const PixelRect out{global_col(ctx.cell, n, 0), global_row(ctx.cell, n, 0), n, n};
    const std::vector<int32_t> src = synthesize(exemplar->pyramid, guides, sp, out);

    const ExemplarLevel& e = exemplar->pyramid.levels[0];
    const auto target = [&](const char* port, int channels) -> Tile<float>* {
      if (!data.wants(port)) return nullptr;
      Tile<float>& t = data.output(port);
      if (t.size() != n || t.channels() != channels || t.halo() != 0)
        t = Tile<float>::uninitialized(n, channels);
      return &t;
    };
    Tile<float>* rgb = target("rgb", 3);
    Tile<float>* source = target("source", 2);
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < n; ++c) {
        // Where the land cover has no data the output has none either (its nodata).
        if (std::isnan(landcover.at(c >> ctx.refine, r >> ctx.refine))) {
          for (int k = 0; k < 3 && rgb; ++k) rgb->at(c, r, k) = NAN;
          for (int k = 0; k < 2 && source; ++k) source->at(c, r, k) = NAN;
          continue;
        }
        const size_t s = size_t(src[size_t(r) * size_t(n) + size_t(c)]);
        if (rgb)
          for (int k = 0; k < 3; ++k)
            rgb->at(c, r, k) = std::round(e.rgb[3 * s + size_t(k)] * 255.0f);
        if (source) {
          source->at(c, r, 0) = float(int(s) % e.width * exemplar->scale);
          source->at(c, r, 1) = float(int(s) / e.width * exemplar->scale);
        }
      }
  }

 private:
  OperatorSpec spec_ = transfer_spec();
};

}  // namespace

std::unique_ptr<Operator> make_transfer() { return std::make_unique<Transfer>(); }

}  // namespace maquette::synthesis
