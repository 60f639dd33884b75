// synthesis.transfer across a polar face's turned edges (issue 18). The faces' plane
// (core/face_plane.h) lays each polar face unturned against one equatorial face only; its other
// three edges meet their equatorial face turned by 90 or 180 degrees, so there the plane's
// synthesis of the polar face (A) and the equatorial face's own (its cells read the polar face
// turned into their frame from the store's halo) would meet in a straight seam.
//
// Instead, a polar cell within kTurnedEdgeBand output pixels of such an edge E also synthesizes
// that band in the equatorial face G's chart: G's plane coordinates continued across E, the
// cell's guides (with their halo) turned so that G's pixels in the halo lie unturned (B). B is
// the function G's cells compute beyond their edge (the same guides at the same plane
// coordinates), so B continues G's output across E bit for bit. In the band the cell takes B
// between E and a minimum-error cut (seam_cut.h, pinned at depth kTurnedEdgeBand / 2 every
// kTurnedEdgePin pixels along E, so a function of global positions), A beyond it. A pixel
// within the band of two turned edges (a corner of the polar face) belongs to the nearer one
// (ties: the lower face number), and a pixel nearer the polar face's unturned edge than to the
// turned one (ties too) keeps A: at each cube corner the charts meet along the diagonal from the
// corner, and every face edge is seamless up to it.
//
// Every output pixel stays a copy of an exemplar pixel, and a function of global pixel
// coordinates and the guides: the same bits for any tiling, window, thread or rank. B's guides
// are G's chart (FacePlane::chart_pixel) found among the cell's own by the face pixel they hold
// (chart_guides.h), up to the cube corners: there too the pixels G's cells read.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/cell_id.h"
#include "core/face_plane.h"
#include "core/grid.h"
#include "core/unfolded_faces.h"
#include "synthesis.h"

namespace maquette::synthesis {

inline constexpr int kTurnedEdgeBand = 32;  // output pixels from the edge
inline constexpr int kTurnedEdgePin = 64;   // output pixels between the cut's pins along it

// One turned edge of a polar cell's face, in the face G across it: G's face frame at some pixel
// level continued beyond its side (0 top, 1 right, 2 bottom, 3 left) over the cell.
struct TurnedEdge {
  CellId cell;    // the polar cell
  int face = -1;  // G
  int side = 0;
  int64_t face_pixels = 0;  // G's pixels a side at the output's level
  // Where the cell lies in G's frame (UnfoldedFaces anchored on G), at the output's level.
  UnfoldedFaces::TilePlace place{};
  std::array<int64_t, 2> plane{};  // G's first pixel in the plane, at the output's level
  int polar_row = 0;  // the polar face's row in the plane: -1 above the equatorial row, 1 below

  // A G-frame pixel beyond the side: its depth (0 beside the edge) and position along the edge.
  int64_t depth(const std::array<int64_t, 2>& q) const;
  int64_t along(const std::array<int64_t, 2>& q) const;
  // The G-frame pixel at depth t and position s.
  std::array<int64_t, 2> at(int64_t s, int64_t t) const;
  // The depth of the cell's pixel row `row` (output level) from the polar face's edge with the
  // equatorial face it is laid against unturned.
  int64_t unturned_depth(int64_t row) const;
};

// The turned edges of `cell`'s face that the cell's output (tiles of tile_size << refine) lies
// within kTurnedEdgeBand pixels of: none on an equatorial face, nor on a polar face's edge laid
// unturned in the plane. Read off the grid's adjacency (UnfoldedFaces) and the plane's places.
// Throws maquette::Error on a polar face when tile_size is not a power of two (the store's tiles
// are), when tile_size << refine is not a multiple of kTurnedEdgePin (the cut's pins must divide
// every cell's stretch of the edge; tiles of 256 or more always are), or when G has no place.
std::vector<TurnedEdge> turned_edges(const Grid& grid, const FacePlane& plane, CellId cell,
                                     int tile_size, int refine);

// The cell's sources (`own`, synthesize()'s for its output tile, row-major) with each turned
// edge's band joined as above. `guides` are the cell's own: its tile with a halo of `halo`
// guide pixels laid in its face's chart (chart_guides.h, as synthesis.transfer lays them), in
// the plane: labels and altitude, which the band lays turned into G's chart. Throws
// maquette::Error, naming the cell, if a band's guides reach beyond that halo, or if `guides` hold
// distance, depth or light (the band does not lay them).
std::vector<int32_t> join_turned_edges(const Grid& grid, const FacePlane& plane,
                                       const ExemplarPyramid& pyramid, const SynthesisParams& sp,
                                       const TargetGuides& guides, int halo,
                                       const std::vector<TurnedEdge>& edges,
                                       std::vector<int32_t> own);

}  // namespace maquette::synthesis
