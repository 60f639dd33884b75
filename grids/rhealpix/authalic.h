// The authalic latitude of WGS84 as Fourier series in the geodetic latitude and back:
//   beta = phi + sum_k c_k sin(2k phi),   phi = beta + sum_k d_k sin(2k beta),
// summed with Clenshaw's recurrence. The coefficients decay like n^k (n ~ 0.00168, the third
// flattening), so kTerms = 6 reaches double precision; they are computed once by a discrete sine
// transform of GeographicLib's exact AuthalicLatitude / InverseAuthalicLatitude.
#pragma once

#include <array>
#include <cstddef>

namespace maquette {

class AuthalicLatitude {
 public:
  static constexpr int kTerms = 6;
  using Coefficients = std::array<double, kTerms>;

  AuthalicLatitude();

  double radius() const { return radius_; }  // authalic radius R_A of WGS84, metres

  // Radians to radians.
  double authalic(double phi) const;
  double geodetic(double beta) const;

  // sin and cos of the authalic latitude from sin and cos of the geodetic one, with no further
  // trigonometric call: beta - phi is below 0.0023, so short Taylor series of its sine and
  // cosine are exact to double precision. cos beta keeps full relative precision near the poles.
  void sin_cos(double sin_phi, double cos_phi, double& sin_beta, double& cos_beta) const {
    const double d =
        series(forward_, 2 * sin_phi * cos_phi, (cos_phi - sin_phi) * (cos_phi + sin_phi));
    const double d2 = d * d;
    const double sin_d = d * (1 - d2 / 6 * (1 - d2 / 20));
    const double one_minus_cos_d = d2 / 2 * (1 - d2 / 12);
    // Small corrections added last, so the results round about once.
    sin_beta = sin_phi + (cos_phi * sin_d - sin_phi * one_minus_cos_d);
    cos_beta = cos_phi - (sin_phi * sin_d + cos_phi * one_minus_cos_d);
  }

 private:
  // sum_k c_k sin(2k x) from sin(2x) and cos(2x).
  static double series(const Coefficients& c, double sin2, double cos2) {
    double b1 = 0;
    double b2 = 0;
    for (int k = kTerms - 1; k >= 0; --k) {
      const double b0 = c[size_t(k)] + 2 * cos2 * b1 - b2;
      b2 = b1;
      b1 = b0;
    }
    return b1 * sin2;
  }

  Coefficients forward_{};
  Coefficients inverse_{};
  double radius_ = 0;
};

}  // namespace maquette
