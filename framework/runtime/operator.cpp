#include "runtime/operator.h"

#include "core/error.h"

namespace maquette {

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

Tile<float>& CellData::output(const std::string& port) {
  const auto it = outputs.find(port);
  if (it == outputs.end()) throw Error("no output tile for port '" + port + "'");
  return it->second;
}

}  // namespace maquette
