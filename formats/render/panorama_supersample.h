// Anti-aliasing by supersampling (PanoramaLook::antialias K > 1): each pixel's colour is the mean,
// in linear light (sRGB's transfer function, IEC 61966-2-1), of K x K samples on a regular grid
// over the pixel, each coloured as render/panorama.h colours a pixel of the picture drawn K times
// wider and higher from the same eye, with the same mesh (the DEM's levels chosen for the
// picture's pixels) and the picture's display stretch. The terrain's edges against the sky and
// near ridges against far ground get each side's share of the pixel; within the surface the
// texture is box-filtered over the pixel (read at the level a sample's footprint needs). The
// guides and silhouettes stay those of the pixel's centre. A pixel's colour depends on its own
// samples alone: the same bits for any strips and threads. Cost: the colour of K^2 samples a pixel
// (each sample rasterized and shaded as a pixel is), drawn in strips of about 2 M samples.
#pragma once

#include <memory>

#include "core/grid.h"
#include "render/panorama.h"
#include "store/store.h"

namespace maquette {

class Supersampler {
 public:
  // The samples' camera: `camera`'s spec K times wider and higher. Preconditions: look.antialias
  // >= 2, and camera's width and height times it at most 65536 (render/camera.h; the job checks
  // it). `scene` gets the attributes of the vertices the samples show; it, `store`, `grid` and
  // look's layers must outlive this.
  Supersampler(const Store& store, const Grid& grid, TerrainScene& scene,
               const PinholeCamera& camera, const PanoramaLook& look);
  ~Supersampler();
  Supersampler(const Supersampler&) = delete;
  Supersampler& operator=(const Supersampler&) = delete;

  // Replaces the colours of every row of `p` (the picture, or a strip of it) with the means of
  // their samples, coloured with `stretch`, the picture's display stretch, and sizes and writes
  // its coverage (Panorama::coverage: the share of each pixel's samples that see terrain).
  void colour(const BandStretch& stretch, Panorama& p);

 private:
  struct Parts;
  std::unique_ptr<Parts> parts_;
};

}  // namespace maquette
