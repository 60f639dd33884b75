// structures.prism's textures and model against the synthetic photos: a photo painted by casting
// each pixel's ray onto the true prism (colour = position on its profile), rectified back by the
// homography; the model's frame, scale and GLB read back by the model ingest's reader.
#include "../prism_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>

#include "../prism_facets.h"
#include "../prism_texture.h"
#include "core/output_file.h"
#include "gltf/gltf_model.h"
#include "gltf/mesh_glb.h"
#include "prism_synthetic.h"

namespace maquette::structures {
namespace {

// The colour of a point (x, 0, z) of the profile's plane: blue 0, green x / 30 m, red z / 40 m
// (BGR), saturating.
cv::Vec3b profile_colour(double x, double z) {
  return {0, cv::saturate_cast<uchar>(255 * x / 30), cv::saturate_cast<uchar>(255 * z / 40)};
}

// The photo of the true profile plane y = 0 (every pixel whose ray meets it in front).
cv::Mat painted_photo(const SyntheticPhoto& p) {
  cv::Mat photo(p.height, p.width, CV_8UC3, cv::Scalar(255, 255, 255));
  const Vec3 centre = p.camera_centre();
  for (int row = 0; row < p.height; ++row)
    for (int col = 0; col < p.width; ++col) {
      const Vec3 ray = p.rotation.transpose() * p.camera.ray(Vec2(col, row));
      const double t = -centre.y() / ray.y();
      if (t <= 0) continue;
      const Vec3 hit = centre + t * ray;
      photo.at<cv::Vec3b>(row, col) = profile_colour(hit.x(), hit.z());
    }
  return photo;
}

TEST(PrismTexture, RectifiedProfileShowsItsOwnPoints) {
  for (int k = 0; k < 20; ++k) {
    const SyntheticPhoto p = synthetic_photo(20261129, k, 0);
    const PrismSolution s = solve_prism(p.exact, p.camera, "photo");
    const PrismFacet profile = prism_facets(s)[0];
    const cv::Mat texture = rectified_texture(painted_photo(p), p.camera, profile);
    const FacetFrame frame = facet_frame(profile);
    const double depth = (p.rotation * p.profile[0] + p.translation).z();
    double sum = 0;
    int n = 0;
    for (int t = 2; t < texture.rows - 2; t += 3)
      for (int c = 2; c < texture.cols - 2; c += 3) {
        // The texel's point, back in the world (the solver's frame is the camera's over depth).
        const Vec3 solver = frame.point((c + 0.5) / texture.cols, (t + 0.5) / texture.rows);
        const Vec3 world = p.rotation.transpose() * (depth * solver - p.translation);
        const cv::Vec3b want = profile_colour(world.x(), world.z()),
                        got = texture.at<cv::Vec3b>(t, c);
        sum += std::abs(int(want[1]) - int(got[1])) + std::abs(int(want[2]) - int(got[2]));
        n += 2;
      }
    // Bilinear sampling of a linear ramp: off by the rounding and the ramp's curvature in pixels.
    EXPECT_LT(sum / n, 2.0) << "photo " << k << ", texture " << texture.cols << " x "
                            << texture.rows;
  }
}

TEST(PrismModel, MetresZUpBaseOnTheGroundAndReadByTheModelIngest) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "maquette_prism_model";
  std::filesystem::create_directories(dir);
  for (int k = 0; k < 10; ++k) {
    const SyntheticPhoto p = synthetic_photo(20261129, k, 0);
    const PrismSolution s = solve_prism(p.exact, p.camera, "photo");
    PrismModelOptions options;
    options.height_m = 17;
    const MeshContent model = prism_model(s, painted_photo(p), p.camera, options);
    ASSERT_EQ(model.objects.size(), p.profile.size() + 2);
    // The truth's extents: profile width w (x), height (z), extrusion (y); the model's vertical
    // is the profile's up edge, scaled to 17 m.
    double w = 0, h = 0;
    for (const Vec3& q : p.profile) w = std::max(w, q.x()), h = std::max(h, q.z());
    const double scale = 17 / h;
    Vec3 lo = Vec3::Constant(1e9), hi = -lo;
    size_t triangles = 0;
    for (const MeshObject& o : model.objects) {
      triangles += o.indices.size() / 3;
      for (size_t i = 0; i < o.positions.size(); i += 3) {
        const Vec3 q(o.positions[i], o.positions[i + 1], o.positions[i + 2]);
        lo = lo.cwiseMin(q), hi = hi.cwiseMax(q);
      }
    }
    EXPECT_NEAR(lo.z(), 0, 1e-5);
    EXPECT_NEAR(hi.z(), 17, 1e-4);
    const double across = std::max(hi.x() - lo.x(), hi.y() - lo.y());
    const double along = std::min(hi.x() - lo.x(), hi.y() - lo.y());
    EXPECT_NEAR(across, scale * std::max(w, p.length), 1e-3 * across) << "photo " << k;
    EXPECT_NEAR(along, scale * std::min(w, p.length), 1e-3 * across) << "photo " << k;
    // Written as a GLB, read back as `maquette ingest --as model` reads it.
    const std::string path = (dir / ("prism" + std::to_string(k) + ".glb")).string();
    const std::string glb = encode_mesh_glb(model);
    write_file_whole(path, glb);
    const MeshContent back = read_gltf_model(path);
    size_t back_triangles = 0, textured = 0;
    Vec3 back_lo = Vec3::Constant(1e9), back_hi = -back_lo;
    for (const MeshObject& o : back.objects) {
      back_triangles += o.indices.size() / 3;
      for (size_t i = 0; i < o.positions.size(); i += 3) {
        const Vec3 q(o.positions[i], o.positions[i + 1], o.positions[i + 2]);
        back_lo = back_lo.cwiseMin(q), back_hi = back_hi.cwiseMax(q);
      }
    }
    for (const Material& m : back.materials) textured += !m.image.empty();
    EXPECT_EQ(back_triangles, triangles);
    EXPECT_LT((back_lo - lo).cwiseAbs().maxCoeff(), 1e-3);
    EXPECT_LT((back_hi - hi).cwiseAbs().maxCoeff(), 1e-3);
    const std::vector<bool> visible = visible_facets(prism_facets(s));
    EXPECT_EQ(textured, size_t(std::count(visible.begin(), visible.end(), true)));
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace maquette::structures
