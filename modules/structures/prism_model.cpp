#include "prism_model.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/imgcodecs.hpp>

#include "footprint.h"
#include "prism_facets.h"
#include "prism_texture.h"
#include "roof_triangulation.h"

namespace maquette::structures {
namespace {

// The axes of the model's frame in the solution's (camera) frame: rows x, y, z (up).
Eigen::Matrix3d model_axes(const PrismSolution& prism) {
  const size_t n = prism.profile.size();
  const Vec3 corner = prism.profile[size_t(prism.corner)];
  const std::array<Vec3, 3> axes{
      (prism.profile[(size_t(prism.corner) + n - 1) % n] - corner).normalized(),
      (prism.profile[(size_t(prism.corner) + 1) % n] - corner).normalized(),
      prism.extrusion.normalized()};
  size_t up = 0;
  for (size_t i = 1; i < 3; ++i)
    if (std::abs(axes[i].y()) > std::abs(axes[up].y())) up = i;
  const Vec3 z = axes[up].y() < 0 ? axes[up] : Vec3(-axes[up]);  // camera y is down
  const Vec3 x = axes[(up + 1) % 3];
  Eigen::Matrix3d m;
  m.row(0) = x;
  m.row(1) = z.cross(x);
  m.row(2) = z;
  return m;
}

// A facet's triangles, counter-clockwise seen from outside, as indices into its corners, the facet
// scaled by `scale` (to metres: make_footprint refuses rings of almost no area).
std::vector<uint32_t> facet_triangles(const PrismFacet& facet, double scale) {
  const Vec3 u = (facet.corners[1] - facet.corners[0]).normalized();
  const Vec3 v = facet.normal.cross(u);
  PlaneRing ring;
  for (const Vec3& q : facet.corners)
    ring.push_back({scale * (q - facet.corners[0]).dot(u), scale * (q - facet.corners[0]).dot(v)});
  // make_footprint keeps the ring's points in their order (one ring, counter-clockwise in u, v).
  return triangulate_footprint(make_footprint({ring}));
}

}  // namespace

MeshContent prism_model(const PrismSolution& prism, const cv::Mat& photo,
                        const PinholeCamera& camera, const PrismModelOptions& options) {
  const std::vector<PrismFacet> facets = prism_facets(prism);
  const std::vector<bool> visible = visible_facets(facets);
  const std::vector<int> source = texture_sources(facets, visible);
  const Eigen::Matrix3d axes = model_axes(prism);
  // Model coordinates before the shift and scale.
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::max()), hi = -lo;
  for (const PrismFacet& f : facets)
    for (const Vec3& q : f.corners) lo = lo.cwiseMin(axes * q), hi = hi.cwiseMax(axes * q);
  const double scale = options.height_m / (hi.z() - lo.z());
  const Vec3 origin((lo.x() + hi.x()) / 2, (lo.y() + hi.y()) / 2, lo.z());

  MeshContent model;
  std::vector<int> material(facets.size(), -1);
  for (size_t i = 0; i < facets.size(); ++i) {
    if (!visible[i]) continue;
    Material m;
    m.name = "facet " + std::to_string(i);
    std::vector<uchar> jpeg;
    cv::imencode(".jpg", rectified_texture(photo, camera, facets[i], options.max_texels), jpeg,
                 {cv::IMWRITE_JPEG_QUALITY, 90});
    m.image.assign(jpeg.begin(), jpeg.end());
    m.image_mime = "image/jpeg";
    material[i] = int(model.materials.size());
    model.materials.push_back(std::move(m));
  }
  int grey = -1;
  for (size_t i = 0; i < facets.size(); ++i) {
    MeshObject object;
    object.provenance.tool = "prism";
    object.material = source[i] >= 0 ? material[size_t(source[i])] : -1;
    if (object.material < 0) {
      if (grey < 0) {
        grey = int(model.materials.size());
        Material m;
        m.name = "no texture";
        m.base_colour = {0.6f, 0.6f, 0.6f, 1};
        model.materials.push_back(m);
      }
      object.material = grey;
    }
    const FacetFrame frame = facet_frame(facets[i]);
    const Vec3 normal = axes * facets[i].normal;
    for (const Vec3& q : facets[i].corners) {
      const Vec3 p = scale * (axes * q - origin);
      const Vec2 uv = frame.uv(q);
      object.positions.insert(object.positions.end(), {float(p.x()), float(p.y()), float(p.z())});
      object.normals.insert(object.normals.end(),
                            {float(normal.x()), float(normal.y()), float(normal.z())});
      if (object.material != grey)
        object.uvs.insert(object.uvs.end(), {float(uv.x()), float(uv.y())});
    }
    object.indices = facet_triangles(facets[i], scale);
    model.objects.push_back(std::move(object));
  }
  return model;
}

}  // namespace maquette::structures
