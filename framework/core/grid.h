// Grid: the interface every discrete global grid implements (see grids/). Cells are
// squares of a planar projection, identified by CellId; all of a face's cells at a level form a
// 2^level x 2^level array of (col, row), row 0 at the top.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/cell_id.h"

namespace maquette {

struct LonLat {
  double lon = 0;  // degrees
  double lat = 0;  // degrees
};

struct PlanePoint {
  double x = 0;  // metres in the grid's plane
  double y = 0;
};

// An axis-aligned square of the grid's plane (metres): left, top edge and side length.
struct PlaneSquare {
  double x_min = 0;
  double y_max = 0;
  double side = 0;
};

// A position on a face at some level, possibly outside the face (for neighbour and halo
// lookups): col/row count cells (or pixels) from the face's top-left corner.
struct FaceCoord {
  int face = 0;
  int64_t col = 0;
  int64_t row = 0;
};

enum class Containment { Centre, Overlap, Full };

struct LevelInfo {
  int level = 0;
  double cell_side_m = 0;   // mean side on the ellipsoid: sqrt(area)
  double plane_side_m = 0;  // side of the cell's square in the plane
  double area_m2 = 0;       // exact area on the ellipsoid
  double pixel_m = 0;       // mean pixel side for a given tile size: cell_side_m / tile_size
};

class Grid {
 public:
  virtual ~Grid() = default;

  virtual std::string name() const = 0;
  virtual int num_faces() const = 0;

  // Projection between the ellipsoid (degrees) and the grid's plane (metres).
  virtual PlanePoint forward(LonLat p) const = 0;
  virtual LonLat inverse(PlanePoint p) const = 0;

  // Point to cell; throws maquette::Error for a latitude outside +-90 or a bad level.
  virtual CellId cell_from_point(LonLat p, int level) const = 0;
  virtual void cells_from_points(std::span<const LonLat> points, int level,
                                 std::span<CellId> out) const = 0;

  virtual LonLat centre(CellId cell) const = 0;
  virtual PlaneSquare plane_square(CellId cell) const = 0;
  // Closed ring of the cell's boundary on the ellipsoid, counter-clockwise, with
  // `points_per_edge` points per edge (first point repeated at the end).
  virtual std::vector<LonLat> boundary(CellId cell, int points_per_edge) const = 0;
  // Exact area on the ellipsoid (m^2): every cell of a level has the same area.
  virtual double area(int level) const = 0;
  virtual LevelInfo level_info(int level, int tile_size) const = 0;

  // Maps a coordinate at `level` (cells or, with level + log2(N), pixels) that may lie outside
  // its face onto the face that holds it, turning it as the faces meet. Only three faces meet at
  // a face corner, so the quadrant diagonally beyond a corner has no face: a coordinate there
  // (a cells beyond the column edge, b beyond the row edge) is read by crossing first the edge it
  // is farther beyond (the column edge when a >= b), then the next one. nullopt beyond one face
  // width.
  virtual std::optional<FaceCoord> wrap(FaceCoord c, int level) const = 0;

  // The 4 cells sharing an edge with `cell`, in the order top, right, bottom, left of the cell's
  // own face frame (at level 0: the four adjacent faces).
  virtual std::array<CellId, 4> edge_neighbours(CellId cell) const = 0;
  // All distinct cells sharing at least a vertex with `cell` (8, or 7 at the 8 cube corners).
  virtual std::vector<CellId> vertex_neighbours(CellId cell) const = 0;

  // Cells at `level` covering a lon/lat box (west may exceed east: the box crosses the
  // antimeridian; a box reaching +-90 covers the pole), sorted by id.
  virtual std::vector<CellId> cover_bbox(double west, double south, double east, double north,
                                         int level, Containment mode) const = 0;
  // Cells covering a polygon given as rings (first the outer ring, then holes) of lon/lat.
  virtual std::vector<CellId> cover_polygon(const std::vector<std::vector<LonLat>>& rings,
                                            int level, Containment mode) const = 0;
  // The covers above visited in id order without being held, for covers too large to hold: a
  // cell coarser than `level` stands for all its descendants at `level` (it lies inside the
  // region); each cell at `level` is visited once, in one of these or as itself. The polygons'
  // cover is that of their union.
  virtual void visit_cover_bbox(double west, double south, double east, double north, int level,
                                Containment mode,
                                const std::function<void(CellId)>& visit) const = 0;
  virtual void visit_cover_polygons(const std::vector<std::vector<std::vector<LonLat>>>& polygons,
                                    int level, Containment mode,
                                    const std::function<void(CellId)>& visit) const = 0;
};

// The default grid: rHEALPix on WGS84 (see grids/rhealpix).
const Grid& default_grid();

}  // namespace maquette
