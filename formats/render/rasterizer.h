// A deterministic CPU z-buffer for triangle meshes seen by a PinholeCamera. Vertices are
// projected and snapped to 1/16 pixel (integer edge functions, so the tie rules are exact); a
// pixel belongs to a triangle when its centre is inside, or on a top or left edge (the top-left
// rule: a centre on an edge shared by two triangles is drawn by exactly one of them). Depth is
// the camera-frame z, interpolated perspective-correctly; the nearer surface wins, and on equal
// depth the lower triangle index. Rows are split into bands of 8. The mesh's blocks (below) are
// measured by oneTBB tasks (each block's bounding box on screen and nearest depth, and the pieces
// of its triangles the near plane cuts), then binned serially into the bands their bounding boxes
// meet: the pieces in triangle order, the blocks after a sort near to far (by nearest depth, then
// index). Each band is rasterized by one oneTBB task, writing only its own rows: its near-plane
// pieces first, then its blocks near to far, each block's triangles in index order. The result is
// the same bits for any number of threads (the tie rule does not depend on the drawing order).
// Hidden triangles are left out a block at a time: the mesh's blocks of consecutive triangles
// (RenderMesh::block_first), each band draws its blocks near to far (by their nearest corner's
// depth) and leaves out a block when every pixel of the band within its bounding box is already
// nearer than that corner (it would write none of them): the same bits, far less work where most
// of the terrain is hidden, when a block's triangles lie close together (a patch of a height
// field, not a long row of it).
// Triangles are clipped at `near` metres in front of the eye (the pieces keep their barycentric
// weights in the mesh triangle); a triangle (or piece) with a corner projected further than 2^22
// pixels from the picture is left out. There is no back-face culling.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>

#include "render/camera.h"
#include "render/fresh_array.h"

namespace maquette {

// The most triangles in one of the rasterizer's blocks (culled whole when hidden).
constexpr size_t kCullBlockTriangles = 32;

// Its arrays are FreshArrays (render/fresh_array.h): whoever sizes one writes every element.
struct RenderMesh {
  FreshArray<double> positions;  // the eye's ENU frame, metres, 3 per vertex
  FreshArray<uint32_t> indices;  // 3 per triangle
  // Where the rasterizer's blocks start: triangle indices, non-decreasing, at most
  // triangle_count(). A block runs to the next start (none between two equal ones), split into
  // blocks of kCullBlockTriangles and a remainder when longer; the triangles before the first
  // start are blocks of kCullBlockTriangles too (all of them when there is no start). The writer
  // should start one at each compact patch of the surface (bounding boxes on screen are small).
  FreshArray<uint32_t> block_first;
  size_t triangle_count() const { return indices.size() / 3; }
};

// What each pixel of rows first_row .. first_row + height - 1 of the picture sees, row-major from
// the top-left of that strip.
// Its arrays are FreshArrays (render/fresh_array.h): rasterize writes every pixel of each.
struct Fragments {
  static constexpr uint32_t kSky = std::numeric_limits<uint32_t>::max();
  int width = 0, height = 0;
  int first_row = 0;
  FreshArray<uint32_t> triangle;  // index of the triangle seen, kSky for none
  FreshArray<double> depth;       // camera-frame z (metres), +inf for none
  // Perspective-correct barycentric weights of the triangle's 2nd and 3rd vertex at the pixel's
  // centre (the 1st's is 1 - b1 - b2).
  FreshArray<float> b1, b2;
  // Blocks of the mesh left out of a band of rows as hidden behind nearer pixels (one count a
  // band a block): what the occlusion test saved, reported so that a test can see it work.
  size_t culled_blocks = 0;
};

// `mesh` measured for drawing through `camera` (positions in camera.frame()), `near` metres the
// nearest depth drawn: each vertex on screen, each block's bounding box and nearest depth, the
// pieces of the triangles the near plane cuts, the blocks sorted near to far. What every strip of
// a picture draws from: measured once a picture, not once a strip. It keeps a reference to `mesh`.
class RasterPlan {
 public:
  RasterPlan(const RenderMesh& mesh, const PinholeCamera& camera, double near = 1.0);
  ~RasterPlan();
  RasterPlan(const RasterPlan&) = delete;
  RasterPlan& operator=(const RasterPlan&) = delete;

 private:
  struct Parts;
  std::unique_ptr<Parts> parts_;
  friend void rasterize(const RasterPlan& plan, int first_row, int rows, Fragments& out);
};

// Rasterizes `mesh` (positions in camera.frame()) with `near` metres the nearest depth drawn, into
// the picture's rows [first_row, first_row + rows) (rows < 0: to the last row). Each pixel gets
// the same bits whatever the rows drawn with it (a strip of a picture is that picture's rows).
// Precondition: 0 <= first_row < the picture's height.
Fragments rasterize(const RenderMesh& mesh, const PinholeCamera& camera, double near = 1.0,
                    int first_row = 0, int rows = -1);
// The same from a plan of the mesh: the picture's rows [first_row, first_row + rows) drawn into
// `out` (rows < 0: to the last row), the same bits. `out`'s arrays are resized to the rows drawn
// and every pixel of them written: a picture's strips drawn one after the other into the same
// Fragments reuse its memory (the kernel gives and zeroes each page once, not once a strip).
void rasterize(const RasterPlan& plan, int first_row, int rows, Fragments& out);

}  // namespace maquette
