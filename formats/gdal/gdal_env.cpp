#include "gdal/gdal_env.h"

#include <cpl_conv.h>
#include <cpl_error.h>
#include <gdal.h>

#include <cstdlib>
#include <cstring>
#include <mutex>

#include "core/error.h"
#include "gdal/gdal_drivers.h"

namespace maquette {

void init_gdal(int cache_mb) {
  static std::once_flag once;
  std::call_once(once, [cache_mb] {
    // Errors become exceptions with the message; GDAL must not print them to stderr itself.
    CPLSetErrorHandler(CPLQuietErrorHandler);
    if (!std::getenv("GDAL_CACHEMAX")) GDALSetCacheMax64(int64_t(cache_mb) << 20);
  });
}

void record_gdal_failure(GdalErrorTrap& trap, int level, const char* msg) {
  // PAM reports an .aux.xml it could not write as a warning ("Unable to save auxiliary
  // information in ..."): a lost CRS, so a failure here.
  const bool failed = level >= CE_Failure || (msg && std::strstr(msg, "Unable to save"));
  if (failed && trap.failure_.empty()) trap.failure_ = msg && *msg ? msg : "GDAL failed";
}

namespace {

void CPL_STDCALL trap_handler(CPLErr level, CPLErrorNum, const char* msg) {
  record_gdal_failure(*static_cast<GdalErrorTrap*>(CPLGetErrorHandlerUserData()), int(level), msg);
}

}  // namespace

GdalErrorTrap::GdalErrorTrap() { CPLPushErrorHandlerEx(trap_handler, this); }
GdalErrorTrap::~GdalErrorTrap() { CPLPopErrorHandler(); }

void GdalErrorTrap::check(const std::string& what) const {
  if (!failure_.empty()) throw Error(what + ": " + failure_);
}

std::string gdal_last_error(const std::string& fallback) {
  const char* msg = CPLGetLastErrorMsg();
  return msg && *msg ? std::string(msg) : fallback;
}

GdalSession::GdalSession() {
  register_all_gdal_drivers();
  CPLPushErrorHandler(CPLQuietErrorHandler);
  CPLErrorReset();
}

GdalSession::~GdalSession() { CPLPopErrorHandler(); }

void gdal_error(const std::string& what) {
  const std::string detail = gdal_last_error("");
  throw Error(detail.empty() ? what : what + ": " + detail);
}

}  // namespace maquette
