#include "proj_enu.h"

#include <gtest/gtest.h>
#include <proj.h>

#include <iomanip>
#include <sstream>

namespace maquette::test {

ProjEnu::ProjEnu(double lon, double lat, double height) {
  std::ostringstream pipeline;
  pipeline << std::setprecision(17)
           << "+proj=pipeline +step +proj=unitconvert +xy_in=deg +xy_out=rad +step +proj=cart "
              "+ellps=WGS84 +step +proj=topocentric +ellps=WGS84 +lon_0="
           << lon << " +lat_0=" << lat << " +h_0=" << height;
  pj_ = proj_create(PJ_DEFAULT_CTX, pipeline.str().c_str());
  EXPECT_NE(pj_, nullptr) << pipeline.str();
}

ProjEnu::~ProjEnu() { proj_destroy(pj_); }

std::array<double, 3> ProjEnu::operator()(LonLat p, double height) const {
  const PJ_COORD c = proj_trans(pj_, PJ_FWD, proj_coord(p.lon, p.lat, height, 0));
  return {c.xyz.x, c.xyz.y, c.xyz.z};
}

}  // namespace maquette::test
