#include "image/option_layers.h"

#include "core/error.h"

namespace maquette {

LayerInfo option_raster_layer(const Store& store, const std::string& option,
                              const std::string& name) {
  std::optional<LayerInfo> info = store.layer(name);
  if (!info) throw Error(option + " layer '" + name + "' is not in the store " + store.path());
  try {  // a layer a run left incomplete is not read
    info = store.require_layer(name);
  } catch (const Error& e) {
    throw Error(option + ": " + e.what());
  }
  if (info->kind != LayerKind::Raster)
    throw Error(option + " layer '" + name + "' is a " + std::string(layer_kind_name(info->kind)) +
                " layer: expected a raster");
  return *info;
}

LayerInfo height_layer(const Store& store, const std::string& name) {
  const LayerInfo dem = option_raster_layer(store, "--dem", name);
  if (dem.channels != 1)
    throw Error("--dem layer '" + name + "' has " + std::to_string(dem.channels) +
                " channels: expected one channel of heights");
  if (dem.semantics == Semantics::Categorical)
    throw Error("--dem layer '" + name + "' is categorical (classes, not heights)");
  return dem;
}

}  // namespace maquette
