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

// The mosaic's `image` input (3 channels) as a PatchImage; throws maquette::Error naming the
// layer and `op` for another channel count.
PatchImage image_input(const StepContext& ctx, const Mosaic& input, const char* op);

// Non-zero for the mosaic's samples (side x side) whose centre lies in a polygon of `features`
// (even-odd); throws maquette::Error naming inputs.`port` and the feature that is no Polygon or
// MultiPolygon.
std::vector<uint8_t> polygon_mask(const StepContext& ctx, const Mosaic& input,
                                  const FeatureList& features, int side, const std::string& port);

// `image` rounded and clamped to 0..255 (NaN kept) into `out` (the same size and channels).
void write_uint8(const PatchImage& image, Tile<float>& out);

}  // namespace maquette::synthesis
