// GDAL driver registration, in one place for the three GDAL-using libraries (gdal, geotiff,
// vector). Registering every driver (GDALAllRegister, with plug-ins) costs ~8 ms of a program
// that otherwise starts in ~45 ms, so raster ingest first tries GTiff alone and registers the rest
// only when a source is not a GeoTIFF (raster_source.cpp). Header-only so that each library can
// call it without linking another.
#pragma once

#include <gdal.h>
#include <gdal_frmts.h>

#include <mutex>

namespace maquette {
namespace gdal_drivers_detail {

struct Registered {
  std::mutex mutex;
  bool gtiff = false, all = false;
};

// The one registration state of the program (an inline function's static is shared by every
// translation unit).
inline Registered& registered() {
  static Registered r;
  return r;
}

}  // namespace gdal_drivers_detail

// Registers every GDAL driver, once; safe from many threads.
inline void register_all_gdal_drivers() {
  auto& r = gdal_drivers_detail::registered();
  const std::lock_guard lock(r.mutex);
  if (r.all) return;
  GDALAllRegister();
  r.all = r.gtiff = true;
}

// Registers the GTiff driver alone, once (a no-op after register_all_gdal_drivers).
inline void register_gtiff_driver() {
  auto& r = gdal_drivers_detail::registered();
  const std::lock_guard lock(r.mutex);
  if (r.gtiff) return;
  GDALRegister_GTiff();
  r.gtiff = true;
}

}  // namespace maquette
