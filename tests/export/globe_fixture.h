// Whole-globe stores for the picture tests, built once per test run through the real program:
// world.tif (../shared/data/global, a 2048 x 1024 RGB image of the globe) ingested as imagery
// at level 1, and a global DEM written with GDAL (EPSG:4326, 0.5 degree pixels, sea below 0 m)
// ingested as a DEM.
#pragma once

#include <string>

namespace maquette::test {

// The world.tif path, "" when ../shared is absent (the caller skips).
std::string world_tif();

// A store holding layer "world" (world.tif at `level`), made once per level; "" without ../shared.
std::string world_store(int level);

// A store holding layer "dem", the global DEM (global_dem_tif()) ingested at level 2.
std::string global_dem_store();
std::string global_dem_tif();
// The DEM's height (metres) at a point: smooth, from about -3600 to 4600 m.
double global_height(double lon, double lat);

}  // namespace maquette::test
