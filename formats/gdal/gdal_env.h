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

// Registers GDAL's drivers once, and keeps GDAL's own error printing quiet on this thread while
// alive: readers and writers report failures as maquette::Error with GDAL's message (gdal_error),
// not GDAL's lines on stderr besides.
class GdalSession {
 public:
  GdalSession();
  ~GdalSession();
  GdalSession(const GdalSession&) = delete;
  GdalSession& operator=(const GdalSession&) = delete;
};

// A maquette::Error: `what`, then GDAL's last error message if any.
[[noreturn]] void gdal_error(const std::string& what);

// Records the failures GDAL reports on this thread while it lives, quietly: also those a driver
// reports and then clears, or only warns about, while it closes a file (on a full disk a GeoTIFF's
// last blocks and its .aux.xml are lost so, and GDAL's last error is empty afterwards). Writers
// keep one around the creation and close of a file, then call check().
class GdalErrorTrap {
 public:
  GdalErrorTrap();
  ~GdalErrorTrap();
  GdalErrorTrap(const GdalErrorTrap&) = delete;
  GdalErrorTrap& operator=(const GdalErrorTrap&) = delete;
  // Throws maquette::Error "WHAT: <GDAL's first failure>" if there was one.
  void check(const std::string& what) const;

 private:
  std::string failure_;
  friend void record_gdal_failure(GdalErrorTrap&, int, const char*);
};

}  // namespace maquette
