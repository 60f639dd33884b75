// The light guide (StyLit, Fiser et al. 2016: example-based transfer guided by lighting): where
// the painting is dark or light within each of its classes, and where the target is in shade or
// lit within each of its classes, as quantiles, so that the two compare whatever the painting's
// palette and the target's sun (paper 000: "shadowed pixel patches from the input image may be
// placed unintentionally into lighted areas of the output image").
#pragma once

#include <cstdint>
#include <vector>

#include "exemplar.h"

namespace maquette::synthesis {

// Each pixel's quantile within its class, counted or not: the share of the counted pixels of its
// class (counted[i] != 0 and values[i] not NaN) whose value is lower, plus half the share of those
// equal to it (ties take the mid-rank), so a class's counted pixels spread uniformly over
// (0, 1) and equal values get equal quantiles. NaN where the value is NaN or the class has no
// counted pixel. A function of the values alone, not of their order.
std::vector<float> class_quantiles(const std::vector<float>& values,
                                   const std::vector<uint8_t>& classes,
                                   const std::vector<uint8_t>& counted);

// The painting's light from `values` (one a pixel of `e`: its CIE L* for painting_light
// "lightness", painting_lightness; or a grey image's): each pixel's value as its quantile
// (class_quantiles) among the allowed (not excluded) pixels of its label; an excluded pixel takes
// the quantile its value would have among them (never copied, but the pyramid's filters read
// it), 0.5 when its label has no allowed pixel or its value is NaN.
std::vector<float> painting_light(const Exemplar& e, const std::vector<float>& values);

// Each pixel's CIE L* (texture::srgb_to_lab): maquette-paint's painting_light "lightness".
std::vector<float> painting_lightness(const Exemplar& e);

}  // namespace maquette::synthesis
