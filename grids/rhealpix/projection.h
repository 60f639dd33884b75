// The rHEALPix projection of WGS84 (N_side 2, north_square 0, south_square 0, lon_0 0): the
// HEALPix projection of the authalic sphere with its polar triangles rearranged into two squares.
// Points are handled in face-local unit coordinates (u right, v down, both in [0, 1]), computed
// directly from the sphere for precision; the plane is only a translation and scaling of those.
#pragma once

#include <cmath>
#include <numbers>
#include <string>

#include "authalic.h"
#include "core/error.h"
#include "core/grid.h"

namespace maquette {

enum Face { kFaceN = 0, kFaceO, kFaceP, kFaceQ, kFaceR, kFaceS };

struct FacePoint {
  int face = 0;
  double u = 0;  // right, 0..1
  double v = 0;  // down, 0..1
};

// The point at fraction (fu, fv) of the cell's width from its top-left corner.
inline FacePoint cell_point(CellId cell, double fu, double fv) {
  const double n = double(uint64_t(1) << cell.level());
  return {cell.face(), (cell.col() + fu) / n, (cell.row() + fv) / n};
}

class RHealpixProjection {
 public:
  static constexpr double kPi = std::numbers::pi;
  static constexpr double kSqrt3 = std::numbers::sqrt3;

  double radius() const { return authalic_.radius(); }
  const AuthalicLatitude& authalic() const { return authalic_; }

  // Throws maquette::Error for a latitude outside +-90 or a non-finite longitude.
  FacePoint to_face(LonLat p) const {
    if (!(p.lat >= -90 && p.lat <= 90) || !std::isfinite(p.lon)) throw bad_point(p);
    // t in [0, 4) counts quarter turns of longitude from -180 (180 becomes -180). Division, not
    // multiplication by 1/90, so that face edges (multiples of 90) stay exact.
    double t = (p.lon + 180) / 90;
    if (!(t >= 0 && t < 4)) t = wrap_quarters(t);
    const int k = int(t);
    const double frac = t - k;
    const double phi = p.lat * (kPi / 180);
    double sin_beta = 0;
    double cos_beta = 0;
    // cos(pi/2) is not 0 in floating point: keep the poles exactly at the face centres.
    const double cos_phi = std::abs(p.lat) == 90 ? 0 : std::cos(phi);
    authalic_.sin_cos(std::sin(phi), cos_phi, sin_beta, cos_beta);
    if (sin_beta > 2.0 / 3 || sin_beta <= -2.0 / 3) {
      // sigma = sqrt(3 (1 - |sin beta|)) = sqrt(3) cos beta / sqrt(1 + |sin beta|), which has
      // no cancellation near the poles.
      const double sigma = kSqrt3 * std::abs(cos_beta) / std::sqrt(1 + std::abs(sin_beta));
      const double a = (frac - 0.5) * sigma;
      const double h = 0.5 * sigma;
      // Rotate the unrotated offset (a, -h) by k quarter turns counter-clockwise (y up).
      static constexpr double kUa[4] = {1, 0, -1, 0}, kUh[4] = {0, 1, 0, -1};
      static constexpr double kVa[4] = {0, -1, 0, 1}, kVh[4] = {1, 0, -1, 0};
      const double du = kUa[k] * a + kUh[k] * h;
      const double dv = kVa[k] * a + kVh[k] * h;
      return sin_beta > 0 ? FacePoint{kFaceN, 0.5 + du, 0.5 + dv}
                          : FacePoint{kFaceS, 0.5 + du, 0.5 - dv};
    }
    return {kFaceO + k, frac, 0.5 - 0.75 * sin_beta};
  }

  LonLat from_face(FacePoint p) const;
  PlanePoint to_plane(FacePoint p) const;
  // Throws maquette::Error for a point outside the six squares.
  FacePoint from_plane(PlanePoint p) const;

  // Geodetic latitude (degrees) of the points of a polar face at Chebyshev distance `r` (face
  // widths) from its centre.
  double polar_latitude(int face, double r) const;

 private:
  static double wrap_quarters(double t);
  static Error bad_point(LonLat p);

  AuthalicLatitude authalic_;
};

}  // namespace maquette
