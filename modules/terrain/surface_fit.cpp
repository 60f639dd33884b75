#include "surface_fit.h"

#include <Eigen/Dense>
#include <cmath>

namespace maquette::terrain {
namespace {

constexpr std::array<double, 9> kHornWeights = {1, 2, 1, 2, 0, 2, 1, 2, 1};

}  // namespace

Gradient fit_gradient(const Neighbourhood& n, const Heights& h) {
  // Centred on the weighted mean offset, the plane's slope decouples from its intercept.
  double se = 0, sn = 0, sw = 0;
  for (int i = 0; i < 9; ++i) {
    se += kHornWeights[i] * n.east[i];
    sn += kHornWeights[i] * n.north[i];
    sw += kHornWeights[i];
  }
  const double me = se / sw, mn = sn / sw;
  double ee = 0, en = 0, nn = 0, eh = 0, nh = 0;
  for (int i = 0; i < 9; ++i) {
    const double w = kHornWeights[i], de = n.east[i] - me, dn = n.north[i] - mn;
    // Differences to the centre make a constant field give exactly zero.
    const double dh = h[i] - h[4];
    ee += w * de * de, en += w * de * dn, nn += w * dn * dn;
    eh += w * de * dh, nh += w * dn * dh;
  }
  const double det = ee * nn - en * en;
  return {(nn * eh - en * nh) / det, (ee * nh - en * eh) / det};
}

Quadratic fit_quadratic(const Neighbourhood& n, const Heights& h) {
  // Offsets scaled to about one pixel keep the normal equations well conditioned.
  double scale = 0;
  for (int i = 0; i < 9; ++i) scale += n.east[i] * n.east[i] + n.north[i] * n.north[i];
  scale = std::sqrt(scale / 8);
  Eigen::Matrix<double, 9, 6> a;
  Eigen::Matrix<double, 9, 1> b;
  for (int i = 0; i < 9; ++i) {
    const double x = n.east[i] / scale, y = n.north[i] / scale;
    a.row(i) << 1, x, y, x * x / 2, x * y, y * y / 2;
    b(i) = h[i] - h[4];
  }
  const Eigen::Matrix<double, 6, 1> c = (a.transpose() * a).ldlt().solve(a.transpose() * b);
  const double s2 = scale * scale;
  return {{c(1) / scale, c(2) / scale}, {c(3) / s2, c(4) / s2, c(5) / s2}};
}

}  // namespace maquette::terrain
