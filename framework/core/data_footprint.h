// Where a layer's samples come from its sources: the lon/lat polygons a raster ingest records in
// the layer's provenance ("footprint"): the sources' outlines and, when the ingest was limited to
// a --bbox or --region, that region too; one such part per ingest into the layer. A nodata
// sample inside the footprint is a void of the data (SRTM's -32768); one outside lies beyond the
// sources, where there is nothing to fill. Layers without one (stores written before footprints
// were recorded, computed layers whose inputs had none) cannot tell the two apart.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "core/geojson.h"
#include "core/polygon_set.h"

namespace maquette {

class DataFootprint {
 public:
  // One part: the sources' outlines, within `region` (empty: no region beyond the sources).
  DataFootprint(std::vector<PolygonRings> sources, std::vector<PolygonRings> region);

  // The footprint recorded in a layer's provenance, nullopt when it has none. Throws
  // maquette::Error naming `layer` when the record is malformed.
  static std::optional<DataFootprint> from_provenance(const nlohmann::json& provenance,
                                                      const std::string& layer);
  // One part: {"sources": MultiPolygon, "region": MultiPolygon (only when there is one)}, GeoJSON
  // geometries; several: an array of those.
  nlohmann::json to_json() const;
  // This footprint and the parts of `other` that it does not hold yet (a later ingest into the
  // same layer).
  DataFootprint united(const DataFootprint& other) const;

  // Whether `p` lies inside a part: a source's outline (and its region). Longitudes may be any.
  bool contains(LonLat p) const;
  // Cells at `level` overlapping a part, sorted.
  std::vector<CellId> cover(const Grid& grid, int level) const;

 private:
  struct Part {
    std::vector<PolygonRings> sources, region;
    PolygonSet source_set, region_set;
    nlohmann::json to_json() const;
  };
  DataFootprint() = default;
  static Part part(const nlohmann::json& j, const std::string& where);
  std::vector<Part> parts_;
};

}  // namespace maquette
