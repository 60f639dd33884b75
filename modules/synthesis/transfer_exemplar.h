// synthesis.transfer's exemplar from its step's params: the painting read, labelled (a hand
// class image, else segment_by_colour), its exclusions applied, shrunk and analysed; built once
// per process for each distinct set of those params (the cells waiting for it join the work),
// read back from the persistent cache of analyses (exemplar_cache.h) when it holds it,
// and shared by the cells.
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "combined_exemplar.h"
#include "core/output_clash.h"
#include "exemplar_pyramid.h"

namespace maquette::synthesis {

// A painting pixel an output pixel was copied from: the exemplar (0 the first painting, i the
// params' exemplars[i - 1]) and the painting's column and row (the top-left pixel of its
// exemplar_scale block).
struct SourcePixel {
  int exemplar = 0;
  int col = 0, row = 0;
};

struct TransferExemplar {
  int scale = 1;  // painting pixels per exemplar pixel (a side)
  // Of the shrunk paintings side by side (combined_exemplar.h; one painting: itself): levels[0]
  // is what the output copies, its colours harmonized (harmonize.h).
  ExemplarPyramid pyramid;
  std::vector<Placement> parts;  // each painting's place in levels[0], in exemplar pixels

  // The painting pixel of levels[0]'s pixel `s`, which lies in a painting (an allowed pixel).
  SourcePixel source_of(int32_t s) const;
  // levels[0]'s pixel holding painting pixel (col, row) of exemplar `exemplar`; -1 when there is
  // no such exemplar or the pixel lies outside it.
  int32_t pixel_of(int exemplar, int col, int row) const;
};

// From the validated params (README: synthesis.transfer): "painting", "labels" or "classes",
// "exclusion", "exclude_classes", "painting_altitude", "painting_distance" and "painting_light"
// (maquette-paint's; the light "lightness", light_guide.h, or a grey image, white light),
// "painting_guides" (maquette-paint's: "labels", "painting_altitude" and "painting_distance" may
// be "guides", made from its bands: painting_guides.h), "exemplar_scale", "k", and "exemplars" with
// "harmonize" (README: "Several paintings"; each further painting read as the first, its classes
// through further_classes, those it does not name excluded, shrunk, harmonized to the first, then
// all combined). Throws maquette::Error naming the op, field (exemplars[i].field for a further
// painting) and file at fault, among them a painting whose every pixel is excluded and a class
// "landcover_classes" gives a target value that has no pixel left to copy (it would be painted from
// any class). Cached by params (exemplar_key_params) in the process, and on disk (exemplar_cache.h,
// keyed by those and the bytes of exemplar_input_files) across processes and runs. `op` names the
// params in errors: the step's op, or maquette-paint's params file.
std::shared_ptr<const TransferExemplar> transfer_exemplar(
    const nlohmann::json& params, const std::string& op = "synthesis.transfer");

// Throws maquette::Error when `painting_class` has no pixel to copy in the exemplar (not in the
// paintings, excluded, or lost to its blocks), naming `field` (where the class is given), the
// class and the classes that have pixels: the synthesis would copy any class's pixels for it.
void check_class_has_pixels(const TransferExemplar& exemplar, int painting_class,
                            const std::string& field);

// Throws maquette::Error naming `op` and the further painting unless every painting of `params`
// has a "painting_altitude" or none has (the altitude guide compares them all).
void check_altitude_of_every_painting(const nlohmann::json& params, const std::string& op);

// What of the params the analysis reads (not the synthesis's weights): the exemplar's fields,
// and of "landcover_classes" the sets of classes taken as one (the whole table with
// "exemplars"), and what the masks made from "painting_guides" are mapped with
// (guided_masks_key). Throws maquette::Error naming `op` on a bad class table.
nlohmann::json exemplar_key_params(const nlohmann::json& params,
                                   const std::string& op = "synthesis.transfer");

// The files the analysis reads: each painting's image, class image or polygons, exclusion mask,
// altitude, distance and light images, and guides file ("rows", "lightness" and "guides" are no
// files); in exemplar_inputs each named for messages by what it is and its field ("the class image
// (exemplars[0].labels)").
std::vector<InputFile> exemplar_inputs(const nlohmann::json& params);
std::vector<std::string> exemplar_input_files(const nlohmann::json& params);

}  // namespace maquette::synthesis
