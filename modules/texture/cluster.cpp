// texture.cluster (reduce): the hue-saturation histogram of an image (grey pixels given a hue,
// paper 5.2.1) and k classes found in it by deterministic k-means; the artifact's "centres" are
// the "centres" parameter of texture.classify.
#include <algorithm>
#include <fstream>

#include "core/error.h"
#include "kmeans.h"
#include "operators.h"

namespace maquette::texture {
namespace {

OperatorSpec cluster_spec() {
  OperatorSpec s;
  s.name = "texture.cluster";
  s.description =
      "Hue-saturation histogram of an RGB image and k surface-type clusters by deterministic "
      "k-means (centres for texture.classify)";
  s.kind = OperatorKind::Reduce;
  s.inputs = {{"rgb", "RGB image, 0..255", false}};
  s.outputs = {
      {"clusters", "centres and histogram (JSON)", DType::U8, 1, Semantics::Continuous, "", {}}};
  s.params_schema = {{"type", "object"},
                     {"additionalProperties", false},
                     {"required", {"k"}},
                     {"properties",
                      {{"k", {{"type", "integer"}, {"minimum", 1}, {"maximum", 32}}},
                       {"out",
                        {{"type", "string"},
                         {"default", ""},
                         {"description", "also write the result to this file"}}}}}};
  s.params_schema["properties"].update(grey_params_schema());
  return s;
}

class ClusterOp : public ReduceOperator {
 public:
  const OperatorSpec& spec() const override { return spec_; }

  json map(const CellContext& ctx, const CellData& data) const override {
    const HsClassifier grey = HsClassifier::from_params(*ctx.params);
    const Tile<float>& rgb = data.input("rgb");
    if (rgb.channels() != 3)
      throw Error("texture.cluster: inputs.rgb: expected 3 channels, got " +
                  std::to_string(rgb.channels()));
    std::vector<uint64_t> hist(size_t(kHueBins * kSatBins), 0);
    bool any = false;
    for (int r = 0; r < ctx.tile_size; ++r)
      for (int c = 0; c < ctx.tile_size; ++c) {
        const float R = rgb.at(c, r, 0), G = rgb.at(c, r, 1), B = rgb.at(c, r, 2);
        if (std::isnan(R) || std::isnan(G) || std::isnan(B)) continue;
        ++hist[size_t(hs_bin(grey.hsv(R, G, B)))];
        any = true;
      }
    return any ? json(hist) : json();
  }

  json merge(const json& a, const json& b) const override {
    if (a.is_null()) return b;
    if (b.is_null()) return a;
    json out = a;
    for (size_t i = 0; i < b.size(); ++i) out[i] = a[i].get<uint64_t>() + b[i].get<uint64_t>();
    return out;
  }

  Artifact finish(const json& merged, const StepContext& ctx) const override {
    const json& params = *ctx.params;
    if (merged.is_null()) throw Error("texture.cluster: no RGB pixel in the region");
    const std::vector<uint64_t> hist = merged.get<std::vector<uint64_t>>();
    json centres = json::array();
    for (const auto& c : kmeans(hist, params.at("k").get<int>()))
      centres.push_back({{"id", c.centre.id},
                         {"hue", c.centre.hue},
                         {"saturation", c.centre.saturation},
                         {"pixels", c.pixels}});
    const json doc = {
        {"centres", centres},
        {"histogram", {{"hue_bins", kHueBins}, {"saturation_bins", kSatBins}, {"counts", hist}}}};
    const std::string text = doc.dump();
    if (const std::string out = params.at("out"); !out.empty()) {
      std::ofstream file(out);
      if (!(file << text << '\n'))
        throw Error("texture.cluster: params.out: cannot write '" + out + "'");
    }
    Artifact a;
    a.name = "clusters";
    a.data.resize(text.size());
    std::transform(text.begin(), text.end(), a.data.begin(), [](char ch) { return std::byte(ch); });
    a.metadata = {{"k", centres.size()}};
    return a;
  }

 private:
  OperatorSpec spec_ = cluster_spec();
};

}  // namespace

std::unique_ptr<Operator> make_cluster() { return std::make_unique<ClusterOp>(); }

}  // namespace maquette::texture
