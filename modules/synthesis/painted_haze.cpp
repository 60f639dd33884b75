#include "painted_haze.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/srgb.h"

namespace maquette::synthesis {

void check_haze_colour(const PanoramaPicture& picture, const PaintParams& params) {
  if (params.haze_distance == 0 || params.haze_color) return;
  if (std::none_of(picture.distance.begin(), picture.distance.end(),
                   [](float d) { return std::isnan(d); }))
    throw Error(params.source +
                ".haze_distance: the picture shows no sky to take the haze's colour from: give "
                "haze_color");
}

void add_haze(const PanoramaPicture& picture, double haze_distance,
              const std::optional<std::array<uint8_t, 3>>& colour, PaintedPanorama& painted) {
  const size_t n = picture.distance.size();
  std::array<double, 3> haze{};
  if (colour) {
    for (size_t k = 0; k < 3; ++k) haze[k] = srgb_to_linear((*colour)[k] / 255.0);
  } else {
    size_t sky = 0;  // summed in pixel order: the same bits for any threads
    for (size_t i = 0; i < n; ++i)
      if (std::isnan(picture.distance[i])) {
        ++sky;
        for (size_t k = 0; k < 3; ++k) haze[k] += srgb_to_linear(painted.rgb[3 * i + k] / 255.0);
      }
    for (double& h : haze) h /= double(sky);  // sky > 0: check_haze_colour
  }
  tbb::parallel_for(size_t(0), n, [&](size_t i) {
    const double d = picture.distance[i];
    if (std::isnan(d)) return;
    const double f = 1 - std::exp(-d / haze_distance);
    for (size_t k = 0; k < 3; ++k) {
      const double c = srgb_to_linear(painted.rgb[3 * i + k] / 255.0);
      painted.rgb[3 * i + k] = linear_to_srgb_byte((1 - f) * c + f * haze[k]);
    }
  });
}

}  // namespace maquette::synthesis
