#include "geotiff/export_crs.h"

#include <algorithm>
#include <cctype>
#include <charconv>

#include "core/error.h"

namespace maquette {

ExportCrs parse_export_crs(const std::string& text) {
  ExportCrs crs;
  std::string lower = text;
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  crs.rhealpix = lower == "rhealpix";
  const std::string bad = "bad --crs '" + text + "' (expected rhealpix or EPSG:NNNN)";
  OGRErr err = OGRERR_NONE;
  if (crs.rhealpix) {
    err = crs.srs.importFromProj4(kRHealpixProj);
  } else {
    int code = 0;
    const char* digits = text.data() + 5;
    const char* end = text.data() + text.size();
    if (lower.rfind("epsg:", 0) != 0 || std::from_chars(digits, end, code).ptr != end || code <= 0)
      throw Error(bad);
    err = crs.srs.importFromEPSG(code);
    if (err != OGRERR_NONE) throw Error(bad + ": no such EPSG code");
  }
  if (err != OGRERR_NONE) throw Error(bad);
  crs.srs.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  return crs;
}

std::string crs_name(const OGRSpatialReference& srs) {
  const char* authority = srs.GetAuthorityName(nullptr);
  const char* code = srs.GetAuthorityCode(nullptr);
  if (authority && code) return std::string(authority) + ":" + code;
  const char* name = srs.GetName();
  return name ? name : "(unnamed)";
}

}  // namespace maquette
