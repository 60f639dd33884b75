// Layers named by a command's options (--dem, --texture, --land-cover of render and of the 3D
// exports): checked in one place, with one set of messages naming the option.
#pragma once

#include <string>

#include "store/store.h"

namespace maquette {

// The layer `name` given as `option`. Throws maquette::Error naming both when it is not in the
// store, a run left it incomplete, or it is not a raster.
LayerInfo option_raster_layer(const Store& store, const std::string& option,
                              const std::string& name);

// The layer `name` as --dem: option_raster_layer, and one channel, not categorical (land-cover
// classes drawn as heights of a few metres).
LayerInfo height_layer(const Store& store, const std::string& name);

}  // namespace maquette
