// The clone brush's copy (paper 002 §6): a source region of an image copied onto a destination,
// resized by a linear map (the slope-aware resize: a texture cloned from flat ground onto a slope
// is foreshortened by the cosine ratio along the slope's direction), then the band across the
// destination's edge resynthesized from both sides by inpaint() so that the edge does not show.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "inpaint.h"

namespace maquette::synthesis {

// The completion's EM iterations, and PatchMatch passes in each, for a clone's band by default
// (inpaint()'s defaults are 8 and 2): the band is a ring a patch thin between known pixels on both
// sides, so two iterations of one pass resynthesize it without a seam on Zion's Landsat as eight
// of two do (edge gradient; its energy 9 % higher, still 15 % below the hard copy's:
// modules/synthesis/NOTES.md) at under a third of the cost. One iteration is not enough: a
// periodic texture is no longer cloned exactly.
constexpr int kCloneEmIterations = 2;
constexpr int kCloneSearchIterations = 1;

struct CloneParams {
  // Where the source's bounding-box centre lands, in pixels from where it is.
  double offset_x = 0, offset_y = 0;
  // Source offsets from that centre to destination offsets, row-major {a, b, c, d}:
  // destination = (a x + b y, c x + d y). Identity: a copy; {2, 0, 0, 2}: twice as large.
  std::array<double, 4> linear = {1, 0, 0, 1};
  // The band's resynthesis: `fill.band` pixels on each side of the destination's edge (0: a
  // plain copy).
  InpaintParams fill{.em_iterations = kCloneEmIterations,
                     .search_iterations = kCloneSearchIterations};
};

// Where a copy lands: each pixel whose centre maps back (through the inverse of `linear`, about
// the source's bounding-box centre moved by the offset) onto a pixel of `source` (width *
// height). `destination` marks those in the image; `beyond` counts those outside it, which
// clone() drops. Throws maquette::Error as clone() does for the source and the map.
struct CopyFootprint {
  std::vector<uint8_t> destination;
  size_t beyond = 0;
};
CopyFootprint copy_footprint(const std::vector<uint8_t>& source, int width, int height,
                             const CloneParams& params);

// The foreshortening map of a texture moved from ground of slope `from_deg` to ground of slope
// `to_deg` whose downhill direction makes `aspect_deg` with the image's x axis (clockwise, y
// down): lengths along that direction scaled by cos(to) / cos(from), across it kept.
std::array<double, 4> foreshortening(double from_deg, double to_deg, double aspect_deg);

// `image` with the destination of `source` (non-zero, width * height; copy_footprint()) set to the
// source's values (bilinear, through the inverse of `linear`) and the pixels within `fill.band` of
// the destination's edge, on both sides, resynthesized. Destination pixels outside the image are
// dropped. By `fill.values` (inpaint.h): classes are copied from the nearest source pixel (whole,
// never mixed); heights are copied bilinearly, then moved by the mean difference between the
// heights under the destination's edge (within `fill.band`, at least 1) before and after the copy,
// so that the copied relief meets its surroundings. Throws maquette::Error for a source mask of
// another size, an empty source, a singular map, or inpaint()'s errors.
PatchImage clone(const PatchImage& image, const std::vector<uint8_t>& source,
                 const CloneParams& params, const NearestFieldSearch& search);

}  // namespace maquette::synthesis
