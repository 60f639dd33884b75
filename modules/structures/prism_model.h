// structures.prism's model: the prism with its facade textures as a model layer's mesh
// (store/README.md "Model layers": metres, x and y horizontal, z up, the base at z = 0), written
// as a GLB that `maquette ingest --as model` reads.
#pragma once

#include <opencv2/core.hpp>
#include <string>

#include "content/content.h"
#include "prism_solver.h"

namespace maquette::structures {

struct PrismModelOptions {
  // The model's height (its vertical extent), metres: the photo gives the shape up to scale.
  double height_m = 10;
  int max_texels = 1024;  // per texture side (prism_texture.h)
};

// The model of `prism` seen in `photo` by `camera`: one object per facet (the profile, the far
// cap, the sides), each textured from the photo when visible (rectified_texture, JPEG), from its
// symmetry source when hidden (texture_sources), plain grey when it has none. Vertical: the axis
// of the prism (the corner's two profile edges, the extrusion) whose direction in the photo points
// most nearly up (the camera's -y), turned to +z; x along the next of those axes. Base on z = 0,
// scaled to options.height_m, the model's origin at the centre of its base's bounding box.
MeshContent prism_model(const PrismSolution& prism, const cv::Mat& photo,
                        const PinholeCamera& camera, const PrismModelOptions& options = {});

}  // namespace maquette::structures
