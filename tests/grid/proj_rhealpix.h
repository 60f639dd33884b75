// PROJ's rhealpix on WGS84, both polar squares at position 0 as the grid lays its faces: the
// independent oracle of the grid tests' plane points. Degrees in and out.
#pragma once

#include <proj.h>

#include <cmath>
#include <stdexcept>

#include "core/grid.h"

namespace maquette::test {

class ProjRhealpix {
 public:
  ProjRhealpix()
      : ctx_(proj_context_create()),
        pj_(proj_create(ctx_, "+proj=rhealpix +ellps=WGS84 +north_square=0 +south_square=0")) {
    if (!pj_) throw std::runtime_error("PROJ cannot create +proj=rhealpix");
  }
  ~ProjRhealpix() {
    proj_destroy(pj_);
    proj_context_destroy(ctx_);
  }
  ProjRhealpix(const ProjRhealpix&) = delete;
  ProjRhealpix& operator=(const ProjRhealpix&) = delete;

  PlanePoint forward(LonLat p) const {
    const PJ_COORD c = proj_trans(pj_, PJ_FWD, proj_coord(p.lon * kDeg, p.lat * kDeg, 0, 0));
    return {c.xy.x, c.xy.y};
  }
  LonLat inverse(PlanePoint p) const {
    const PJ_COORD c = proj_trans(pj_, PJ_INV, proj_coord(p.x, p.y, 0, 0));
    return {c.lp.lam / kDeg, c.lp.phi / kDeg};
  }

 private:
  static constexpr double kDeg = M_PI / 180;
  PJ_CONTEXT* ctx_;
  PJ* pj_;
};

}  // namespace maquette::test
