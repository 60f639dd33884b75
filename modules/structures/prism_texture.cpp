#include "prism_texture.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>

namespace maquette::structures {

Vec2 FacetFrame::uv(const Vec3& p) const {
  return {(p - origin).dot(u) / extent_u, 1 - (p - origin).dot(v) / extent_v};
}

Vec3 FacetFrame::point(double s, double t) const {
  return origin + s * extent_u * u + (1 - t) * extent_v * v;
}

FacetFrame facet_frame(const PrismFacet& facet) {
  FacetFrame f;
  f.u = (facet.corners[1] - facet.corners[0]).normalized();
  f.v = facet.normal.cross(f.u);
  double lo_u = std::numeric_limits<double>::max(), lo_v = lo_u, hi_u = -lo_u, hi_v = -lo_u;
  for (const Vec3& q : facet.corners) {
    const double a = (q - facet.corners[0]).dot(f.u), b = (q - facet.corners[0]).dot(f.v);
    lo_u = std::min(lo_u, a), hi_u = std::max(hi_u, a);
    lo_v = std::min(lo_v, b), hi_v = std::max(hi_v, b);
  }
  f.origin = facet.corners[0] + lo_u * f.u + lo_v * f.v;
  f.extent_u = hi_u - lo_u;
  f.extent_v = hi_v - lo_v;
  return f;
}

cv::Mat rectified_texture(const cv::Mat& photo, const PinholeCamera& camera,
                          const PrismFacet& facet, int max_texels) {
  const FacetFrame f = facet_frame(facet);
  // The bounding box's corners in the photo: (s, t) = (0, 0), (1, 0), (1, 1), (0, 1).
  const std::array<Vec2, 4> st{Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0, 1)};
  std::array<Vec2, 4> pixel;
  for (size_t i = 0; i < 4; ++i) pixel[i] = camera.project(f.point(st[i].x(), st[i].y()));
  const double along_u = std::max((pixel[1] - pixel[0]).norm(), (pixel[2] - pixel[3]).norm());
  const double along_v = std::max((pixel[3] - pixel[0]).norm(), (pixel[2] - pixel[1]).norm());
  const double per_metre = std::max(along_u / f.extent_u, along_v / f.extent_v);
  const double shrink = std::min(1.0, max_texels / (per_metre * std::max(f.extent_u, f.extent_v)));
  const int width = std::max(2, int(std::lround(per_metre * shrink * f.extent_u)));
  const int height = std::max(2, int(std::lround(per_metre * shrink * f.extent_v)));
  std::vector<cv::Point2f> from, to;
  for (size_t i = 0; i < 4; ++i) {
    // Texel centres at integers here (OpenCV), at (x + 0.5) / width in texture coordinates.
    from.emplace_back(float(st[i].x() * width - 0.5), float(st[i].y() * height - 0.5));
    to.emplace_back(float(pixel[i].x()), float(pixel[i].y()));
  }
  // Texels to pixels: warpPerspective then samples the photo at each texel's pixel.
  const cv::Mat texel_to_pixel = cv::getPerspectiveTransform(from, to);
  cv::Mat texture;
  cv::warpPerspective(photo, texture, texel_to_pixel, cv::Size(width, height),
                      cv::INTER_LINEAR | cv::WARP_INVERSE_MAP, cv::BORDER_REPLICATE);
  return texture;
}

}  // namespace maquette::structures
