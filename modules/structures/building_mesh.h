// structures.buildings' work on one footprint feature: its solid (LoD1, or LoD2 with a pitched
// roof) standing on the DEM, checked, as a mesh object of a cell's content.
#pragma once

#include <optional>
#include <string>

#include "building_height.h"
#include "content/content.h"
#include "core/grid.h"
#include "core/tile.h"
#include "gdal/vertical_datum.h"
#include "runtime/vector_feature.h"

namespace maquette::structures {

// Pixels of DEM around each cell that structures.buildings reads: a building owned by the cell
// (its first point in it) must lie within them (terrain_base.h), so reach at most this many
// pixels beyond the cell's edge (London's largest blocks, ~220 m, reach ~120 pixels of 2.2 m
// beyond a cell on the polar face, whose plane shears them).
inline constexpr int kDemHaloPixels = 128;

// An image over the cell and a margin around it: the cell's orthophoto tile of `size` pixels with
// its halo of `halo` pixels, (size + 2 halo) pixels wide, the cell at [halo, halo + size).
struct TextureWindow {
  int size = 0, halo = 0;
};

// Where a building is written: the cell owning it, that cell's DEM tile (with halo), the
// content's frame, and the image its roof drapes, if any.
struct BuildingSite {
  const Grid* grid = nullptr;
  CellId cell;
  const Tile<float>* dem = nullptr;  // heights (m) above its vertical datum, NaN: no data
  EnuOrigin origin;
  std::optional<TextureWindow> texture;
  // The DEM's heights to heights above the ellipsoid (its recorded datum); null: they are.
  const EllipsoidalHeights* to_ellipsoid = nullptr;
};

// The building of a Polygon or MultiPolygon feature (courtyards as holes, one solid per part):
// its heights and roof from the tags (building_height.h: flat, gabled, hipped, pyramidal or
// skillion; roof_planes.h), its base at the lowest terrain under the whole footprint
// (terrain_base.h), taken to the ellipsoid at the anchor (the geoid's slope over a building is
// well under a millimetre); each part built in the tangent plane at the footprint's first point
// (core/enu_frame.h, at the base height): its walls up to its roof (roof_surface.h,
// building_solid.h), checked there (closed, outward, planar faces, volume = the roof surface's
// volume, area x height when flat, to 1e-9); then put in the site's east-north-up frame as
// float32 (a rigid move: within a float's rounding, 0.1 mm at 2 km from the origin). The first
// vertex is the footprint's first point at the base: the anchor. uvs, with a texture window: each
// vertex's position in that image (0, 0 at its top-left, 1, 1 at its bottom-right, as glTF), so
// the roof, pitched or flat, drapes the orthophoto; the walls show the colours of the roof's edge,
// drawn down (an orthophoto has no facades). Provenance: the feature id as object id, tool
// "structures.buildings", attributes height_m (the roof's top above the base, the highest part's),
// base_m, area_m2 and roof_shape (as built). `warning`, when given, receives what the user should
// know of a building built otherwise than tagged (a roof:shape not modelled, a pitched roof that
// gave no valid solid: built flat at its top), else is emptied. Throws InvalidFootprint (without
// the feature id) for a footprint that gives no valid solid, a bad tag, no DEM under the
// footprint, or a footprint reaching beyond the DEM tile's halo or across an edge of the grid's
// faces.
MeshObject building_mesh(const VectorFeature& feature, const HeightRules& rules,
                         const BuildingSite& site, std::string* warning = nullptr);

}  // namespace maquette::structures
