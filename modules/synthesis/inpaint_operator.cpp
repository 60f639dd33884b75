// synthesis.inpaint (region): the samples of an image under a mask (the polygons of a features
// layer, e.g. structures.bridge's footprints, or a mask raster) filled from the rest of the image
// (inpaint.h). A region operator: a hole may span several cells, and its fill reads the whole
// region (the cells are pasted into one mosaic, filled, and cut back), with kRegionContext samples
// of context beyond the region's cells. It runs once, on one rank; inpaint() gives the same bits
// for any thread count.
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "core/error.h"
#include "inpaint.h"
#include "operators.h"
#include "patchmatch.h"
#include "region_inputs.h"

namespace maquette::synthesis {
namespace {

// Throws unless the step maps the holes' input, footprints or mask (or both).
void require_holes(bool footprints, bool mask) {
  if (!footprints && !mask)
    throw Error("inputs: give the holes as 'footprints' (polygons) or 'mask' (a raster)");
}

OperatorSpec inpaint_spec() {
  OperatorSpec s;
  s.name = "synthesis.inpaint";
  s.description =
      "Fills the samples of an image under polygons or a mask from the rest of the image: "
      "bidirectional similarity with PatchMatch, coarse to fine, a band around the holes "
      "resynthesized (paper 002 §6)";
  s.kind = OperatorKind::Region;
  s.halo = kRegionContext;
  s.inputs = filled_layer_inputs("heights (float32 x 1, m), for output heights");
  s.inputs.push_back({"footprints", "features layer: polygons to fill (e.g. structures.bridge's)",
                      true, LayerKind::Features, 0});
  s.inputs.push_back({"mask", "raster layer: its non-zero samples filled", true});
  s.outputs = filled_layer_outputs("with its holes filled");
  s.params_schema = {{"type", "object"},
                     {"additionalProperties", false},
                     {"properties", inpaint_param_properties()}};
  s.check_params = [](const json& params, const std::set<std::string>& mapped_inputs) {
    read_inpaint_params(params);
    require_holes(mapped_inputs.count("footprints") > 0, mapped_inputs.count("mask") > 0);
  };
  return s;
}

class Inpaint final : public RegionOperator {
 public:
  const OperatorSpec& spec() const override { return spec_; }

  void run(const StepContext& ctx, const Mosaic& input, Mosaic& output) const override {
    InpaintParams params = read_inpaint_params(*ctx.params);
    const std::vector<FilledLayer> layers = filled_layers(ctx, input, output, "synthesis.inpaint");
    const int side = layers.front().picture.width;
    const auto footprints = input.features.find("footprints");
    const auto mask = input.layers.find("mask");
    require_holes(footprints != input.features.end(), mask != input.layers.end());
    std::vector<uint8_t> hole(size_t(side) * side, 0);
    if (footprints != input.features.end()) {
      hole = polygon_mask(ctx, input, footprints->second, side, "footprints");
    }
    if (mask != input.layers.end()) {
      const auto m = mask->second.data();
      const int c = mask->second.channels();
      for (size_t i = 0; i < hole.size(); ++i) {
        const auto marks = [](float v) { return std::isfinite(v) && v != 0; };
        hole[i] = hole[i] != 0 || std::any_of(m.begin() + i * c, m.begin() + (i + 1) * c, marks);
      }
    }
    const bool any_hole = std::any_of(hole.begin(), hole.end(), [](uint8_t h) { return h != 0; });
    if (!any_hole) {
      // Footprints beside the region (or a mask of zeros) leave nothing to fill: a run that changes
      // nothing is said, not passed off as a fill.
      std::string where;
      if (footprints != input.features.end())
        where = "inputs.footprints' polygons (" + std::to_string(footprints->second.size()) +
                " found near it)";
      if (mask != input.layers.end())
        where += (where.empty() ? "" : " or ") + std::string("inputs.mask's non-zero samples");
      spdlog::warn(
          "synthesis.inpaint: nothing to fill: no sample of the region lies in {}; the image is "
          "written unchanged",
          where);
    }
    for (const FilledLayer& layer : layers) {
      params.values = layer.values;
      write_filled(layer,
                   any_hole ? inpaint(layer.picture, hole, params, PatchMatch()) : layer.picture,
                   output);
    }
  }

 private:
  OperatorSpec spec_ = inpaint_spec();
};

}  // namespace

std::unique_ptr<Operator> make_inpaint() { return std::make_unique<Inpaint>(); }

}  // namespace maquette::synthesis
