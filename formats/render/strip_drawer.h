// The fragments of a picture's strips drawn one after the other into one strip's arrays, each
// strip's vertices given their attributes (render/terrain_scene.h attribute_vertices) before it is
// shaded, from one plan of the mesh (render/rasterizer.h RasterPlan): a render/panorama.h DrawRows.
#pragma once

#include "render/rasterizer.h"
#include "render/terrain_scene.h"

namespace maquette {

class StripDrawer {
 public:
  StripDrawer(TerrainScene& scene, const PinholeCamera& camera)
      : scene_(scene), plan_(scene.mesh, camera) {}
  // The picture's rows [first, first + rows); valid until the next call.
  const Fragments& operator()(int first, int rows) {
    rasterize(plan_, first, rows, fragments_);
    attribute_vertices(scene_, &fragments_);
    return fragments_;
  }

 private:
  TerrainScene& scene_;
  const RasterPlan plan_;
  Fragments fragments_;
};

}  // namespace maquette
