// Image completion (paper 002 §6, the clone brush's removal): a hole filled from the rest of the
// image by Simakov, Caspi, Shechtman and Irani's bidirectional similarity ("Summarizing visual data
// using bidirectional similarity", CVPR 2008) solved as Wexler, Shechtman and Irani's
// expectation-maximization ("Space-time completion of video", PAMI 2007), coarse to fine on a
// Gaussian pyramid, the nearest-neighbour fields found by a NearestFieldSearch (PatchMatch).
//
// Roles of the pixels, at every level: the region R resynthesized is the hole and the pixels
// within `band` (chessboard) of it, the paper's band of width d, so the fill's edge lies in
// resynthesized pixels and does not show. Target patches are those overlapping R (their pixels
// outside R are fixed: coherence with the surroundings); reference patches lie wholly outside R
// (and clear of nodata). Each iteration matches every target patch to its nearest reference
// patch (coherence: nothing in R unlike the rest) and every reference patch near R (within one
// patch of the target patches) to its nearest target patch (completeness: what surrounds the hole
// is found in it), then sets each pixel of R to the weighted mean of the values the matched
// patches covering it propose (weights exp(-SSD / 2 sigma^2), sigma^2 the 75th percentile of the
// SSDs, as Wexler; the completeness votes scaled by `completeness` and both normalized by their
// patch counts, as Simakov). The finest level's last iteration takes the votes' weighted mode
// instead of their mean (Wexler's mean-shift, from the mean: where the patches disagree the mean
// blurs the fill, the mode keeps the value most of them propose); classes take their most voted
// class there instead.
#pragma once

#include <cstdint>
#include <vector>

#include "nearest_field.h"

namespace maquette::synthesis {

// What a layer's values are (layer_values.h): colours or other continuous values, compared and
// averaged as they are; heights (1 channel, metres), their smooth trend under the hole kept and the
// detail above it completed (patches compared and copied as detail, so a fill meets the slope
// around it); classes (1 channel of class codes), compared and voted as one channel per class, each
// pixel of the finest level taking its most voted class, so the fill holds only classes found
// outside the hole, never an average of codes.
enum class LayerValues { Continuous, Heights, Classes };

struct InpaintParams {
  int patch = 7;              // side of the square patches (odd, >= 3)
  int band = 3;               // pixels around the hole resynthesized too (>= 0)
  int em_iterations = 8;      // expectation-maximization iterations per pyramid level (>= 1)
  int search_iterations = 2;  // passes of the field search per iteration (>= 1)
  double completeness = 3;    // weight of the completeness votes (0: coherence alone, Wexler)
  uint64_t seed = 0;          // of the search's random draws
  LayerValues values = LayerValues::Continuous;
};

// `image` with its pixels where `hole` is non-zero (width * height) filled, and those within
// `band` of the hole resynthesized; every other pixel keeps its bits (all of them when the hole is
// empty). Pixels outside the hole with a NaN in any channel are nodata: never copied, kept as they
// are (their neighbours are resynthesized from a provisional diffusion fill there). The result
// depends on the inputs and params only, never on the thread count. Throws maquette::Error for
// invalid params, a mask of another size, heights or classes of more than one channel, classes
// with none outside the hole, or an image where no patch lies wholly outside the hole, its band and
// the nodata.
PatchImage inpaint(const PatchImage& image, const std::vector<uint8_t>& hole,
                   const InpaintParams& params, const NearestFieldSearch& search);

}  // namespace maquette::synthesis
