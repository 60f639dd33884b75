// Halo assembly: a tile padded with `halo` pixels from its neighbours. Halo pixel (col, row) is
// the face pixel (cell.col() * size + col, cell.row() * size + row) at pixel level
// L = cell.level() + log2(size), mapped by Grid::wrap(., L): pixels beyond a face edge come from
// the neighbouring face, turned as the faces meet (0/90/180/270 degrees).
//
// Corner rule: at the 8 cube corners only three faces meet, so the quadrant diagonally beyond
// a face corner has no pixels of its own. A pixel there, a pixels beyond the column edge and b
// beyond the row edge, is read by crossing the edge it is farther beyond first (the column edge
// when a >= b) and then the other one. Its source is then a pixel of one of the two adjacent
// faces, folded around the corner, and some sources repeat (the diagonal pixel of a corner pixel
// is its neighbour across the row edge): use pixel_source + pixel_centre for the true position
// of a halo pixel rather than assuming a regular grid there.
//
// Pixels whose source tile is absent are NaN.
#pragma once

#include <functional>
#include <optional>

#include "core/cell_id.h"
#include "core/grid.h"
#include "core/tile.h"

namespace maquette {

// Returns the stored tile of a cell, or nullopt when there is none.
using TileFetch = std::function<std::optional<Tile<float>>(CellId)>;

// The tile of `cell` (tile size `size`) with a halo of `halo` pixels (0 <= halo <= size), with the
// channels of the fetched tiles (1 and all NaN when none is stored). `fetch` is called at most
// once per cell (the cell itself and up to 8 neighbours). Throws maquette::Error when a fetched
// tile has another size or channel count.
Tile<float> assemble_halo(const Grid& grid, CellId cell, int size, int halo,
                          const TileFetch& fetch);
// The same from tiles the caller keeps (a cache): `find` returns a cell's stored tile, or nullptr
// when there is none, read in place (no tile is copied) while assemble_halo runs.
using TileFind = std::function<const Tile<float>*(CellId)>;
Tile<float> assemble_halo(const Grid& grid, CellId cell, int size, int halo, const TileFind& find);

// Where pixel (col, row) of `cell`'s tile (halo pixels included) really lies: the face pixel it
// is read from, at pixel level cell.level() + log2(size). nullopt beyond one face width.
std::optional<FaceCoord> pixel_source(const Grid& grid, CellId cell, int size, int col, int row);

// Geodetic centre of a face pixel at `pixel_level` (may exceed CellId::kMaxLevel).
LonLat pixel_centre(const Grid& grid, FaceCoord pixel, int pixel_level);
// The geodetic point at fractional pixel coordinates (col, row) of `face` at `pixel_level`
// (pixel centres at integers, as pixel_centre).
LonLat face_point_lonlat(const Grid& grid, int face, double col, double row, int pixel_level);

// A one-channel tile of `cell` (no halo) holding field(pixel centre): e.g. a known field for tests.
Tile<float> sample_field(const Grid& grid, CellId cell, int size,
                         const std::function<double(LonLat)>& field);

}  // namespace maquette
