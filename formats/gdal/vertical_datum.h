// Vertical datums of height layers: what a DEM's heights are measured from (recorded at ingest in
// the layer's provenance), and their conversion to heights above the WGS84 ellipsoid for 3D
// exports, with PROJ's geoid grids (Debian's proj-data ships EGM96's, egm96_15.gtx).
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "core/grid.h"
#include "store/store.h"

namespace maquette {

struct VerticalDatum {
  static constexpr const char* kEllipsoid = "ellipsoid";

  std::string crs;   // a vertical CRS PROJ knows ("EPSG:5773"), or kEllipsoid
  std::string name;  // "EGM96 height", "WGS 84 ellipsoid"
  std::string from;  // how it was chosen: the option, the source's CRS or the DEM default

  bool ellipsoidal() const { return crs == kEllipsoid; }
  nlohmann::json to_json() const;
  std::string describe() const;  // "EGM96 height (EPSG:5773), default for --as dem ..."
};

// `egm96` (EPSG:5773), `egm2008` (EPSG:3855), `ellipsoid`, or any vertical (or compound) CRS
// PROJ takes: "EPSG:5703", WKT, PROJJSON. Throws maquette::Error naming `option` and the value.
VerticalDatum parse_vertical_datum(const std::string& text, const std::string& option);

// The vertical datum a source's CRS (WKT) states: the vertical part of a compound CRS, the
// ellipsoid for a geographic 3D CRS; nullopt when it states none.
std::optional<VerticalDatum> source_vertical_datum(const std::string& crs_wkt,
                                                   const std::string& source);

// The default for `--as dem` sources that state none: EGM96, the datum of SRTM and of most
// global DEMs (ASTER GDEM, ALOS AW3D30, GMTED2010).
VerticalDatum default_dem_vertical_datum();

// The datum recorded in a layer's provenance ("vertical_datum"); nullopt when there is none.
std::optional<VerticalDatum> layer_vertical_datum(const LayerInfo& layer);

// Heights on a vertical datum to heights above the WGS84 ellipsoid: PROJ's transformation from
// WGS 84 + the datum to WGS 84 (3D), using a geoid grid. May be called from many threads at once
// (one PROJ object per thread).
class EllipsoidalHeights {
 public:
  EllipsoidalHeights();  // heights already above the ellipsoid: the identity
  // Throws maquette::Error when PROJ has no transformation with its grids at hand, naming the
  // grid files it looked for and where.
  explicit EllipsoidalHeights(const VerticalDatum& datum);
  ~EllipsoidalHeights();
  EllipsoidalHeights(EllipsoidalHeights&&) noexcept;

  // The ellipsoidal height of `height` at `p`; throws outside the grid.
  double operator()(LonLat p, double height) const;

 private:
  struct Transform;
  std::unique_ptr<Transform> transform_;  // null: the identity
};

// The conversion of a height layer's values to the ellipsoid, from its recorded datum; without
// one (synthetic or operator-made heights) they are taken as ellipsoidal heights already.
EllipsoidalHeights ellipsoidal_heights(const LayerInfo& layer);

}  // namespace maquette
