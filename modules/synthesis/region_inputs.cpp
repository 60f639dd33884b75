#include "region_inputs.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/mosaic_geometry.h"
#include "core/polygon_set.h"
#include "core/unfolded_faces.h"

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

namespace {

// The layers the operators fill: input port, output port, values, channels.
struct FilledKind {
  const char* input;
  const char* output;
  LayerValues values;
  int channels;
};
constexpr FilledKind kFilledKinds[] = {{"image", "rgb", LayerValues::Continuous, 3},
                                       {"dem", "heights", LayerValues::Heights, 1},
                                       {"landcover", "classes", LayerValues::Classes, 1}};

}  // namespace

std::vector<InputSpec> filled_layer_inputs(const char* dem_description) {
  InputSpec image{"image", "imagery (uint8 x 3), for output rgb", true};
  image.channels = {3};
  return {image, single_channel_input("dem", dem_description, Semantics::Continuous, true),
          single_channel_input("landcover", "land-cover classes (1 channel), for output classes",
                               Semantics::Categorical, true)};
}

std::vector<OutputSpec> filled_layer_outputs(const std::string& what) {
  return {{"rgb", "the image " + what, DType::U8, 3, Semantics::Continuous, "", 0.0},
          {"heights", "the DEM " + what, DType::F32, 1, Semantics::Continuous, "m", std::nullopt},
          {"classes", "the land cover " + what + " (65535: none)", DType::U16, 1,
           Semantics::Categorical, "", 65535.0}};
}

std::vector<FilledLayer> filled_layers(const StepContext& ctx, const Mosaic& input,
                                       const Mosaic& output, const char* op) {
  std::vector<FilledLayer> layers;
  for (const FilledKind& kind : kFilledKinds) {
    if (!output.layers.contains(kind.output)) continue;
    const auto in = input.layers.find(kind.input);
    if (in == input.layers.end()) {
      throw Error(std::string("outputs.") + kind.output + ": " + op + " makes it from inputs." +
                  kind.input + ", which the step does not map");
    }
    const Tile<float>& tile = in->second;
    if (tile.channels() != kind.channels) {
      throw Error(std::string("inputs.") + kind.input + ": layer '" +
                  ctx.input_layer(kind.input).name + "' has " + std::to_string(tile.channels()) +
                  " channels; " + op + " takes " + std::to_string(kind.channels));
    }
    if (!layers.empty() && tile.size() != layers.front().picture.width) {
      throw Error(std::string("inputs.") + kind.input + ": layer '" +
                  ctx.input_layer(kind.input).name + "' gives " + std::to_string(tile.size()) +
                  " samples a side, inputs." + layers.front().input + " " +
                  std::to_string(layers.front().picture.width) +
                  "; ingest them at the same level and tile size");
    }
    PatchImage picture(tile.size(), tile.size(), kind.channels);
    std::copy(tile.data().begin(), tile.data().end(), picture.values.begin());
    layers.push_back({kind.input, kind.output, kind.values, std::move(picture)});
  }
  if (layers.empty())
    throw Error(std::string("outputs: ") + op + " writes rgb, heights or classes");
  return layers;
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

void write_filled(const FilledLayer& layer, const PatchImage& filled, Mosaic& output) {
  auto values = output.layers.at(layer.output).data();
  const bool colours = layer.values == LayerValues::Continuous;
  for (size_t i = 0; i < values.size(); ++i) {
    const float v = filled.values[i];
    values[i] = std::isnan(v) || !colours ? v : std::clamp(std::round(v), 0.0f, 255.0f);
  }
}

std::vector<uint8_t> region_cells(const StepContext& ctx, const Mosaic& input, const Mosaic& output,
                                  int side) {
  std::vector<uint8_t> mask(size_t(side) * side, 0);
  const UnfoldedFaces plane(*ctx.grid, input.face, input.level);
  for (const auto& [cell, content] : output.content) {
    const int n = 1 << (input.level - cell.level());
    const auto at = plane.place_tile(cell, n);
    if (!at) continue;
    for (int r = 0; r < n; ++r) {
      for (int c = 0; c < n; ++c) {
        const auto q = at->at(c, r);
        const int64_t col = q[0] - input.origin_col, row = q[1] - input.origin_row;
        if (col >= 0 && row >= 0 && col < side && row < side) mask[size_t(row) * side + col] = 1;
      }
    }
  }
  return mask;
}

}  // namespace maquette::synthesis
