// GDAL set-up shared by the readers: a bounded block cache, and error messages that name the
// file. Drivers are registered by whoever opens a file (gdal_drivers.h).
#pragma once

#include <string>

namespace maquette {

// Quiets GDAL's own error printing and sets the block cache (GDAL_CACHEMAX) to `cache_mb` MiB
// unless the user set GDAL_CACHEMAX. Safe to call many times and from many threads.
void init_gdal(int cache_mb = 256);

// GDAL's last error message on this thread, or `fallback` when there is none.
std::string gdal_last_error(const std::string& fallback);

}  // namespace maquette
