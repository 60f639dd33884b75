// The Colorado example (examples/climate-colorado.json) through the real program on
// ../shared/data/climate: ingest the PRISM 4 km elevation grid and the 376 stations, fit
// temperature and precipitation to elevation, regionalize, adjust for orography. Plausibility
// against the stations themselves and climate normals, so that a unit slip (the source's monthly
// totals are centimetres; the example's column is millimetres) cannot pass: read back with GDAL
// at each station, the layers agree with the station values to within what a regression on
// elevation explains, and Colorado's annual precipitation stays within its known range.
// Skipped when the data is absent.
#include <gdal_priv.h>
#include <gtest/gtest.h>
#include <ogrsf_frmts.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "run_cli.h"

namespace maquette::test {
namespace {

using json = nlohmann::json;

const std::string kClimate = std::string(MAQUETTE_SHARED_DIR) + "/data/climate";

struct Station {
  double lon, lat, temperature_c, precipitation_mm;
};

// The stations with both values, read with OGR's CSV driver.
std::vector<Station> read_stations(const std::string& csv) {
  std::unique_ptr<GDALDataset> ds(
      GDALDataset::Open(csv.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY));
  if (!ds) throw std::runtime_error("cannot open " + csv);
  std::vector<Station> out;
  for (auto& feature : *ds->GetLayer(0)) {
    const auto number = [&](const char* field) {
      const char* s = feature->GetFieldAsString(field);
      return *s ? std::stod(s) : std::nan("");
    };
    const Station s{number("lon"), number("lat"), number("mean_annual_tmean_C"),
                    number("mean_annual_precip_mm")};
    if (std::isfinite(s.temperature_c) && std::isfinite(s.precipitation_mm)) out.push_back(s);
  }
  return out;
}

// A layer of the store exported by the program to EPSG:4326 and read back with GDAL.
class LonLatRaster {
 public:
  explicit LonLatRaster(const std::string& path)
      : ds_(static_cast<GDALDataset*>(GDALOpen(path.c_str(), GA_ReadOnly))) {
    if (!ds_) throw std::runtime_error("cannot open " + path);
    ds_->GetGeoTransform(gt_);
  }
  // The value of the pixel holding (lon, lat); NaN outside the raster or at nodata.
  double at(double lon, double lat) const {
    const int col = int(std::floor((lon - gt_[0]) / gt_[1]));
    const int row = int(std::floor((lat - gt_[3]) / gt_[5]));
    if (col < 0 || row < 0 || col >= ds_->GetRasterXSize() || row >= ds_->GetRasterYSize())
      return std::nan("");
    float v = 0;
    GDALRasterBand* band = ds_->GetRasterBand(1);
    if (band->RasterIO(GF_Read, col, row, 1, 1, &v, 1, 1, GDT_Float32, 0, 0) != CE_None)
      return std::nan("");
    int has_nodata = 0;
    const double nodata = band->GetNoDataValue(&has_nodata);
    return (has_nodata && v == nodata) ? std::nan("") : v;
  }
  std::pair<double, double> range() const {
    double mm[2];
    ds_->GetRasterBand(1)->ComputeRasterMinMax(FALSE, mm);
    return {mm[0], mm[1]};
  }

 private:
  std::unique_ptr<GDALDataset> ds_;
  double gt_[6] = {};
};

double median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(Colorado, ExampleGivesPlausibleTemperatureAndPrecipitation) {
  const std::string csv = kClimate + "/CO_stations_annual_climate.csv";
  if (!std::filesystem::exists(csv)) GTEST_SKIP() << "no " << csv << " (../shared is absent)";
  GDALAllRegister();
  // The example as it is, but its store in a temporary folder, its sources in ../shared, and
  // without climate.solar (not under test here).
  const std::string dir = temp_dir();
  json p = json::parse(slurp(std::string(MAQUETTE_SOURCE_DIR) + "/examples/climate-colorado.json"));
  p["store"] = dir + "/colorado.mqt";
  json steps = json::array();
  for (json s : p["steps"]) {
    if (s["op"] == "climate.solar") continue;
    if (s["op"] == "ingest")
      for (json& source : s["params"]["sources"])
        source =
            kClimate + "/" + std::filesystem::path(source.get<std::string>()).filename().string();
    steps.push_back(s);
  }
  p["steps"] = steps;
  std::ofstream(dir + "/colorado.json") << p.dump(1);
  const CliResult run = run_maquette("-q run " + dir + "/colorado.json");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  for (const std::string layer : {"temperature", "precipitation"}) {
    const CliResult exp = run_maquette("-q export gtiff " + dir + "/colorado.mqt --layer " + layer +
                                       " " + dir + "/" + layer + ".tif --crs EPSG:4326");
    ASSERT_EQ(exp.exit_code, 0) << exp.err;
  }
  const LonLatRaster temperature(dir + "/temperature.tif"),
      precipitation(dir + "/precipitation.tif");

  // Colorado's mean annual precipitation: ~180 mm in the San Luis Valley to ~1,500 mm on the
  // highest ranges (PRISM 1991-2020 normals); temperature ~-5 to 14 C.
  const auto [p_min, p_max] = precipitation.range();
  EXPECT_GT(p_min, 100);
  EXPECT_LT(p_max, 2000);
  const auto [t_min, t_max] = temperature.range();
  EXPECT_GT(t_min, -12);
  EXPECT_LT(t_max, 18);

  // At the stations inside the region: the layers agree with the station values as well as a
  // regression on elevation can (median ratio near 1; a factor 10 slip gives 0.1 or 10).
  std::vector<double> p_ratio, t_error;
  for (const Station& s : read_stations(csv)) {
    const double pv = precipitation.at(s.lon, s.lat), tv = temperature.at(s.lon, s.lat);
    if (!std::isfinite(pv) || !std::isfinite(tv) || s.precipitation_mm <= 0) continue;
    p_ratio.push_back(pv / s.precipitation_mm);
    t_error.push_back(std::abs(tv - s.temperature_c));
  }
  ASSERT_GT(p_ratio.size(), 250u);
  EXPECT_GT(median(p_ratio), 0.85);
  EXPECT_LT(median(p_ratio), 1.2);
  EXPECT_LT(median(t_error), 1.5);
  // Akron, CO (424.7 mm/yr at the station; 1991-2020 normal ~420 mm).
  EXPECT_NEAR(precipitation.at(-103.15, 40.15), 425, 425 * 0.25);
}

}  // namespace
}  // namespace maquette::test
