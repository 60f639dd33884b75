#include "neighbourhood.h"

namespace maquette::terrain {

bool neighbourhood(const TileFrame& frame, int col, int row, Neighbourhood& out) {
  const Vec3& centre = frame.ecef(col, row);
  for (int i = 0; i < 9; ++i) {
    const int c = col + i % 3 - 1, r = row + i / 3 - 1;
    if (!frame.known(c, r)) return false;
    const Vec3& p = frame.ecef(c, r);
    const EastNorth d =
        frame.tangent(col, row, {p[0] - centre[0], p[1] - centre[1], p[2] - centre[2]});
    out.east[i] = d.east;
    out.north[i] = d.north;
  }
  return true;
}

}  // namespace maquette::terrain
