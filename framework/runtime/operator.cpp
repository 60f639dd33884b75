#include "runtime/operator.h"

#include <utility>

#include "core/error.h"

namespace maquette {

InputSpec single_channel_input(std::string name, std::string description, Semantics semantics,
                               bool optional) {
  InputSpec in;
  in.name = std::move(name);
  in.description = std::move(description);
  in.optional = optional;
  in.semantics = semantics;
  in.channels = {1};
  return in;
}

std::string_view operator_kind_name(OperatorKind k) {
  switch (k) {
    case OperatorKind::Cell:
      return "cell";
    case OperatorKind::Reduce:
      return "reduce";
    case OperatorKind::Region:
      return "region";
    case OperatorKind::Task:
      return "task";
  }
  return "unknown";
}

const Tile<float>& CellData::input(const std::string& port) const {
  const auto it = inputs.find(port);
  if (it == inputs.end()) throw Error("no input tile for port '" + port + "'");
  return it->second;
}

const FeatureList& CellData::features_of(const std::string& port) const {
  const auto it = features.find(port);
  if (it == features.end()) throw Error("no features for port '" + port + "'");
  return it->second;
}

namespace {

const LayerInfo& layer_of(const InputLayers* layers, const std::string& port) {
  if (layers)
    for (const auto& [name, layer] : *layers)
      if (name == port) return layer;
  throw Error("no layer is read by input port '" + port + "'");
}

}  // namespace

const LayerInfo& CellContext::input_layer(const std::string& port) const {
  return layer_of(input_layers, port);
}

const LayerInfo& StepContext::input_layer(const std::string& port) const {
  return layer_of(input_layers, port);
}

bool CellContext::owns(LonLat anchor) const {
  return grid->cell_from_point(anchor, cell.level()) == cell;
}

namespace {

template <class Content>
Content& content_of(std::map<std::string, Content>& by_port, const std::string& port,
                    const char* kind) {
  const auto it = by_port.find(port);
  if (it == by_port.end())
    throw Error("no " + std::string(kind) + " content for port '" + port +
                "' (not a mapped port of that kind)");
  return it->second;
}

}  // namespace

MeshContent& CellContent::mesh(const std::string& port) { return content_of(meshes, port, "mesh"); }

InstancesContent& CellContent::instances_of(const std::string& port) {
  return content_of(instances, port, "instances");
}

VolumeContent& CellContent::volume(const std::string& port) {
  return content_of(volumes, port, "volume");
}

bool CellContent::wants(const std::string& port) const {
  return meshes.count(port) != 0 || instances.count(port) != 0 || volumes.count(port) != 0;
}

Tile<float>& CellData::output(const std::string& port) {
  const auto it = outputs.find(port);
  if (it == outputs.end()) throw Error("no output tile for port '" + port + "'");
  return it->second;
}

}  // namespace maquette
