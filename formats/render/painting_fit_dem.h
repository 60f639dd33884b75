// The warped DEM of a painting fit as a layer of the store (`render fit --warped-dem`): the DEM
// moved by the fit's ground warp (render/painting_fit_ground.h), h'(x) = h(x - d(x)), an ordinary
// DEM layer that every operator, `render panorama` and the exports read.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "core/grid.h"
#include "render/painting_fit_ground.h"
#include "store/store.h"

namespace maquette {

// Throws maquette::Error naming the option and value unless `name` can be the warped DEM's new
// layer: not empty, and no layer of `store` has it (the --dem layer included): nothing stored is
// replaced. A warped DEM left incomplete by an interrupted run may be written again. Called before
// any work, so a bad name leaves nothing written.
void check_warped_dem_name(const Store& store, const std::string& name);

// Writes the layer `out`: `dem`'s definition (level, tile size, dtype, nodata, units, codec, its
// vertical datum and footprint) and cells, each sample h(x - d(x)), `dem` read bilinearly there
// (its missing samples left out, nodata where the nearest is missing or beyond its tiles; when
// `dem` has no nodata value, the sample's own height there); where
// the warp has faded out, the sample's own bytes (a tile wholly there: its blob's samples, the
// same bits). Its overviews built. Its provenance: `warped_by` (what made it) beside the DEM's
// datum and footprint. Written under a run of its own and marked incomplete until whole; on any
// failure the layer and run are dropped and maquette::Error names the layer. An incomplete layer
// `out` that an interrupted run left is dropped whole before the new one is written. Deterministic
// (one thread, cells in order). Precondition: check_warped_dem_name(store, out) passed and `dem` is
// a one-channel raster layer.
void write_warped_dem(Store& store, const Grid& grid, const LayerInfo& dem, const GroundWarp& warp,
                      const std::string& out, const nlohmann::json& warped_by);

}  // namespace maquette
