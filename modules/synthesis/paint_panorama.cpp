#include "paint_panorama.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "core/error.h"
#include "core/sibling_path.h"
#include "light_guide.h"
#include "painted_haze.h"
#include "painting_guides.h"
#include "skyline_blend.h"
#include "transfer_params.h"

namespace maquette::synthesis {
namespace {

bool is_sky(const PanoramaPicture& p, size_t i) { return std::isnan(p.distance[i]); }

// The median of the shading factor over the terrain (1 without terrain).
double median_shading(const PanoramaPicture& p) {
  std::vector<float> lit;
  for (size_t i = 0; i < p.shading.size(); ++i)
    if (!is_sky(p, i) && !std::isnan(p.shading[i])) lit.push_back(p.shading[i]);
  if (lit.empty()) return 1;
  const auto middle = lit.begin() + ptrdiff_t(lit.size() / 2);
  std::nth_element(lit.begin(), middle, lit.end());
  return *middle;
}

}  // namespace

std::vector<InputFile> paint_inputs(const std::string& picture, const std::string& params_path,
                                    const PaintParams& params) {
  std::vector<InputFile> inputs{{"the panorama", picture},
                                {"the panorama's guides", sibling_path(picture, "-guides.tif")},
                                {"the params", params_path}};
  for (InputFile& input : exemplar_inputs(params.exemplar)) inputs.push_back(std::move(input));
  return inputs;
}

std::vector<float> panorama_light(const PanoramaPicture& p, const PaintParams& params) {
  std::vector<uint8_t> classes(p.shading.size()), terrain(p.shading.size());
  for (size_t i = 0; i < p.shading.size(); ++i) {
    terrain[i] = !is_sky(p, i);
    classes[i] = painting_class(params.classes, p.land_cover[i]);
  }
  std::vector<float> light = class_quantiles(p.shading, classes, terrain);
  for (size_t i = 0; i < light.size(); ++i)  // the sky has no light, whatever its shading band
    if (!terrain[i]) light[i] = std::numeric_limits<float>::quiet_NaN();
  return light;
}

TargetGuides panorama_target(const PanoramaPicture& p, const PaintParams& params,
                             const std::vector<float>& light, const PixelRect& window) {
  const int64_t halo = synthesis_halo();
  TargetGuides g;
  g.rect = {window.col0 - halo, window.row0 - halo, window.width + 2 * halo,
            window.height + 2 * halo};
  const size_t n = size_t(g.rect.width) * size_t(g.rect.height);
  g.labels.resize(n);
  if (params.altitude_range) g.altitude.resize(n);
  if (params.distance_range) g.distance.resize(n);
  if (params.silhouettes) g.depth.resize(n);
  if (!light.empty()) g.light.resize(n);
  for (int64_t r = 0; r < g.rect.height; ++r)
    for (int64_t c = 0; c < g.rect.width; ++c) {
      const size_t o = size_t(r) * size_t(g.rect.width) + size_t(c);
      const int64_t col = std::clamp<int64_t>(g.rect.col0 + c, 0, p.width - 1);
      const int64_t row = std::clamp<int64_t>(g.rect.row0 + r, 0, p.height - 1);
      const size_t i = size_t(row) * size_t(p.width) + size_t(col);
      const bool sky = is_sky(p, i);
      g.labels[o] = picture_class(params.classes, params.sky_class, p.land_cover[i], p.distance[i]);
      if (params.altitude_range)
        g.altitude[o] = altitude_guide(p.altitude[i], *params.altitude_range);
      if (params.distance_range)
        g.distance[o] = picture_distance(p.distance[i], *params.distance_range);
      if (params.silhouettes)
        g.depth[o] = sky ? std::numeric_limits<float>::infinity() : p.distance[i];
      if (!light.empty()) g.light[o] = light[i];
    }
  return g;
}

PaintedPanorama paint_panorama(const PanoramaPicture& p, const TransferExemplar& exemplar,
                               const PaintParams& params) {
  const bool lit = params.synthesis.w_light > 0;
  if ((params.shading > 0 || lit) && p.shading.size() != size_t(p.width) * size_t(p.height))
    throw Error("paint_panorama: " +
                (lit ? "w_light " + std::to_string(params.synthesis.w_light)
                     : "shading " + std::to_string(params.shading)) +
                " asked of a picture read without its shading band");
  check_haze_colour(p, params);  // before the painting's work, not after it
  // A sky class without pixels would have the sky painted from any class (the land's).
  if (params.sky_class)
    check_class_has_pixels(exemplar, *params.sky_class, params.source + ".sky_class");
  const std::vector<float> light = lit ? panorama_light(p, params) : std::vector<float>();
  const int64_t t = params.tile;
  const int64_t across = (p.width + t - 1) / t, down = (p.height + t - 1) / t;
  std::vector<int32_t> src(size_t(p.width) * size_t(p.height));
  tbb::parallel_for(int64_t(0), across * down, [&](int64_t k) {
    const PixelRect window{k % across * t, k / across * t, std::min(t, p.width - k % across * t),
                           std::min(t, p.height - k / across * t)};
    const std::vector<int32_t> tile = synthesize(
        exemplar.pyramid, panorama_target(p, params, light, window), params.synthesis, window);
    for (int64_t r = 0; r < window.height; ++r)
      std::copy_n(tile.begin() + ptrdiff_t(r * window.width), window.width,
                  src.begin() + ptrdiff_t((window.row0 + r) * p.width + window.col0));
  });

  const ExemplarLevel& e = exemplar.pyramid.levels[0];
  const double reference = params.shading > 0 ? median_shading(p) : 1;
  PaintedPanorama out{p.width, p.height, p.rgb,
                      std::vector<float>(2 * src.size(), std::numeric_limits<float>::quiet_NaN())};
  tbb::parallel_for(size_t(0), src.size(), [&](size_t i) {
    const bool sky = is_sky(p, i);
    if (sky && !params.sky_class) return;
    const double shade =
        sky || params.shading == 0 || std::isnan(p.shading[i])
            ? 1.0
            : 1.0 - params.shading + params.shading * double(p.shading[i]) / reference;
    const size_t s = size_t(src[i]);
    for (size_t k = 0; k < 3; ++k)
      out.rgb[3 * i + k] =
          uint8_t(std::lround(std::clamp(double(e.rgb[3 * s + k]) * 255.0 * shade, 0.0, 255.0)));
    out.source[2 * i] = float(int(s) % e.width * exemplar.scale);
    out.source[2 * i + 1] = float(int(s) / e.width * exemplar.scale);
  });
  if (params.haze_distance > 0) add_haze(p, params.haze_distance, params.haze_color, out);
  blend_skyline(p, params.sky_class.has_value(), out);
  return out;
}

}  // namespace maquette::synthesis
