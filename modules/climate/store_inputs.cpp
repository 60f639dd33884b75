#include "store_inputs.h"

#include <algorithm>
#include <limits>

#include "core/error.h"

namespace maquette::climate {

const Store& run_store(const Store* store, const std::string& op) {
  if (store == nullptr)
    throw Error(op + ": no store: the operator reads its inputs from a run's store");
  return *store;
}

nlohmann::json read_json_artifact(const Store& store, const std::string& name,
                                  const std::string& op, const std::string& field) {
  const auto artifact = store.get_artifact(name);
  if (!artifact)
    throw Error(op + ": params." + field + ": no artifact '" + name + "' in " + store.path());
  try {
    return nlohmann::json::parse(artifact->text());
  } catch (const nlohmann::json::exception&) {
    throw Error(op + ": params." + field + ": artifact '" + name + "' is not JSON");
  }
}

std::vector<Zone> read_zones(const Store& store, const std::string& layer,
                             const std::string& name_field, const std::string& op) {
  const std::string where = op + ": params.zones";
  const auto info = store.layer(layer);
  if (!info) throw Error(where + ": no layer '" + layer + "' in " + store.path());
  if (info->kind != LayerKind::Features)
    throw Error(where + ": layer '" + layer + "' is a " + std::string(layer_kind_name(info->kind)) +
                " layer, not features");
  std::vector<Zone> zones;
  for (const Feature& f :
       store.features_in(layer, CellId(0), CellId(uint64_t(std::numeric_limits<int64_t>::max())))) {
    Zone z;
    z.fid = f.fid;
    const std::string at = where + ": feature " + std::to_string(f.fid) + " of '" + layer + "'";
    z.polygons = wkb_polygons(f.wkb, at);
    z.bbox = f.bbox;
    const auto name = f.attributes.find(name_field);
    z.name = name_field.empty() || name == f.attributes.end() || name->is_null()
                 ? std::to_string(f.fid)
                 : (name->is_string() ? name->get<std::string>() : name->dump());
    zones.push_back(std::move(z));
  }
  if (zones.empty()) throw Error(where + ": layer '" + layer + "' has no features");
  return zones;
}

}  // namespace maquette::climate
