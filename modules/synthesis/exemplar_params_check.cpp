#include "exemplar_params_check.h"

#include "core/error.h"
#include "painting.h"
#include "transfer_exemplar.h"
#include "transfer_params.h"

namespace maquette::synthesis {
namespace {

// A field given another value than its schema's default (the params come with the defaults
// filled in: a default is not told from a field left out).
bool set_apart_from_default(const nlohmann::json& fields, const nlohmann::json& schema,
                            const char* field) {
  return fields.contains(field) && fields.at(field) != schema.at(field).at("default");
}

void check_classes_beside_labels(const nlohmann::json& fields, const std::string& where) {
  if (!fields.contains("labels") ||
      !set_apart_from_default(fields, exemplar_params_schema(), "classes"))
    return;
  throw Error(where + "classes: " + fields.at("classes").dump() +
              " is the k of the segmentation by colour, which the class image " +
              fields.at("labels").dump() + " (" + where +
              "labels) replaces: leave out classes or labels");
}

}  // namespace

void check_exemplar_params(const nlohmann::json& params, const std::string& op, bool dem_given) {
  for (const InputFile& file : exemplar_inputs(params)) require_file(file.path, file.what);
  check_classes_beside_labels(params, op + ".");
  const bool further = params.contains("exemplars");
  if (!further && set_apart_from_default(params, further_exemplars_schema(), "harmonize"))
    throw Error(op + ".harmonize: " + params.at("harmonize").dump() +
                " matches further paintings' colours to the first's, and there are none (no "
                "exemplars): leave out harmonize or add exemplars");
  class_groups(params.at("landcover_classes"), op);
  if (further)
    for (size_t i = 0; i < params.at("exemplars").size(); ++i) {
      const nlohmann::json& fields = params.at("exemplars").at(i);
      const std::string where = op + ".exemplars[" + std::to_string(i) + "]";
      check_classes_beside_labels(fields, where + ".");
      further_classes(params.at("landcover_classes"), fields.at("landcover_classes"), op, where);
    }
  check_altitude_of_every_painting(params, op);
  altitude_range(params, op, dem_given);
  if (params.contains("line_classes")) {  // the transfer's fields (not the assessment's)
    check_fields_without_effect(params, op);
    line_labels(params, op);
  }
}

}  // namespace maquette::synthesis
