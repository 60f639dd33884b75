// maquette-prism: structures.prism as a program (README.md "structures.prism"): clicks in a photo
// to a textured model GLB for `maquette ingest --as model`. A program, not an operator: operators
// write cells (rasters, meshes, instances, volumes), and a model layer is in no cell.
//   maquette-prism STROKES.json MODEL.glb [--picture PICTURE.png]
#include <algorithm>
#include <array>
#include <cstdio>
#include <exception>
#include <iostream>
#include <opencv2/imgcodecs.hpp>
#include <string>

#include "core/error.h"
#include "core/output_file.h"
#include "gltf/mesh_glb.h"
#include "prism_facets.h"
#include "prism_model.h"
#include "prism_photo.h"
#include "prism_picture.h"
#include "prism_strokes.h"

using namespace maquette;
using namespace maquette::structures;

int main(int argc, char** argv) {
  const std::string usage = "usage: maquette-prism STROKES.json MODEL.glb [--picture PICTURE.png]";
  if (argc != 3 && !(argc == 5 && std::string(argv[3]) == "--picture")) {
    std::cerr << usage << "\n";
    return 2;
  }
  try {
    const PrismStrokes strokes = read_prism_strokes(argv[1]);
    const Photo photo = read_photo(strokes.photo);
    PinholeCamera camera;
    camera.principal = Vec2(photo.pixels.cols / 2.0, photo.pixels.rows / 2.0);
    const char* focal_from = strokes.focal_px ? "strokes" : photo.focal_px ? "EXIF" : "estimated";
    camera.focal_px = strokes.focal_px ? *strokes.focal_px
                      : photo.focal_px ? *photo.focal_px
                                       : prior_focal_px(photo.pixels.cols, photo.pixels.rows);
    const PrismSolution prism =
        solve_prism(strokes.clicks, camera, argv[1], !strokes.focal_px && !photo.focal_px);
    camera.focal_px = prism.focal_px;
    PrismModelOptions options;
    options.height_m = strokes.height_m;
    const MeshContent model = prism_model(prism, photo.pixels, camera, options);
    write_file_whole(argv[2], encode_mesh_glb(model));
    const std::vector<bool> visible = visible_facets(prism_facets(prism));
    std::array<float, 3> lo{1e30f, 1e30f, 1e30f}, hi{-1e30f, -1e30f, -1e30f};
    for (const MeshObject& o : model.objects)
      for (size_t i = 0; i < o.positions.size(); ++i)
        lo[i % 3] = std::min(lo[i % 3], o.positions[i]),
               hi[i % 3] = std::max(hi[i % 3], o.positions[i]);
    std::printf("model %.2f x %.2f x %.2f m (x, y, z up)\n", hi[0] - lo[0], hi[1] - lo[1],
                hi[2] - lo[2]);
    std::printf(
        "%s: focal length %.1f px (%s), %d roots of Eq. 9 in front of the camera, %s, "
        "%zu facets (%zd visible), reprojection rms %.2f px\n",
        argv[2], camera.focal_px, focal_from, prism.roots,
        prism.refined ? "refined by least squares" : "exact (minimal clicks)", visible.size(),
        std::count(visible.begin(), visible.end(), true),
        std::sqrt(prism.residual_px2 / double(strokes.clicks.profile.size() + 1 +
                                              strokes.clicks.more_extrusions.size())));
    if (argc == 5) {
      const cv::Mat picture = picture_of_model(model, 1000, 700, 225, 20);
      if (!cv::imwrite(argv[4], picture)) throw Error(std::string(argv[4]) + ": cannot be written");
    }
  } catch (const std::exception& e) {
    std::cerr << "maquette-prism: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
