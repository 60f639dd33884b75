#include "gdal/gdal_env.h"

#include <cpl_conv.h>
#include <cpl_error.h>
#include <gdal.h>

#include <cstdlib>
#include <mutex>

namespace maquette {

void init_gdal(int cache_mb) {
  static std::once_flag once;
  std::call_once(once, [cache_mb] {
    // Errors become exceptions with the message; GDAL must not print them to stderr itself.
    CPLSetErrorHandler(CPLQuietErrorHandler);
    if (!std::getenv("GDAL_CACHEMAX")) GDALSetCacheMax64(int64_t(cache_mb) << 20);
  });
}

std::string gdal_last_error(const std::string& fallback) {
  const char* msg = CPLGetLastErrorMsg();
  return msg && *msg ? std::string(msg) : fallback;
}

}  // namespace maquette
