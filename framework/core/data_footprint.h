// Where a layer's samples come from its sources: the lon/lat polygons a raster ingest records in
// the layer's provenance ("footprint"): the sources' outlines and, when the ingest was limited to
// a --bbox or --region, that region too. A nodata sample inside the footprint is a void of the
// data (SRTM's -32768); one outside lies beyond the sources, where there is nothing to fill.
// Layers without one (stores written before footprints were recorded, computed layers whose
// inputs had none) cannot tell the two apart.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "core/geojson.h"
#include "core/polygon_set.h"

namespace maquette {

class DataFootprint {
 public:
  // `region` empty: no region beyond the sources.
  DataFootprint(std::vector<PolygonRings> sources, std::vector<PolygonRings> region);

  // The footprint recorded in a layer's provenance, nullopt when it has none. Throws
  // maquette::Error naming `layer` when the record is malformed.
  static std::optional<DataFootprint> from_provenance(const nlohmann::json& provenance,
                                                      const std::string& layer);
  // {"sources": MultiPolygon, "region": MultiPolygon (only when there is one)}, GeoJSON geometries.
  nlohmann::json to_json() const;

  // Whether `p` lies inside a source's outline (and the region). Longitudes may be any.
  bool contains(LonLat p) const;
  // Cells at `level` overlapping a source's outline (and the region), sorted.
  std::vector<CellId> cover(const Grid& grid, int level) const;

 private:
  std::vector<PolygonRings> sources_, region_;
  PolygonSet source_set_, region_set_;
};

}  // namespace maquette
