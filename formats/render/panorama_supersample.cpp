#include "render/panorama_supersample.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "core/srgb.h"
#include "render/strip_drawer.h"

namespace maquette {

namespace {

constexpr double kSampleStripPixels = 1 << 21;  // samples drawn at once

CameraSpec samples_spec(CameraSpec spec, int k) {
  spec.width *= k;
  spec.height *= k;
  return spec;
}

// The samples are coloured without the land-cover guide (the colour does not read it).
PanoramaLook samples_look(PanoramaLook look) {
  look.land_cover = nullptr;
  look.antialias = 1;
  return look;
}

// sRGB bytes in linear light and back (IEC 61966-2-1's transfer function): a byte's linear value,
// and the linear values halfway (in bytes) between two bytes, so that a mean goes back to the
// byte whose interval holds it.
struct LinearLight {
  std::array<float, 256> linear;
  std::array<float, 255> upper;  // upper[b]: between bytes b and b + 1
  LinearLight() {
    auto to_linear = [](double v) { return float(srgb_to_linear(v / 255)); };
    for (int b = 0; b < 256; ++b) linear[size_t(b)] = to_linear(b);
    for (int b = 0; b < 255; ++b) upper[size_t(b)] = to_linear(b + 0.5);
  }
  uint8_t byte(float l) const {
    return uint8_t(std::upper_bound(upper.begin(), upper.end(), l) - upper.begin());
  }
};

const LinearLight& linear_light() {
  static const LinearLight table;
  return table;
}

}  // namespace

struct Supersampler::Parts {
  const Grid& grid;
  TerrainScene& scene;
  const int k;
  const PinholeCamera camera;
  const PanoramaLook look;
  StripDrawer draw;
  PanoramaSamplers samplers;
  Panorama strip;  // the samples of a strip of the picture's rows
  FreshArray<float> texels;
  Parts(const Store& store, const Grid& g, TerrainScene& s, const PinholeCamera& picture,
        const PanoramaLook& picture_look)
      : grid(g),
        scene(s),
        k(picture_look.antialias),
        camera(samples_spec(picture.spec(), k)),
        look(samples_look(picture_look)),
        draw(s, camera),
        samplers(store, g, look) {}
};

Supersampler::Supersampler(const Store& store, const Grid& grid, TerrainScene& scene,
                           const PinholeCamera& camera, const PanoramaLook& look)
    : parts_(std::make_unique<Parts>(store, grid, scene, camera, look)) {}

Supersampler::~Supersampler() = default;

void Supersampler::colour(const BandStretch& stretch, Panorama& p) {
  Parts& s = *parts_;
  const int first = p.first_row, last = p.first_row + p.height;
  resize_fresh(p.coverage, size_t(p.width) * size_t(p.height));  // every pixel written below
  const int k = s.k, w = p.width, sw = k * w;
  const int rows = std::max(1, int(kSampleStripPixels / (double(sw) * k)));
  const LinearLight& light = linear_light();
  for (int top = first; top < last; top += rows) {
    const int bottom = std::min(last, top + rows);
    size_panorama(s.strip, sw, k * top, k * (bottom - top), s.look);
    shade_guides(s.grid, s.scene, s.draw(k * top, k * (bottom - top)), s.camera, s.look, s.samplers,
                 s.strip, s.texels, nullptr);
    s.samplers.forget_unused();
    colour_panorama(s.camera, s.look, stretch, s.texels, s.strip);
    tbb::parallel_for(top, bottom, [&](int row) {
      uint8_t* out = &p.rgb[3 * size_t(row - p.first_row) * size_t(w)];
      const uint8_t* in = &s.strip.rgb[3 * size_t(k * (row - top)) * size_t(sw)];
      const float* distance = &s.strip.distance[size_t(k * (row - top)) * size_t(sw)];
      float* coverage = &p.coverage[size_t(row - p.first_row) * size_t(w)];
      for (int col = 0; col < w; ++col) {
        int terrain = 0;
        for (int j = 0; j < k; ++j)
          for (int i = 0; i < k; ++i)
            terrain += !std::isnan(distance[size_t(j) * size_t(sw) + size_t(k * col + i)]);
        coverage[col] = float(terrain) / float(k * k);
        for (int band = 0; band < 3; ++band) {
          float sum = 0;
          for (int j = 0; j < k; ++j)
            for (int i = 0; i < k; ++i)
              sum += light.linear[in[3 * (size_t(j) * size_t(sw) + size_t(k * col + i)) +
                                     size_t(band)]];
          out[3 * size_t(col) + size_t(band)] = light.byte(sum / float(k * k));
        }
      }
    });
  }
}

}  // namespace maquette
