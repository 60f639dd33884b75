#include "stroke_band.h"

#include <algorithm>
#include <cmath>

namespace maquette::deform {

bool StrokeBand::contains(EastNorth2 p) const {
  for (size_t i = 0; i + 1 < curve.size(); ++i) {
    const EastNorth2 a = curve[i], b = curve[i + 1];
    const double dx = b[0] - a[0], dy = b[1] - a[1], length = std::hypot(dx, dy);
    const double along = ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / length;
    const double right = ((p[0] - a[0]) * dy - (p[1] - a[1]) * dx) / length;
    const double from = i == 0 ? -end_margin_m : 0;
    const double to = i + 2 == curve.size() ? length + end_margin_m : length;
    if (along >= from && along <= to && right >= offset_min && right <= offset_max) return true;
  }
  // On the outer side of a bend a point can lie past one segment's end and before the next
  // one's start, where no projection reaches: there the band is the disc sector around the
  // vertex, the signed offset being the distance from the vertex, its sign the side of the turn.
  for (size_t i = 1; i + 1 < curve.size(); ++i) {
    const EastNorth2 v = curve[i];
    const double in_x = v[0] - curve[i - 1][0], in_y = v[1] - curve[i - 1][1];
    const double out_x = curve[i + 1][0] - v[0], out_y = curve[i + 1][1] - v[1];
    const double dx = p[0] - v[0], dy = p[1] - v[1];
    if (dx * in_x + dy * in_y <= 0 || dx * out_x + dy * out_y >= 0) continue;
    const double distance = std::hypot(dx, dy);
    const double offset = dx * in_y - dy * in_x >= 0 ? distance : -distance;
    if (offset >= offset_min && offset <= offset_max) return true;
  }
  return false;
}

bool in_any_band(const std::vector<StrokeBand>& bands, EastNorth2 p) {
  return std::any_of(bands.begin(), bands.end(),
                     [&](const StrokeBand& b) { return b.contains(p); });
}

}  // namespace maquette::deform
