// texture.cluster (reduce): the colour histogram of an image (hue x saturation, or x value; grey
// pixels given a hue, paper 5.2.1; or CIELAB), surface-type clusters found in it (k-means or a
// Gaussian mixture, k given or chosen; colour_clusters.h) and optionally its density plot as a PNG.
// The artifact's "centres" are the "centres" parameter of texture.classify.
#include <algorithm>

#include "colour_clusters.h"
#include "core/error.h"
#include "core/output_file.h"
#include "hs_classes.h"
#include "hs_plot.h"
#include "illumination.h"
#include "operators.h"
#include "runtime/params_schema.h"

namespace maquette::texture {
namespace {

constexpr int kMaxK = 32;

ClusterRequest parse_request(const json& p);

OperatorSpec cluster_spec() {
  OperatorSpec s;
  s.name = "texture.cluster";
  s.description =
      "Hue-saturation(-value) or CIELAB histogram of an RGB image, surface-type clusters by "
      "deterministic "
      "k-means or Gaussian mixture with k given or chosen (centres for texture.classify), and "
      "its density plot";
  s.kind = OperatorKind::Reduce;
  s.inputs = {{.name = "rgb", .description = "RGB image, 0..255", .channels = {3}},
              {"hillshade",
               "terrain.derive's hillshade at the image's sun (illumination correction, as "
               "texture.classify's)",
               true}};
  s.outputs = {
      {"clusters", "centres and histogram (JSON)", DType::U8, 1, Semantics::Continuous, "", {}}};
  s.params_schema = {
      {"type", "object"},
      {"additionalProperties", false},
      {"required", {"k"}},
      {"properties",
       {{"k",
         {{"minimum", 1},
          {"maximum", kMaxK},
          {"description", "number of clusters, or \"auto\" to choose up to k_max"}}},
        {"k_max", integer_param(2, kMaxK, 8, "largest k tried when k is \"auto\"")},
        {"method", {{"type", "string"}, {"enum", {"kmeans", "gmm"}}, {"default", "kmeans"}}},
        {"space", {{"type", "string"}, {"enum", {"hs", "hsv", "lab"}}, {"default", "hs"}}},
        {"out", named_param(NamedKind::OutputFile, "", "also write the result to this file")},
        {"plot",
         named_param(
             NamedKind::OutputFile, "",
             "write the hue-saturation density plot to this PNG file (\"hs\", \"hsv\")")}}}};
  s.params_schema["properties"].update(grey_params_schema());
  s.params_schema["properties"].update(illumination_params_schema());
  s.check_params = [](const json& p, const std::set<std::string>& mapped) {
    check_illumination_params(p, mapped.count("hillshade") > 0, "texture.cluster");
    parse_request(p);  // k, and a plot only in "hs" or "hsv"
  };
  return s;
}

ClusterRequest parse_request(const json& p) {
  ClusterRequest r{parse_cluster_method(p.at("method").get<std::string>()),
                   parse_colour_space(p.at("space").get<std::string>()), 0,
                   p.at("k_max").get<int>()};
  if (r.space == ColourSpace::Lab && !p.at("plot").get<std::string>().empty())
    throw Error(
        "texture.cluster: params.plot: the density plot is drawn in \"hs\" or \"hsv\", "
        "not in space \"lab\"");
  if (const json& k = p.at("k"); k.is_number_integer())
    r.k = k.get<int>();
  else if (k != "auto")
    throw Error("texture.cluster: params.k: expected an integer 1.." + std::to_string(kMaxK) +
                " or \"auto\", got " + k.dump());
  return r;
}

json matrix(const Matrix& m, int dims) {
  json out = json::array();
  for (int a = 0; a < dims; ++a)
    out.push_back(std::vector<double>(m[size_t(a)].begin(), m[size_t(a)].begin() + dims));
  return out;
}

// The artifact: method, space, centres (ids in decreasing pixel count), the mixture's
// components, how k was chosen, the histogram.
json clusters_document(const ClusterRequest& request, const ColourClusters& found,
                       const std::vector<uint64_t>& histogram) {
  const bool hsv = request.space == ColourSpace::Hsv, lab = request.space == ColourSpace::Lab;
  json centres = json::array();
  for (size_t c = 0; c < found.centres.size(); ++c) {
    json centre = {{"id", c}};
    if (lab) {
      const auto x = point_lab(found.centres[c]);
      centre.update({{"L", x[0]}, {"a", x[1]}, {"b", x[2]}});
    } else {
      const Hsv x = point_colour(found.centres[c]);
      centre.update({{"hue", x.h}, {"saturation", x.s}});
      if (hsv) centre["value"] = x.v;
    }
    centre["pixels"] = found.pixels[c];
    centres.push_back(centre);
  }
  json hist = lab ? json{{"lightness_bins", kLightnessBins},
                         {"chroma_bins", kChromaBins},
                         {"chroma_range", {-kChromaLimit, kChromaLimit}}}
                  : json{{"hue_bins", kHueBins}, {"saturation_bins", kSatBins}};
  if (hsv) hist["value_bins"] = kValueBins;
  hist["counts"] = histogram;
  json doc = {{"method", request.method == ClusterMethod::Gmm ? "gmm" : "kmeans"},
              {"space", lab   ? "lab"
                        : hsv ? "hsv"
                              : "hs"},
              {"k", found.centres.size()},
              {"centres", centres},
              {"histogram", hist}};
  if (found.mixture) {
    const int dims = found.mixture->dims;
    json components = json::array();
    for (size_t c = 0; c < found.mixture->components.size(); ++c) {
      const Gaussian& g = found.mixture->components[c];
      components.push_back({{"id", c},
                            {"weight", g.weight},
                            {"mean", std::vector<double>(g.mean.begin(), g.mean.begin() + dims)},
                            {"covariance", matrix(g.covariance, dims)}});
    }
    doc["components"] = components;
    doc["log_likelihood"] = found.mixture->log_likelihood;
    doc["em_iterations"] = found.mixture->iterations;
  }
  if (!found.tried_k.empty())
    doc["selection"] = {{"criterion", found.mixture ? "bic" : "silhouette"},
                        {"k", found.tried_k},
                        {"values", found.criterion}};
  return doc;
}

class ClusterOp : public ReduceOperator {
 public:
  const OperatorSpec& spec() const override { return spec_; }

  json map(const CellContext& ctx, const CellData& data) const override {
    const ColourSpace space = parse_request(*ctx.params).space;
    const HsClassifier grey = HsClassifier::from_params(*ctx.params);
    const Tile<float>& rgb = data.input("rgb");
    if (rgb.channels() != 3)
      throw Error("texture.cluster: inputs.rgb: expected 3 channels, got " +
                  std::to_string(rgb.channels()));
    std::vector<uint64_t> hist(size_t(histogram_bins(space)), 0);
    const std::optional<Illumination> light = illumination_of(*ctx.params, data, "texture.cluster");
    bool any = false;
    for (int r = 0; r < ctx.tile_size; ++r)
      for (int c = 0; c < ctx.tile_size; ++c) {
        std::array<float, 3> x = {rgb.at(c, r, 0), rgb.at(c, r, 1), rgb.at(c, r, 2)};
        if (std::isnan(x[0]) || std::isnan(x[1]) || std::isnan(x[2])) continue;
        if (light) x = light->corrected(x, c, r);
        const int bin = space == ColourSpace::Lab ? lab_bin(srgb_to_lab(x[0], x[1], x[2]))
                                                  : colour_bin(grey.hsv(x[0], x[1], x[2]), space);
        ++hist[size_t(bin)];
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
    const ClusterRequest request = parse_request(params);
    if (merged.is_null()) throw Error("texture.cluster: no RGB pixel in the region");
    const std::vector<uint64_t> hist = merged.get<std::vector<uint64_t>>();
    const ColourClusters found = find_clusters(hist, request);
    const json doc = clusters_document(request, found, hist);
    const std::string text = doc.dump();
    if (const std::string out = params.at("out"); !out.empty()) {
      try {
        write_file_whole(out, text + '\n');  // whole or not at all
      } catch (const Error& e) {
        throw Error(std::string("texture.cluster: params.out: ") + e.what());
      }
    }
    if (const std::string plot = params.at("plot"); !plot.empty()) {
      std::vector<Hsv> marks;
      for (const Point& p : found.centres) marks.push_back(point_colour(p));
      try {
        write_hs_plot(hs_marginal(hist, request.space), marks, plot);
      } catch (const Error& e) {
        throw Error(std::string("texture.cluster: params.plot: ") + e.what());
      }
    }
    return Artifact::FromText("clusters", text, {{"k", found.centres.size()}});
  }

 private:
  OperatorSpec spec_ = cluster_spec();
};

}  // namespace

std::unique_ptr<Operator> make_cluster() { return std::make_unique<ClusterOp>(); }

}  // namespace maquette::texture
