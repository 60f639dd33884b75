// structures.prism's facade textures: each visible facet rectified from the photo by the
// homography between its plane and the image (paper 002 §7.3).
#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "prism_facets.h"

namespace maquette::structures {

// A facet's texture frame: texel (s, t) of a width x height image shows the facet's point
//   origin + (s / width) * extent_u * u + (1 - t / height) * extent_v * v
// (u along its first edge, v = normal x u, t down from the image's top as glTF's uvs).
struct FacetFrame {
  Vec3 origin, u, v;  // origin: the bounding box's corner of least u and v
  double extent_u = 0, extent_v = 0;
  Vec2 uv(const Vec3& point) const;      // glTF texture coordinates of a point of the facet
  Vec3 point(double s, double t) const;  // s, t in 0..1 across the texture
};

FacetFrame facet_frame(const PrismFacet& facet);

// The facet as the photo shows it, rectified: the image warped by the homography from texels to
// pixels (OpenCV warpPerspective, bilinear, the photo's border replicated where the facet leaves
// it). Texels per metre: those of the facet's least foreshortened side in the photo (its longest
// projected edge of the bounding box, in pixels, over its length), at most `max_texels` along
// either side. Precondition: the facet is in front of the camera.
cv::Mat rectified_texture(const cv::Mat& photo, const PinholeCamera& camera,
                          const PrismFacet& facet, int max_texels = 1024);

}  // namespace maquette::structures
