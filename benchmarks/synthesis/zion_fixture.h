// The synthesis benchmarks' fixture: the example's exemplar (examples/synthesis-zion.json:
// Bruegel's painting, 8 colour classes, the sky's excluded, exemplar scale 2) and a window of
// Zion's NLCD land cover at its own 30 m pixels as the target's labels (no altitude guide: ebsynth
// is given the same labels and nothing else). Its class table is the example's but for forest
// and wetlands, which take the painting's near-black shade (class 1) with its dark olive foliage
// (6) as one class (session 20: the distinct-source bound 0.270 -> 0.376). Shared by
// synthesis_benchmark and ebsynth_compare.
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <vector>

#include "assess_metrics.h"
#include "synthesis.h"
#include "transfer_exemplar.h"

namespace maquette::synthesis::bench {

// The example's transfer params (painting, classes, exclusions, class table, scale).
nlohmann::json zion_params();

// The exemplar analysed (transfer_exemplar: cached per process).
std::shared_ptr<const TransferExemplar> zion_exemplar();

// The painting classes of NLCD pixels [col0, col0 + width) x [row0, ...) of the fixture's
// window (kUnknownLabel outside the raster or for unmapped classes), row-major.
std::vector<uint8_t> zion_labels(const PixelRect& window);

// Our synthesis of `out` (pixels of the NLCD window) cut into tiles of `tile` pixels, each
// computed from its own guides grown by synthesis_halo(), on `threads` threads (as the
// operator's cells are), with `params`: exemplar pixel per output pixel, row-major.
std::vector<int32_t> synthesize_tiles(const TransferExemplar& t, const PixelRect& out, int tile,
                                      int threads, const SynthesisParams& params = {});

// `out`'s AssessedImage for exemplar pixels `source` and colours `rgb` (3 per pixel 0..255).
AssessedImage assessed(const PixelRect& out, std::vector<int32_t> source, std::vector<float> rgb);

}  // namespace maquette::synthesis::bench
