// GDAL set-up shared by the readers: drivers registered once, a bounded block cache, and error
// messages that name the file.
#pragma once

#include <string>

namespace maquette {

// Registers the GDAL drivers and sets the block cache (GDAL_CACHEMAX) to `cache_mb` MiB unless
// the user set GDAL_CACHEMAX. Safe to call many times and from many threads.
void init_gdal(int cache_mb = 256);

// GDAL's last error message on this thread, or `fallback` when there is none.
std::string gdal_last_error(const std::string& fallback);

}  // namespace maquette
