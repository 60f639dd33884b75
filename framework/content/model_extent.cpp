#include "content/model_extent.h"

#include <algorithm>
#include <cmath>

#include "content/content_blob.h"
#include "content/glb_chunks.h"
#include "core/error.h"

namespace maquette {

double model_horizontal_extent(std::string_view blob, const std::string& where) {
  read_content_envelope(blob, where);
  const GlbChunks glb = split_glb(content_payload(blob), where);
  const nlohmann::json& gltf = glb.gltf;
  double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  for (const auto& mesh : gltf.value("meshes", nlohmann::json::array()))
    for (const auto& primitive : mesh.value("primitives", nlohmann::json::array())) {
      const auto& attributes = primitive.value("attributes", nlohmann::json::object());
      const auto position = attributes.find("POSITION");
      const nlohmann::json* accessor = nullptr;
      if (position != attributes.end() && position->is_number_unsigned() &&
          position->get<size_t>() < gltf.value("accessors", nlohmann::json::array()).size())
        accessor = &gltf["accessors"][position->get<size_t>()];
      if (!accessor || !accessor->contains("min") || !accessor->contains("max") ||
          (*accessor)["min"].size() != 3 || (*accessor)["max"].size() != 3)
        throw Error(where + ": a primitive of the model's GLB has no POSITION accessor with its " +
                    "min and max");
      for (size_t a = 0; a < 3; ++a) {
        lo[a] = std::min(lo[a], (*accessor)["min"][a].get<double>());
        hi[a] = std::max(hi[a], (*accessor)["max"][a].get<double>());
      }
    }
  if (!(lo[0] <= hi[0])) throw Error(where + ": the model's GLB has no primitive");
  // glTF x is east and z south: the horizontal sides.
  return std::max(hi[0] - lo[0], hi[2] - lo[2]);
}

}  // namespace maquette
