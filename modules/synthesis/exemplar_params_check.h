// The checks of synthesis.transfer's (and synthesis.assess's) exemplar params that need no
// analysis of the painting, made when the pipeline is read (OperatorSpec::check_params), so that a
// mistyped path or a field that does nothing is told before the steps before it run.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace maquette::synthesis {

// Throws maquette::Error naming the field, and the file or value at fault, when
// - a file the analysis reads (exemplar_inputs: a painting, class image, exclusion mask, guide
//   image) does not exist ("relative to the working directory" said for a relative path);
// - "classes" other than its default is given beside "labels", for the first painting or a
//   further one: it is the k of the segmentation by colour, which the class image replaces;
// - "harmonize" other than its default is given without "exemplars": there is nothing to match;
// - a "landcover_classes" table is malformed (class_groups, further_classes);
// - altitude_range or painting_altitude is given without inputs.dem, or the reverse
//   (altitude_range());
// - "line_classes" (the transfer's) names a class the table does not (line_labels()), or it,
//   "patch_search", "patch_edges" or "patch_balance" is given with "patch_passes" 0: the passes
//   they weigh do not run, or "spread_typical" with "w_spread" 0 (check_fields_without_effect()).
// `op` prefixes the fields of messages that name them; `dem_given`: inputs.dem is mapped.
// Preconditions: `params` validated against transfer_params_schema(), defaults filled in.
void check_exemplar_params(const nlohmann::json& params, const std::string& op, bool dem_given);

}  // namespace maquette::synthesis
