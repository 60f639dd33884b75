#include "projection.h"

#include <algorithm>
#include <array>
#include <optional>
#include <utility>

namespace maquette {
namespace {

constexpr double kPi = RHealpixProjection::kPi;
constexpr double kRadToDeg = 180 / kPi;

// The faces in the 4 x 3 layout of the plane (columns from x = -pi, rows from y = 3 pi / 4).
constexpr std::array<int, 6> kLayoutCol = {0, 0, 1, 2, 3, 0};
constexpr std::array<int, 6> kLayoutRow = {0, 1, 1, 1, 1, 2};

std::optional<int> face_at(double col, double row) {
  if (row == 1 && col >= 0 && col <= 3) return kFaceO + int(col);
  if (col == 0 && row == 0) return kFaceN;
  if (col == 0 && row == 2) return kFaceS;
  return std::nullopt;
}

// Left and top edge of a face in the plane, in units of the authalic radius.
double face_x_min(int face) { return -kPi + kLayoutCol[size_t(face)] * kPi / 2; }
double face_y_max(int face) { return 3 * kPi / 4 - kLayoutRow[size_t(face)] * kPi / 2; }

// A polar face point relative to the face centre, in face widths, y up, north-equivalent (the
// south face is the mirror image of the north one in y): quarter k of the longitudes, offset dx
// along and dy (<= 0) across it in the unrotated frame.
struct PolarOffset {
  int k = 0;
  double dx = 0;
  double dy = 0;
};

PolarOffset polar_offset(int face, double u, double v) {
  const double x = u - 0.5;
  const double y = face == kFaceN ? 0.5 - v : v - 0.5;
  // The quarter of longitudes is the triangle of the square (bottom, right, top, left) holding
  // the point; undo its rotation (points on a diagonal have the same longitude either way).
  if (-y >= std::abs(x)) return {0, x, y};
  if (x >= std::abs(y)) return {1, y, -x};
  if (y >= std::abs(x)) return {2, -x, -y};
  return {3, -y, x};
}

}  // namespace

double RHealpixProjection::wrap_quarters(double t) {
  t = std::fmod(t, 4.0);
  if (t < 0) t += 4;
  return t < 4 ? t : 0;  // t + 4 may round up to 4
}

Error RHealpixProjection::bad_point(LonLat p) {
  return Error("invalid point lon " + std::to_string(p.lon) + ", lat " + std::to_string(p.lat) +
               ": expected a finite longitude and a latitude within +-90 degrees");
}

double RHealpixProjection::polar_latitude(int face, double r) const {
  // sigma = 2 r = sqrt(6) sin(pi/4 - |beta| / 2).
  const double beta = kPi / 2 - 2 * std::asin(2 * r / std::sqrt(6.0));
  const double lat = std::min(authalic_.geodetic(beta) * kRadToDeg, 90.0);
  return face == kFaceN ? lat : -lat;
}

LonLat RHealpixProjection::from_face(FacePoint p) const {
  if (p.face != kFaceN && p.face != kFaceS) {
    const double sin_beta = std::clamp((0.5 - p.v) * 4 / 3, -1.0, 1.0);
    const double lat = authalic_.geodetic(std::asin(sin_beta)) * kRadToDeg;
    return {-180 + (p.face - kFaceO + p.u) * 90, lat};
  }
  const PolarOffset o = polar_offset(p.face, p.u, p.v);
  const double r = -o.dy;
  if (r == 0) return {0, polar_latitude(p.face, 0)};  // the pole: any longitude
  const double lon = -135 + 90 * o.k + o.dx / (2 * r) * 90;
  return {lon >= 180 ? lon - 360 : lon, polar_latitude(p.face, r)};
}

PlanePoint RHealpixProjection::to_plane(FacePoint p) const {
  const double r = radius();
  return {r * (face_x_min(p.face) + p.u * kPi / 2), r * (face_y_max(p.face) - p.v * kPi / 2)};
}

FacePoint RHealpixProjection::from_plane(PlanePoint p) const {
  const double col = (p.x / radius() + kPi) / (kPi / 2);
  const double row = (3 * kPi / 4 - p.y / radius()) / (kPi / 2);
  const double col0 = std::floor(col);
  const double row0 = std::floor(row);
  // The floor rule; a point on the outer boundary of a face goes to that face (the faces left,
  // above, and left and above the floor's square, in that order). So does a point beyond it by
  // rounding only: a face edge computed in metres (x_min + side) may land a few ulps outside.
  constexpr double kRounding = 1e-12;  // face widths, 10 micrometres
  constexpr std::pair<double, double> kOffsets[] = {{0, 0}, {-1, 0}, {0, -1}, {-1, -1}, {1, 0},
                                                    {0, 1}, {1, 1},  {1, -1}, {-1, 1}};
  for (const auto& [dc, dr] : kOffsets) {
    const double c = col0 + dc, r = row0 + dr;
    const auto face = face_at(c, r);
    const double u = col - c, v = row - r;
    if (face && u >= -kRounding && u <= 1 + kRounding && v >= -kRounding && v <= 1 + kRounding)
      return {*face, std::clamp(u, 0.0, 1.0), std::clamp(v, 0.0, 1.0)};
  }
  throw Error("plane point x " + std::to_string(p.x) + ", y " + std::to_string(p.y) +
              " lies outside the six squares of the rHEALPix plane");
}

}  // namespace maquette
