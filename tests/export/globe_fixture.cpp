#include "globe_fixture.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <numbers>

#include "run_cli.h"
#include "synthetic_raster.h"

namespace maquette::test {

std::string world_tif() {
  const std::string path = MAQUETTE_SHARED_DIR "/data/global/world.tif";
  return std::filesystem::exists(path) ? path : "";
}

std::string world_store(int level) {
  static std::map<int, std::string> stores;
  if (world_tif().empty()) return "";
  auto [it, fresh] = stores.try_emplace(level);
  if (fresh) {
    it->second = temp_dir() + "/world" + std::to_string(level) + ".mqt";
    const CliResult r = run_maquette("ingest " + it->second + " --layer world --as imagery " +
                                     world_tif() + " --level " + std::to_string(level));
    EXPECT_EQ(r.exit_code, 0) << r.err;
  }
  return it->second;
}

double global_height(double lon, double lat) {
  constexpr double d = std::numbers::pi / 180;
  // A function of the point on the sphere (no seam at the antimeridian, one value at each pole).
  const double x = std::cos(lat * d) * std::cos(lon * d), y = std::cos(lat * d) * std::sin(lon * d),
               z = std::sin(lat * d);
  return 500 + 3000 * std::sin(2 * x + y) * std::cos(3 * y - z) + 1500 * z;
}

std::string global_dem_tif() {
  static const std::string path = [] {
    const std::string p = temp_dir() + "/global_dem.tif";
    RasterSpec spec;
    spec.width = 720, spec.height = 360;
    spec.geotransform = {-180, 0.5, 0, 90, 0, -0.5};
    spec.crs = "EPSG:4326";
    write_raster(p, spec, [](int, double lon, double lat) { return global_height(lon, lat); });
    return p;
  }();
  return path;
}

std::string global_dem_store() {
  static const std::string path = [] {
    const std::string p = temp_dir() + "/global_dem.mqt";
    const CliResult r =
        run_maquette("ingest " + p + " --layer dem --as dem " + global_dem_tif() + " --level 2");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return p;
  }();
  return path;
}

}  // namespace maquette::test
