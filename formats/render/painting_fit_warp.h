// The residual warp of a painting fit (issue 19): what the camera and bend leave of the clicks'
// errors, taken away by a thin-plate spline of the picture plane. It moves where the fitted camera
// draws a point (picture coordinates) to where the painting shows it, so a painter's own
// distortions (a valley widened, a peak moved) follow the clicks.
//
// The spline: displacement(p) = a0 + a1 x + a2 y + sum_i w_i U(|p - c_i|), U(r) = r^2 log r, in
// coordinates divided by the painting's larger side; its weights solve the thin-plate system with
// `smoothing` lambda added to the kernel's diagonal (0: the spline moves every centre exactly onto
// its target; larger: smoother, the noise of the clicks left in place).
#pragma once

#include <array>
#include <vector>

namespace maquette {

using PicturePoint = std::array<double, 2>;

class PictureWarp {
 public:
  // The identity.
  PictureWarp() = default;
  // Moves `from[i]` towards `to[i]`. Throws maquette::Error when the sizes differ or the points
  // are too few or collinear for the spline (fewer than 3, or a singular system). `scale`: the
  // painting's larger side (pixels), > 0; `smoothing` >= 0.
  PictureWarp(const std::vector<PicturePoint>& from, const std::vector<PicturePoint>& to,
              double scale, double smoothing);

  PicturePoint operator()(const PicturePoint& p) const;

  const std::vector<PicturePoint>& centres() const { return centres_; }
  // Per centre, the (x, y) weights; then the affine part's (x, y) for 1, x and y.
  const std::vector<PicturePoint>& weights() const { return weights_; }
  const std::array<PicturePoint, 3>& affine() const { return affine_; }
  double scale() const { return scale_; }

 private:
  std::vector<PicturePoint> centres_, weights_;  // centres in pixels
  std::array<PicturePoint, 3> affine_{};
  double scale_ = 1;
};

}  // namespace maquette
