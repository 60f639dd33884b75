// What synthesis.inpaint and synthesis.clone read and write alike: the completion's params (their
// schema and values), the image as a PatchImage, polygons of a features port as a mask of the
// region mosaic's samples, and the filled image written back as uint8 values.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "inpaint.h"
#include "runtime/operator.h"

namespace maquette::synthesis {

// Both operators' halo: context read beyond the region's cells, where patches near the region's
// edge find their matches.
inline constexpr int kRegionContext = 32;

// The JSON schema properties of InpaintParams: patch, band, em_iterations, search_iterations,
// completeness, seed.
json inpaint_param_properties();

// InpaintParams from validated params (defaults filled); throws maquette::Error naming
// params.patch when it is even.
InpaintParams read_inpaint_params(const json& params);

// A layer the operators fill (or clone into): an output port mapped by the step and the input
// port it is made from, their values' kind, and the input as a PatchImage.
struct FilledLayer {
  const char* input;   // "image", "dem" or "landcover"
  const char* output;  // "rgb", "heights" or "classes"
  LayerValues values;
  PatchImage picture;
};

// The input ports of the filled layers (imagery uint8 x 3, heights, land-cover classes).
std::vector<InputSpec> filled_layer_inputs(const char* dem_description);

// Their output ports, each described as the layer `what` (e.g. "with its holes filled").
std::vector<OutputSpec> filled_layer_outputs(const std::string& what);

// The layers to fill: one per output the step maps (rgb from image, heights from dem, classes
// from landcover). Throws maquette::Error naming the port at fault and `op`: an output mapped
// without its input, an image of other than 3 channels, heights or land cover of other than 1,
// layers of different sizes.
std::vector<FilledLayer> filled_layers(const StepContext& ctx, const Mosaic& input,
                                       const Mosaic& output, const char* op);

// `filled` (the layer's picture filled) into the layer's output: colours rounded and clamped to
// 0..255, heights and classes as they are (NaN kept in all).
void write_filled(const FilledLayer& layer, const PatchImage& filled, Mosaic& output);

// The samples of the region's cells in the mosaic (side x side, non-zero): what the runner keeps
// of a region operator's output (the rest is context).
std::vector<uint8_t> region_cells(const StepContext& ctx, const Mosaic& input, const Mosaic& output,
                                  int side);

// Non-zero for the mosaic's samples (side x side) whose centre lies in a polygon of `features`
// (even-odd); throws maquette::Error naming inputs.`port` and the feature that is no Polygon or
// MultiPolygon.
std::vector<uint8_t> polygon_mask(const StepContext& ctx, const Mosaic& input,
                                  const FeatureList& features, int side, const std::string& port);

}  // namespace maquette::synthesis
