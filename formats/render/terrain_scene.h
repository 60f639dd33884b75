// The terrain a panorama draws: a DEM layer's tiles as one triangle mesh in a camera's ENU frame,
// each cell at the level its distance needs (scene_cells). Each tile (full-resolution, or an
// overview of a coarser level), padded with a one-pixel halo from its neighbours of the same level
// (core/halo.h, across face seams too), gives a vertex at every sample centre, halo included
// (core/tile_frame.h: where the sample really lies), and two triangles per square of four samples,
// always split along the same diagonal, written in patches of 4 x 4 squares, each one of the
// rasterizer's blocks (RenderMesh::block_first, culled whole when hidden: render/rasterizer.h),
// as is each side of the skirt. The halo's squares reach into the
// neighbours, so tiles of one level share the squares along their seams (drawn twice, the same
// triangles), and a tile's skirt, a wall hanging from its halo's ring deeper than the tile's relief
// plus a sample, closes the cracks where a neighbour is drawn at another level (it hangs only
// there: along a neighbour of the same level it could be seen from below alone). Squares with a
// missing sample (nodata, no neighbour tile) are left out, and the skirt along them. Heights go to
// the ellipsoid through the layer's vertical datum, exaggerated by a factor above that datum. Tiles
// are read and their shares of the mesh counted in parallel, then each written in place (no copies
// joined) in their cell order: the mesh is the same whatever the threads. With the cull, a patch
// wholly out of the view is left out (its block empty) and its samples are no vertices unless a
// drawn square or the skirt uses them. The vertices' other
// attributes (lon/lat, plane point, altitude, normal) are made afterwards by attribute_vertices,
// for the vertices of the triangles a picture shows only (a small share on an oblique view:
// PanoramaCli.ShownVerticesAttributesAreEveryVertexs prints its count): the tiles' heights and
// sample places are kept for it.
#pragma once

#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

#include "core/grid.h"
#include "core/tile.h"
#include "gdal/vertical_datum.h"
#include "image/layer_sampler.h"
#include "render/camera.h"
#include "render/rasterizer.h"
#include "render/sample_places.h"
#include "store/store.h"

namespace maquette {

// A drawn tile as attribute_vertices needs it: its heights with two rings of halo, its samples'
// places, which of its samples are vertices, and the first of its vertices in the mesh.
struct SceneTile {
  Tile<float> heights{1, 1};
  std::optional<SamplePlaces> places;
  // Per patch of kBlockSquares x kBlockSquares squares (of the n + 1 squares a side: samples
  // -1 .. n, row-major): 1 when its squares are drawn, 0 when it lies wholly out of the view
  // (build_terrain_scene's cull). A sample is a vertex when a drawn square uses it or it is on
  // the halo's inner ring (the skirt's), and it has data.
  std::vector<uint8_t> drawn;
  // Per edge of the halo's inner ring (its samples once round, from the top-left, clockwise): 1
  // when the skirt hangs along it, 0 where the ring lies on a neighbour drawn at the same level
  // (the two surfaces overlap there: no seam to close).
  std::vector<uint8_t> skirted;
  size_t first_vertex = 0;
  // Per row of samples -1 .. n, the number of its first vertex from first_vertex; then the skirt's
  // first (n + 3 entries): attribute_vertices looks at the rows holding a vertex asked for only.
  std::vector<uint32_t> row_first;
};

// Its arrays are FreshArrays (render/fresh_array.h). The mesh's: each tile writes every element of
// its share (build_terrain_scene checks the share it wrote against the one it counted). The
// attributes (lonlat, plane, altitude, normals) are those of the vertices attribute_vertices was
// given, in its slots (`slot`): a picture shows a small share of the vertices, spread over nearly
// every page of arrays indexed by vertex (40 of the 4 MP benchmark picture's 290 MB of fresh
// pages, against 13 MB in slots). Each slot is written.
struct TerrainScene {
  static constexpr uint32_t kNoSlot = std::numeric_limits<uint32_t>::max();
  static constexpr uint32_t kAsked = kNoSlot - 1;  // to be given a slot
  std::vector<CellId> cells;                       // the tiles drawn (scene_cells)
  RenderMesh mesh;
  FreshArray<double> lonlat;  // degrees, 2 per slot
  // The grid's plane (render/sample_places.h SamplePlace::plane), 2 per slot: a layer is read at a
  // pixel from these interpolated, without projecting its lon/lat; NaN off the tile's face.
  FreshArray<double> plane;
  FreshArray<float> altitude;  // the DEM's height (its own datum, not exaggerated), per slot
  // Unit normals in the camera's ENU frame (central differences of the exaggerated, unbent
  // surface, at a tile's border too, from a second ring of halo: a sample drawn by two tiles has
  // one normal; one-sided only beside nodata), 3 per slot.
  FreshArray<float> normals;
  // What attribute_vertices reads: per cell; and per vertex its attributes' slot, kNoSlot when it
  // has none.
  std::vector<SceneTile> tiles;
  std::vector<uint32_t> slot;
  std::shared_ptr<const EllipsoidalHeights> heights;  // the DEM's datum, for the tiles' places
  double exaggeration = 1;
};

// The cells whose tiles draw the DEM: from the coarsest level holding overviews down, a cell is
// drawn at its level when that level holds tiles and one of its samples, at the cell's nearest
// horizontal distance from the eye, is at most `sample_pixels` pixels wide on the picture (its
// side times the focal length over the distance: a cell under the eye is never coarse);
// otherwise its children holding tiles are looked at, down to the full-resolution tiles. With
// `cull`, a cell wholly out of the view (beyond a side of the picture or behind the eye, with a
// margin of two samples, 1/16 of its side and the earth's bulge over it, for any height from
// -11,000 m (the ocean floor) to 9000 m times `exaggeration`) is left out with its children: the
// caller must not move the vertices afterwards (a bend). With `sample_pixels` 0 every
// full-resolution tile. Sorted by id within each root, roots ascending.
std::vector<CellId> scene_cells(const Store& store, const Grid& grid, const LayerInfo& dem,
                                const PinholeCamera& camera, double sample_pixels,
                                double exaggeration, bool cull);

// Throws maquette::Error unless `exaggeration` is finite and > 0 (build_terrain_scene and
// TerrainHeights check it: an infinite one made every camera "below the terrain (inf m)").
void check_exaggeration(double exaggeration);

// `dem`: a one-channel raster layer of heights in metres; `exaggeration` > 0; `sample_pixels`
// >= 0 and `cull` as scene_cells; with `cull`, also a tile's patch of squares (a rasterizer's
// block) wholly out of the view is left out, its samples no vertices unless a drawn square or the
// skirt uses them (the same pixels: beyond a side of the picture or behind the eye, at its lowest
// and highest sample, with a margin of a sample and the earth's bulge over the patch, the corners
// of the patch's squares, on tiles whose places are interpolated (SamplePlaces::interpolated);
// a tile placed exactly, as where a polar face's diagonal bends its rows, is drawn whole; groups of
// 4 x 4 patches are tested alike first, one wholly out or in deciding for its patches; the
// patches along the halo's ring and the skirt are always drawn). The scene's places refer to
// `grid`: it must outlive the scene. `datum`: the DEM's conversion to the ellipsoid when the caller
// has it (shared with TerrainHeights; PROJ's operation is costly to set up), else made from `dem`.
// `tiles`: the DEM's LayerSampler::shared_tiles at its level when the caller reads them again
// afterwards (the cast shadows), else made here and freed once the tiles' halos are made. Throws
// maquette::Error naming the value at fault, and when no tile of the DEM is in the view (cull).
TerrainScene build_terrain_scene(const Store& store, const Grid& grid, const LayerInfo& dem,
                                 const PinholeCamera& camera, double exaggeration,
                                 double sample_pixels, bool cull,
                                 std::shared_ptr<const EllipsoidalHeights> datum = nullptr,
                                 std::shared_ptr<LayerSampler::Tiles> tiles = nullptr);

// Writes the attributes (lonlat, plane, altitude, normals) of the vertices of the triangles
// `fragments` shows (nullptr: of every vertex) not written yet, into slots after those written
// (in vertex order: the same slots for any threads): a tile's vertices by one task, each the same
// bits whichever pictures or strips asked for it, so it may be called once per strip.
// Reads the mesh's indices only (not its positions: the normals are the unbent surface's).
void attribute_vertices(TerrainScene& scene, const Fragments* fragments);

// The drawn terrain's height above the ellipsoid at points: the DEM sampled bilinearly between
// samples, converted to the ellipsoid and exaggerated as build_terrain_scene draws it (heights of
// the datum times `exaggeration`), so an eye placed above it is above what is drawn. The tiles
// are read and the datum's transformation set up once for all the points (`datum`, the DEM's
// conversion to the ellipsoid, when the caller has it, else made from `dem`). Not thread-safe.
// Throws as check_exaggeration.
class TerrainHeights {
 public:
  TerrainHeights(const Store& store, const Grid& grid, const LayerInfo& dem,
                 double exaggeration = 1,
                 std::shared_ptr<const EllipsoidalHeights> datum = nullptr);
  // nullopt where the layer has no data.
  std::optional<double> operator()(LonLat p);

 private:
  const Grid& grid_;
  LayerInfo dem_;
  LayerSampler sampler_;
  std::shared_ptr<const EllipsoidalHeights> heights_;
  double exaggeration_;
};

}  // namespace maquette
