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
  return false;
}

bool in_any_band(const std::vector<StrokeBand>& bands, EastNorth2 p) {
  return std::any_of(bands.begin(), bands.end(),
                     [&](const StrokeBand& b) { return b.contains(p); });
}

}  // namespace maquette::deform
