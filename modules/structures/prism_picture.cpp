#include "prism_picture.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

namespace maquette::structures {

cv::Mat picture_of_model(const MeshContent& model, int width, int height, double azimuth_deg,
                         double elevation_deg) {
  using V3 = Eigen::Vector3d;
  V3 lo = V3::Constant(1e300), hi = -lo;
  for (const MeshObject& o : model.objects)
    for (size_t i = 0; i < o.positions.size(); i += 3) {
      const V3 p(o.positions[i], o.positions[i + 1], o.positions[i + 2]);
      lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    }
  const V3 target = (lo + hi) / 2;
  const double radius = (hi - lo).norm() / 2;
  const double az = azimuth_deg * std::numbers::pi / 180,
               el = elevation_deg * std::numbers::pi / 180;
  const double focal = width / 2.0 / std::tan(25 * std::numbers::pi / 180);
  // The bounding sphere within the narrower of the two fields of view.
  const double half_view =
      std::atan(std::tan(25 * std::numbers::pi / 180) * std::min(1.0, double(height) / width));
  const V3 eye =
      target + 1.15 * radius / std::sin(half_view) *
                   V3(std::sin(az) * std::cos(el), std::cos(az) * std::cos(el), std::sin(el));
  const V3 forward = (target - eye).normalized();
  const V3 right = forward.cross(V3::UnitZ()).normalized();
  const V3 down = forward.cross(right);
  const auto to_camera = [&](const V3& p) {
    return V3((p - eye).dot(right), (p - eye).dot(down), (p - eye).dot(forward));
  };
  const auto to_pixel = [&](const V3& c) {
    return cv::Point2f(float(width / 2.0 + focal * c.x() / c.z()),
                       float(height / 2.0 + focal * c.y() / c.z()));
  };
  // Facets facing the eye, farthest first.
  std::vector<std::pair<double, size_t>> order;
  for (size_t k = 0; k < model.objects.size(); ++k) {
    const MeshObject& o = model.objects[k];
    V3 centre = V3::Zero();
    const size_t n = o.positions.size() / 3;
    for (size_t i = 0; i < n; ++i)
      centre += V3(o.positions[3 * i], o.positions[3 * i + 1], o.positions[3 * i + 2]) / double(n);
    const V3 normal(o.normals[0], o.normals[1], o.normals[2]);
    if (normal.dot(eye - centre) > 0) order.push_back({-to_camera(centre).z(), k});
  }
  std::sort(order.begin(), order.end());
  cv::Mat picture(height, width, CV_8UC3, cv::Scalar(255, 255, 255));
  for (const auto& [depth, k] : order) {
    const MeshObject& o = model.objects[k];
    std::vector<cv::Point2f> at, texel;
    std::vector<cv::Point> outline;
    const Material& m = model.materials[size_t(o.material)];
    const cv::Mat texture = m.image.empty()
                                ? cv::Mat()
                                : cv::imdecode(cv::Mat(1, int(m.image.size()), CV_8UC1,
                                                       const_cast<char*>(m.image.data())),
                                               cv::IMREAD_COLOR);
    for (size_t i = 0; i < o.positions.size() / 3; ++i) {
      const cv::Point2f p = to_pixel(
          to_camera(V3(o.positions[3 * i], o.positions[3 * i + 1], o.positions[3 * i + 2])));
      at.push_back(p);
      outline.emplace_back(int(std::lround(p.x)), int(std::lround(p.y)));
      if (!texture.empty())
        texel.emplace_back(o.uvs[2 * i] * float(texture.cols),
                           o.uvs[2 * i + 1] * float(texture.rows));
    }
    cv::Mat mask = cv::Mat::zeros(height, width, CV_8UC1);
    cv::fillPoly(mask, std::vector<std::vector<cv::Point>>{outline}, 255, cv::LINE_AA);
    if (texture.empty() || at.size() < 4) {
      const auto& c = m.base_colour;
      picture.setTo(cv::Scalar(255 * c[2], 255 * c[1], 255 * c[0]), mask);
    } else {
      const cv::Mat h = cv::findHomography(texel, at);
      cv::Mat warped;
      cv::warpPerspective(texture, warped, h, picture.size(), cv::INTER_LINEAR);
      warped.copyTo(picture, mask);
    }
    cv::polylines(picture, std::vector<std::vector<cv::Point>>{outline}, true,
                  cv::Scalar(60, 60, 60), 1, cv::LINE_AA);
  }
  return picture;
}

}  // namespace maquette::structures
