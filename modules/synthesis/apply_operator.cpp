// synthesis.apply: a transfer's source map applied to other images of its paintings
// (apply_sources.h), cell by cell.
#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <set>

#include "apply_sources.h"
#include "core/error.h"
#include "exemplar.h"
#include "operators.h"
#include "painting.h"
#include "transfer_params.h"

namespace maquette::synthesis {
namespace {

constexpr const char* kOp = "synthesis.apply";

OperatorSpec apply_spec() {
  OperatorSpec s;
  s.name = kOp;
  s.description =
      "Applies a synthesis.transfer's source map to other images of its paintings (ebsynth's "
      "\"repeat\"): each pixel takes an image's value where its colour was copied from";
  InputSpec source{"source",
                   "the transfer's source: painting pixel (column, row) per output pixel, and its "
                   "painting",
                   false};
  source.channels = {3};
  s.inputs = {source};
  s.outputs = {
      {"rgb",
       "the images' colours at the sources, as the transfer's (0 is nodata: a channel at 0 is "
       "written 1)",
       DType::U8, 3, Semantics::Continuous, "", 0.0},
      {"value", "the one-band images' values at the sources: each block's mean", DType::F32, 1,
       Semantics::Continuous, "", std::nullopt},
      {"classes",
       "the one-band images' classes at the sources: each block's most frequent (65535: none)",
       DType::U16, 1, Semantics::Categorical, "", 65535.0}};
  s.writes_all_samples = true;
  s.params_schema = {
      {"type", "object"},
      {"additionalProperties", false},
      {"required", {"images"}},
      {"properties",
       {{"images",
         {{"type", "array"},
          {"minItems", 1},
          {"items", {{"type", "string"}}},
          {"description",
           "one image per painting, each of its painting's size: the transfer's painting first, "
           "then each of its exemplars (colours for rgb, one band for value and classes)"}}},
        {"exemplar_scale",
         {{"type", "integer"},
          {"enum", {1, 2, 4, 8}},
          {"description",
           "painting pixels per source block: the transfer's (by default the one recorded with "
           "the source layer, else 2)"}}}}}};
  s.check_params = [](const json& params, const std::set<std::string>&) {
    const auto& images = params.at("images");
    for (size_t i = 0; i < images.size(); ++i)
      require_file(images[i].get<std::string>(), "params.images[" + std::to_string(i) + "]");
  };
  return s;
}

// The exemplar_scale the sources were made at: the params', which must be that of the
// synthesis.transfer that made the source layer when its provenance says; else the transfer's, or
// 2 (the transfer's default). Throws maquette::Error when the two differ, or when the images are
// not one per painting of that transfer.
int source_scale(const CellContext& ctx) {
  const json& params = *ctx.params;
  const LayerInfo& layer = ctx.input_layer("source");
  const auto transfer = transfer_params_of(layer);
  if (!transfer) return params.value("exemplar_scale", 2);
  const int made = transfer->at("exemplar_scale").get<int>();
  if (params.contains("exemplar_scale") && params.at("exemplar_scale").get<int>() != made)
    throw Error(std::string(kOp) + ".exemplar_scale " + params.at("exemplar_scale").dump() +
                ": the source layer '" + layer.name + "' was made by synthesis.transfer at " +
                "exemplar_scale " + std::to_string(made) + ": give " + std::to_string(made) +
                " or leave exemplar_scale out");
  const size_t paintings = 1 + transfer->value("exemplars", json::array()).size();
  if (const size_t images = params.at("images").size(); images != paintings)
    throw Error(std::string(kOp) + ".images: " + std::to_string(images) + " for the " +
                std::to_string(paintings) + " painting(s) of the synthesis.transfer that made '" +
                layer.name +
                "': give one image per painting, its painting first, then one per "
                "exemplar in order");
  return made;
}

// How an output port reads the images: colours, or one band's block means or modes.
enum class Reading { Colours, Means, Modes };

// Each set of images read and shrunk once per process for each reading, shared by the cells.
std::shared_ptr<const std::vector<SourceImage>> source_images(const json& params, int scale,
                                                              Reading reading) {
  static std::mutex mutex;
  static std::map<std::string, std::shared_ptr<const std::vector<SourceImage>>> cache;
  const std::string key = params.at("images").dump() + " at " + std::to_string(scale) + " as " +
                          std::to_string(int(reading));
  const std::lock_guard lock(mutex);
  auto& slot = cache[key];
  if (!slot) {
    auto images = std::make_shared<std::vector<SourceImage>>();
    for (const auto& item : params.at("images")) {
      const std::string path = item.get<std::string>();
      images->push_back(reading == Reading::Colours ? colour_image(path, scale)
                        : reading == Reading::Means ? value_image(path, scale, BlockValue::Mean)
                                                    : value_image(path, scale, BlockValue::Mode));
    }
    slot = images;
  }
  return slot;
}

class Apply : public CellOperator {
 public:
  const OperatorSpec& spec() const override { return spec_; }

  void run(const CellContext& ctx, CellData& data) const override {
    const Tile<float>& source = data.input("source");
    const int n = source.size(), scale = source_scale(ctx);
    const auto fill = [&](const char* port, Reading reading, const auto& value_of) {
      if (!data.wants(port)) return;
      const int channels = reading == Reading::Colours ? 3 : 1;
      Tile<float>& out = data.output(port);
      if (out.size() != n || out.channels() != channels || out.halo() != 0)
        out = Tile<float>::uninitialized(n, channels);
      const auto images = source_images(*ctx.params, scale, reading);
      float block[3];
      for (int r = 0; r < n; ++r)
        for (int c = 0; c < n; ++c) {
          const float col = source.at(c, r, 0), row = source.at(c, r, 1);
          const float painting = source.at(c, r, 2);
          if (std::isnan(col) || std::isnan(row) || std::isnan(painting)) {
            for (int k = 0; k < channels; ++k) out.at(c, r, k) = NAN;  // no source: nodata
            continue;
          }
          try {
            block_at(*images, col, row, painting, block);
          } catch (const Error& e) {
            throw Error(std::string(kOp) + ": inputs.source of cell " + ctx.cell.ToText() + ": " +
                        e.what());
          }
          for (int k = 0; k < channels; ++k) out.at(c, r, k) = value_of(block[k]);
        }
    };
    // The transfer writes its level's colours, the shrunk painting's over 255: the same float
    // first, so that the same rounding gives the same byte.
    fill("rgb", Reading::Colours, [](float v) { return colour_byte(v / 255.0f); });
    fill("value", Reading::Means, [](float v) { return v; });
    fill("classes", Reading::Modes, [&](float v) {
      if (!std::isnan(v) && !(v >= 0 && v < 65535 && v == std::floor(v)))
        throw Error(std::string(kOp) + ": outputs.classes: the images hold " + std::to_string(v) +
                    ", not a class (a whole number 0 .. 65534): map such an image to value");
      return v;
    });
  }

 private:
  OperatorSpec spec_ = apply_spec();
};

}  // namespace

std::unique_ptr<Operator> make_apply() { return std::make_unique<Apply>(); }

}  // namespace maquette::synthesis
