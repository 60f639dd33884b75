// Features out of a store: the features of a region (`features_in_region`, also what quicklooks
// draw) and their export through OGR as GeoJSON or GeoPackage, geometry and attributes as
// ingested. `maquette export geojson|gpkg`. See README.md.
#pragma once

#include <string>
#include <vector>

#include "core/grid.h"
#include "image/layer_cells.h"
#include "store/store.h"

namespace maquette {

// The features of a features layer in the region, each once, by fid: with a box, those whose
// geometry meets the box; with cells, those indexed in them (a cell finer than the layer's
// level counts as its ancestor at that level); without either, all. Throws maquette::Error
// when the layer is not a features layer or has no feature in the region.
std::vector<Feature> features_in_region(const Store& store, const Grid& grid,
                                        const LayerInfo& layer, const RegionSpec& region);

enum class FeatureFormat { GeoJson, GeoPackage };

// Writes `features` of `layer` to `out` (a temporary name, renamed when complete): WGS84
// lon/lat (EPSG:4326), the store's fids as feature ids, the fields recorded at ingest in their
// order and types (fields without a record typed from their values). Throws maquette::Error
// naming the file when it cannot be written.
void write_features(const LayerInfo& layer, const std::vector<Feature>& features,
                    FeatureFormat format, const std::string& out);

}  // namespace maquette
