// Shared set-up of the ingest tests: a temp directory, ingest into a fresh store, and a walk
// over every stored sample with its lon/lat.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/grid.h"
#include "gdal/raster_ingest.h"
#include "store/store.h"

namespace maquette::test {

std::string temp_dir();  // from tests/cli/run_cli.cpp

// Ingests into a new store `dir/name.mqt` with quiet output; returns the open store.
std::unique_ptr<Store> ingest(const std::string& dir, const std::string& name,
                              const std::vector<std::string>& sources, RasterIngestOptions o);

// Calls visit(cell, lon/lat of the sample, values of its channels (NaN = nodata)) for every
// sample of every tile of the layer.
void for_each_sample(const Store& store, const std::string& layer,
                     const std::function<void(CellId, LonLat, const float*)>& visit);

}  // namespace maquette::test
