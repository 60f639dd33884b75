// synthesis.inpaint (region): the samples of an image under a mask (the polygons of a features
// layer, e.g. structures.bridge's footprints, or a mask raster) filled from the rest of the image
// (inpaint.h). A region operator: a hole may span several cells, and its fill reads the whole
// region (the cells are pasted into one mosaic, filled, and cut back), with kHalo samples of
// context beyond the region's cells. It runs once, on one rank; inpaint() gives the same bits
// for any thread count.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/mosaic_geometry.h"
#include "core/polygon_set.h"
#include "inpaint.h"
#include "operators.h"
#include "patchmatch.h"

namespace maquette::synthesis {
namespace {

// Context read beyond the region's cells: patches near the region's edge find their matches there.
constexpr int kHalo = 32;

OperatorSpec inpaint_spec() {
  OperatorSpec s;
  s.name = "synthesis.inpaint";
  s.description =
      "Fills the samples of an image under polygons or a mask from the rest of the image: "
      "bidirectional similarity with PatchMatch, coarse to fine, a band around the holes "
      "resynthesized (paper 002 §6)";
  s.kind = OperatorKind::Region;
  s.halo = kHalo;
  s.inputs = {{"image", "imagery (uint8 x 3) to fill", false},
              {"footprints", "features layer: polygons to fill (e.g. structures.bridge's)", true,
               LayerKind::Features, 0},
              {"mask", "raster layer: its non-zero samples filled", true}};
  s.outputs = {
      {"rgb", "the image with its holes filled", DType::U8, 3, Semantics::Continuous, "", 0.0}};
  const auto integer = [](int minimum, int maximum, int value, const char* what) {
    return json{{"type", "integer"},
                {"minimum", minimum},
                {"maximum", maximum},
                {"default", value},
                {"description", what}};
  };
  s.params_schema = {
      {"type", "object"},
      {"additionalProperties", false},
      {"properties",
       {{"patch", integer(3, 15, 7, "side of the square patches, samples (odd)")},
        {"band", integer(0, 16, 3, "samples around the holes resynthesized too (the paper's d)")},
        {"em_iterations", integer(1, 32, 8, "iterations of the completion per pyramid level")},
        {"search_iterations", integer(1, 16, 2, "PatchMatch passes per iteration")},
        {"completeness",
         {{"type", "number"},
          {"minimum", 0},
          {"maximum", 100},
          {"default", 3},
          {"description",
           "weight of the completeness votes (what surrounds a hole appears in it; 0: "
           "coherence alone)"}}},
        {"seed", integer(0, 2147483647, 0, "of PatchMatch's random draws")}}}};
  return s;
}

// Non-zero for the mosaic's samples whose centre lies in a polygon of `features`.
std::vector<uint8_t> polygon_mask(const StepContext& ctx, const Mosaic& input,
                                  const FeatureList& features, int side) {
  std::vector<PolygonRings> polygons;
  for (const VectorFeature* f : features) {
    if (f->geometry.type != GeometryType::Polygon &&
        f->geometry.type != GeometryType::MultiPolygon) {
      throw Error("inputs.footprints: feature " + std::to_string(f->id) + " is a " +
                  std::string(geometry_type_name(f->geometry.type)) +
                  ", not a Polygon or MultiPolygon");
    }
    for (const GeoPolygon& p : f->geometry.polygons) {
      PolygonRings& rings = polygons.emplace_back();
      for (const GeoPath& ring : p.rings) {
        auto& out = rings.emplace_back();
        for (const GeoPoint& q : ring) out.push_back({q.lon, q.lat});
      }
    }
  }
  std::vector<uint8_t> mask(size_t(side) * side, 0);
  const PolygonSet set(polygons);
  if (set.empty()) return mask;
  const MosaicGeometry geometry(*ctx.grid, input.face, input.level, input.origin_col,
                                input.origin_row);
  for (int row = 0; row < side; ++row) {
    for (int col = 0; col < side; ++col) {
      const auto centre = geometry.sample_lonlat(col, row);
      mask[size_t(row) * side + col] = centre && set.contains(*centre);
    }
  }
  return mask;
}

class Inpaint final : public RegionOperator {
 public:
  const OperatorSpec& spec() const override { return spec_; }

  void run(const StepContext& ctx, const Mosaic& input, Mosaic& output) const override {
    const json& p = *ctx.params;
    InpaintParams params;
    params.patch = p.at("patch").get<int>();
    if (params.patch % 2 == 0) {
      throw Error("params.patch: " + std::to_string(params.patch) + " is even; give an odd side");
    }
    params.band = p.at("band").get<int>();
    params.em_iterations = p.at("em_iterations").get<int>();
    params.search_iterations = p.at("search_iterations").get<int>();
    params.completeness = p.at("completeness").get<double>();
    params.seed = p.at("seed").get<uint64_t>();

    const Tile<float>& image = input.layers.at("image");
    if (image.channels() != 3) {
      throw Error("inputs.image: layer '" + ctx.input_layer("image").name + "' has " +
                  std::to_string(image.channels()) +
                  " channels; synthesis.inpaint fills imagery of 3 (uint8 x 3)");
    }
    const int side = image.size();
    const auto footprints = input.features.find("footprints");
    const auto mask = input.layers.find("mask");
    if (footprints == input.features.end() && mask == input.layers.end()) {
      throw Error("inputs: give the holes as 'footprints' (polygons) or 'mask' (a raster)");
    }
    std::vector<uint8_t> hole(size_t(side) * side, 0);
    if (footprints != input.features.end()) {
      hole = polygon_mask(ctx, input, footprints->second, side);
    }
    if (mask != input.layers.end()) {
      const auto m = mask->second.data();
      const int c = mask->second.channels();
      for (size_t i = 0; i < hole.size(); ++i) {
        const auto marks = [](float v) { return std::isfinite(v) && v != 0; };
        hole[i] = hole[i] != 0 || std::any_of(m.begin() + i * c, m.begin() + (i + 1) * c, marks);
      }
    }
    PatchImage picture(side, side, 3);
    std::copy(image.data().begin(), image.data().end(), picture.values.begin());
    const bool any_hole = std::any_of(hole.begin(), hole.end(), [](uint8_t h) { return h != 0; });
    const PatchImage filled = any_hole ? inpaint(picture, hole, params, PatchMatch()) : picture;
    auto out = output.layers.at("rgb").data();
    for (size_t i = 0; i < out.size(); ++i) {
      out[i] = std::isnan(filled.values[i])
                   ? NAN
                   : std::clamp(std::round(filled.values[i]), 0.0f, 255.0f);
    }
  }

 private:
  OperatorSpec spec_ = inpaint_spec();
};

}  // namespace

std::unique_ptr<Operator> make_inpaint() { return std::make_unique<Inpaint>(); }

}  // namespace maquette::synthesis
