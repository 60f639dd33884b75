// A model layer's horizontal size (store/README.md, "Model layers"), read from its GLB's JSON
// chunk without decoding Draco: glTF requires each POSITION accessor's min and max, and the
// model's GLB is in its own frame with glTF's axes (x east, y up, z south: gltf/mesh_glb.h).
#pragma once

#include <string>
#include <string_view>

namespace maquette {

// The larger side, in metres, of the model's bounding box in x (east) and y (north): the union of
// its primitives' POSITION bounds. `blob` is the model layer's blob (Store::get_model). Throws
// maquette::Error naming `where` (e.g. "model 'hotel' of store X") for a payload that is not a
// GLB or a primitive without a POSITION accessor with min and max.
double model_horizontal_extent(std::string_view blob, const std::string& where);

}  // namespace maquette
