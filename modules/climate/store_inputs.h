// What the climate operators read from the run's store (CellContext::store, StepContext::store)
// besides their raster inputs: JSON artifacts and the zone polygons of a features layer.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "store/store.h"
#include "zones.h"

namespace maquette::climate {

// The run's store `store`; throws naming op when there is none (an operator called outside a run).
const Store& run_store(const Store* store, const std::string& op);

// The JSON artifact `name` (params field `field`); throws naming op, field and value when absent
// or not JSON.
nlohmann::json read_json_artifact(const Store& store, const std::string& name,
                                  const std::string& op, const std::string& field);

// Every polygon feature of the features layer `layer`, by fid, named by the attribute
// `name_field` (else the fid). Throws naming op, field and fid for another layer kind or a
// feature that is not a polygon.
std::vector<Zone> read_zones(const Store& store, const std::string& layer,
                             const std::string& name_field, const std::string& op);

}  // namespace maquette::climate
