#include "region_inputs.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/mosaic_geometry.h"
#include "core/polygon_set.h"

namespace maquette::synthesis {

json inpaint_param_properties() {
  const auto integer = [](int minimum, int maximum, int value, const char* what) {
    return json{{"type", "integer"},
                {"minimum", minimum},
                {"maximum", maximum},
                {"default", value},
                {"description", what}};
  };
  return {{"patch", integer(3, 15, 7, "side of the square patches, samples (odd)")},
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
          {"seed", integer(0, 2147483647, 0, "of PatchMatch's random draws")}};
}

InpaintParams read_inpaint_params(const json& p) {
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
  return params;
}

PatchImage image_input(const StepContext& ctx, const Mosaic& input, const char* op) {
  const Tile<float>& image = input.layers.at("image");
  if (image.channels() != 3) {
    throw Error("inputs.image: layer '" + ctx.input_layer("image").name + "' has " +
                std::to_string(image.channels()) + " channels; " + op +
                " takes imagery of 3 (uint8 x 3)");
  }
  PatchImage picture(image.size(), image.size(), 3);
  std::copy(image.data().begin(), image.data().end(), picture.values.begin());
  return picture;
}

std::vector<uint8_t> polygon_mask(const StepContext& ctx, const Mosaic& input,
                                  const FeatureList& features, int side, const std::string& port) {
  std::vector<PolygonRings> polygons;
  for (const VectorFeature* f : features) {
    if (f->geometry.type != GeometryType::Polygon &&
        f->geometry.type != GeometryType::MultiPolygon) {
      throw Error("inputs." + port + ": feature " + std::to_string(f->id) + " is a " +
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

void write_uint8(const PatchImage& image, Tile<float>& out) {
  auto values = out.data();
  for (size_t i = 0; i < values.size(); ++i) {
    values[i] =
        std::isnan(image.values[i]) ? NAN : std::clamp(std::round(image.values[i]), 0.0f, 255.0f);
  }
}

}  // namespace maquette::synthesis
