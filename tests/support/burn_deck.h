// A bridge's deck rasterized by GDAL, the tests' independent oracle of its footprint.
#pragma once

#include <gdal_priv.h>

#include <nlohmann/json.hpp>
#include <vector>

namespace maquette::test {

// Burns the deck between two edges (GeoJSON LineString coordinates, [lon, lat] each, both drawn
// the same way) into `dataset`: band k + 1 of every pixel whose centre lies inside takes
// `values[k]` (one value per band). The outline is the first edge then the second reversed,
// densified to 1e-6 degrees so that it follows straight lines in degrees as structures.bridge's
// deck does, and transformed from WGS84 into the dataset's own spatial reference (which must be
// set). False when the transform or the rasterization fails.
bool burn_deck(GDALDataset& dataset, const nlohmann::json& first_edge,
               const nlohmann::json& second_edge, const std::vector<double>& values);

}  // namespace maquette::test
