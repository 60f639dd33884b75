// The synthesis benchmarks' fixture: the example's exemplar (examples/synthesis-zion.json:
// Bruegel's painting, 8 colour classes, the sky's excluded, exemplar scale 2), or the painting
// with another class image given (the hand-drawn examples/bruegel-harvesters-classes.geojson),
// and a window of Zion's NLCD land cover at its own 30 m pixels as the target's labels (no
// altitude guide: ebsynth is given the same labels and nothing else). Its class table: the
// example's, but forest and wetlands take the painting's near-black shade (class 1) with its dark
// olive foliage (6) as one class (session 20: the distinct-source bound 0.270 -> 0.376); another
// table may be given. Shared by synthesis_benchmark, ebsynth_compare and the synthesis module's
// test of the goals (modules/synthesis/tests/window_goals_test.cpp).
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "assess_metrics.h"
#include "synthesis.h"
#include "transfer_exemplar.h"

namespace maquette::synthesis::bench {

// The fixture's class table (NLCD's grouped classes -> painting classes, above).
nlohmann::json zion_classes();

// The transfer params (painting, classes, exclusions, scale) with the class table `classes`;
// `painting_classes`, when it holds "labels" (a class image, synthesis.transfer's), replaces the
// 8 colour classes with it and its "exclude_classes"; its "exemplars" and "harmonize" (further
// paintings searched with Bruegel's) are passed on.
nlohmann::json zion_params(const nlohmann::json& classes = zion_classes(),
                           const nlohmann::json& painting_classes = nlohmann::json::object());

// `weights` (an object of synthesis.transfer's weights and choices, synthesis_params_schema(),
// and optionally its "landcover_classes", "labels", "exclude_classes", "exemplars" and
// "harmonize") validated, the defaults filled in (the fixture's class table among them); errors
// name `program`.
nlohmann::json zion_weights(const nlohmann::json& weights, const std::string& program);

// The weights and choices of the synthesis.transfer step of `example` (a pipeline's file name in
// examples/) for this fixture, to be validated by zion_weights(): its synthesis_params_schema()
// fields, and its further paintings ("exemplars", "harmonize") with their relative paths read
// from the source folder (as the examples are run) and without their altitude (the fixture has
// no altitude guide). Bruegel's class table stays the fixture's.
nlohmann::json example_weights(const std::string& example);

// What of zion_weights()' `weights` describes the paintings, for zion_exemplar(): its "labels",
// "exclude_classes", "exemplars" and "harmonize" (with "exemplars").
nlohmann::json painting_classes(const nlohmann::json& weights);

// The exemplar analysed with zion_params(classes, painting_classes) (transfer_exemplar: cached
// per process).
std::shared_ptr<const TransferExemplar> zion_exemplar(
    const nlohmann::json& classes = zion_classes(),
    const nlohmann::json& painting_classes = nlohmann::json::object());

// The painting classes, through the class table `classes`, of NLCD pixels [col0, col0 + width)
// x [row0, ...) of the fixture's window (kUnknownLabel outside the raster or for unmapped
// classes), row-major.
std::vector<uint8_t> zion_labels(const PixelRect& window,
                                 const nlohmann::json& classes = zion_classes());

// Our synthesis of `out` (pixels of the NLCD window) cut into tiles of `tile` pixels, each
// computed from its own guides grown by synthesis_halo(), on `threads` threads (as the
// operator's cells are), with `params` and the class table `classes`: exemplar pixel per output
// pixel, row-major.
std::vector<int32_t> synthesize_tiles(const TransferExemplar& t, const PixelRect& out, int tile,
                                      int threads, const SynthesisParams& params = {},
                                      const nlohmann::json& classes = zion_classes());

// The colours (3 per pixel, 0..255) of exemplar `e`'s pixels `source`, in their order: what a
// synthesis's output shows.
std::vector<float> source_colours(const Exemplar& e, const std::vector<int32_t>& source);

// `out`'s AssessedImage for exemplar pixels `source` and colours `rgb` (3 per pixel 0..255),
// its labels through the class table `classes`.
AssessedImage assessed(const PixelRect& out, std::vector<int32_t> source, std::vector<float> rgb,
                       const nlohmann::json& classes = zion_classes());

}  // namespace maquette::synthesis::bench
