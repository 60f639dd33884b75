// The surface-layer model of paper 001 (sections 4 and 5): a hierarchy of layers, each with a
// colour, noise scale and bias, a roughness and one constraint function per input quantity,
// sampled as 256 bins over the quantity's range. Layers are kept flat in depth-first order
// (layers[0] is the root), each knowing its parent, which is the order they are evaluated in.
#pragma once

#include <array>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace maquette::texture {

using json = nlohmann::json;

inline constexpr int kModelVersion = 1;
inline constexpr int kBins = 256;
using Table = std::array<float, kBins>;

struct Quantity {
  std::string name;  // "height", "slope", or the name of an input raster
  double lo = 0, hi = 1;
};

// The quantity "landcover" is categorical: codes 0..255 (e.g. NLCD classes), one table bin per
// code over the range [-0.5, 255.5] (code c at bin c's centre, so tables are read without
// interpolation between codes), upsampled by nearest neighbour instead of the B-spline.
inline constexpr const char* kCategoricalQuantity = "landcover";
inline constexpr double kCategoricalLo = -0.5, kCategoricalHi = 255.5;
bool is_categorical(const std::string& quantity);

// Fractal 3D gradient noise of the position on the globe (see noise.h).
struct NoiseParams {
  uint64_t seed = 1;
  int octaves = 3;
  double wavelength_m = 200;  // of the coarsest octave
  double persistence = 0.5;   // amplitude ratio between octaves
};

struct Layer {
  std::string name;
  int parent = -1;                // index into Model::layers, -1 for the root
  int class_id = -1;              // surface type it represents (-1: none; inherits the parent's)
  std::array<float, 3> colour{};  // RGB 0..255
  float bias = 1, noise_scale = 0, roughness_m = 0;
  NoiseParams noise;
  std::vector<std::optional<Table>> constraints;  // per Model::quantities index
};

struct Model {
  std::vector<Quantity> quantities;
  std::vector<Layer> layers;                    // depth-first
  int quantity(const std::string& name) const;  // index or -1
};

// Parses and checks a model document. Errors name the field and value, prefixed with `context`:
//   "texture.procedural: params.model.layers[2].constraints.slope.hat: expected 4 numbers".
Model parse_model(const json& doc, const std::string& context);
json model_to_json(const Model& model);

// The clamped hat of paper 4.1 (Fig. 2): 0 below a, rising to 1 at b, 1 up to c, 0 from d on,
// sampled at the 256 bin centres of [lo, hi).
Table hat_table(const std::array<double, 4>& abcd, double lo, double hi);

// The class of a layer: its own or its nearest ancestor's (-1 when none has one).
int layer_class(const Model& model, int layer);

}  // namespace maquette::texture
