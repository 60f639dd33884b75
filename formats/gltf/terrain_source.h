// What a terrain mesh reads from a store: a DEM layer at any level up to its own (full tiles at
// its level, overview tiles above), and an imagery layer cut or reduced to a cell's square.
#pragma once

#include <optional>
#include <string>

#include "core/grid.h"
#include "core/tile.h"
#include "store/store.h"

namespace maquette {

// Checks the imagery an export uses (the DEM: image/option_layers.h height_layer): a uint8 raster
// of 1, 3 or 4 channels. Throws maquette::Error naming the layer.
LayerInfo require_texture_layer(const Store& store, const std::string& name);

// The layer's tile (or overview tile) of `cell`, no finer than the layer's level.
std::optional<RawTile> tile_at_level(const Store& store, const LayerInfo& layer, CellId cell);

// The DEM tile of `cell` with a halo of 2 pixels (NaN where there is no data); nullopt when
// the cell has no tile.
std::optional<Tile<float>> dem_with_halo(const Store& store, const Grid& grid, const LayerInfo& dem,
                                         CellId cell);

// The imagery of `cell`: its tile, or the part of an ancestor's tile when the cell is finer than
// the layer. nullopt when there is none.
std::optional<Tile<uint8_t>> texture_of(const Store& store, const LayerInfo& imagery, CellId cell);

}  // namespace maquette
