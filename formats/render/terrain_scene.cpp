#include "render/terrain_scene.h"

#include <spdlog/fmt/fmt.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <numeric>
#include <optional>
#include <span>
#include <stdexcept>
#include <utility>

#include "core/error.h"
#include "core/halo.h"
#include "core/lonlat_bounds.h"
#include "gdal/vertical_datum.h"
#include "image/layer_sampler.h"
#include "render/sample_places.h"

namespace maquette {
namespace {

constexpr uint32_t kNoVertex = std::numeric_limits<uint32_t>::max();

// Two rings of halo: the outer one only for the drawn ring's normals, so that a sample's normal is
// the same central difference in every tile that draws it (no seam in the shading).
constexpr int kHalo = 2;

// The squares' triangles are written in patches of kBlockSquares x kBlockSquares squares (fewer
// along the tile's last row and column of patches, and without the squares left out), each one of
// the rasterizer's blocks (RenderMesh::block_first; render/rasterizer.h: hidden blocks are culled
// whole), as is each side of the skirt (split by the rasterizer into blocks of at most
// kCullBlockTriangles). A whole patch is one block: not split.
constexpr int kBlockSquares = 4;
static_assert(2 * kBlockSquares * kBlockSquares <= kCullBlockTriangles);

// A tile's patches a side (of its n + 1 squares a side: samples -1 .. n).
int tile_patches(int n) { return (n + 1 + kBlockSquares - 1) / kBlockSquares; }

// A tile's blocks (block_first's entries): its patches and the skirt's four sides.
size_t tile_blocks(int n) { return size_t(tile_patches(n)) * size_t(tile_patches(n)) + 4; }

// Calls visit(k, c0, r0, c1, r1) for the k-th patch of a tile's squares (of its n + 1 squares a
// side: samples -1 .. n), in row order: squares c0 .. c1 - 1 of rows r0 .. r1 - 1.
template <typename Visit>
void each_patch(int n, Visit&& visit) {
  size_t k = 0;
  for (int r0 = -1; r0 < n; r0 += kBlockSquares)
    for (int c0 = -1; c0 < n; c0 += kBlockSquares)
      visit(k++, c0, r0, std::min(n, c0 + kBlockSquares), std::min(n, r0 + kBlockSquares));
}

// Whether sample (c, r), -1 .. n, of `tile` is used: on the halo's inner ring (the skirt's), or a
// corner of a drawn square (squares c - 1 .. c and r - 1 .. r, in patches c / kBlockSquares ..
// (c + 1) / kBlockSquares and alike for rows).
bool used(const SceneTile& tile, int n, int c, int r) {
  if (c < 0 || r < 0 || c >= n || r >= n) return true;
  const size_t patches = size_t(tile_patches(n));
  const size_t pc0 = size_t(c / kBlockSquares), pc1 = size_t((c + 1) / kBlockSquares),
               pr0 = size_t(r / kBlockSquares), pr1 = size_t((r + 1) / kBlockSquares);
  return tile.drawn[pr0 * patches + pc0] || tile.drawn[pr0 * patches + pc1] ||
         tile.drawn[pr1 * patches + pc0] || tile.drawn[pr1 * patches + pc1];
}

// The halo's inner ring (samples -1 and n), once round: the skirt hangs from it.
std::vector<std::array<int, 2>> halo_ring(int n) {
  std::vector<std::array<int, 2>> ring;
  ring.reserve(4 * size_t(n + 1));
  for (int c = -1; c < n; ++c) ring.push_back({c, -1});
  for (int r = -1; r < n; ++r) ring.push_back({n, r});
  for (int c = n; c > -1; --c) ring.push_back({c, n});
  for (int r = n; r > -1; --r) ring.push_back({-1, r});
  return ring;
}

// Per edge k of halo_ring(n) (from its k-th sample to the next): 1 when the skirt hangs along it.
// A ring sample lies in a neighbour's tile; when that neighbour is drawn at the same level its
// squares and `cell`'s ring squares are the same surface, overlapping by a square, so no ray
// passes between them and a skirt there could only be seen from below the terrain (walls hanging
// under the DEM's edge, seen from outside it). `drawn_cells`: the scene's cells, sorted.
std::vector<uint8_t> skirted_edges(const Grid& grid, CellId cell, int n,
                                   const std::vector<CellId>& drawn_cells) {
  const int log2_size = log2_tile_size(n);
  const auto ring = halo_ring(n);
  std::vector<uint8_t> level_neighbour(ring.size(), 0);
  for (size_t k = 0; k < ring.size(); ++k) {
    const std::optional<FaceCoord> src = pixel_source(grid, cell, n, ring[k][0], ring[k][1]);
    level_neighbour[k] =
        src && std::binary_search(
                   drawn_cells.begin(), drawn_cells.end(),
                   CellId::FromFaceColRow(src->face, cell.level(), uint32_t(src->col >> log2_size),
                                          uint32_t(src->row >> log2_size)));
  }
  std::vector<uint8_t> skirted(ring.size());
  for (size_t k = 0; k < ring.size(); ++k)
    skirted[k] = !(level_neighbour[k] && level_neighbour[(k + 1) % ring.size()]);
  return skirted;
}

// A tile's share of the mesh: a vertex per drawn sample (-1 .. n) with data and per such sample of
// the inner ring (the skirt's), two triangles per square of four such samples and per ring edge
// between two. Every sample within the halo has a place (render/sample_places.h: known within a
// face width), so the counts follow from the heights alone and the mesh is written in place
// (write_tile).
struct TileShare {
  size_t vertices = 0, indices = 0;
};

// Where a sample at `z` metres of the DEM's datum is drawn: `exaggeration` times z along the
// ellipsoid's normal from its place at height 0 (unbent).
Vec3d exaggerated(const SamplePlace& place, float z, double exaggeration) {
  const double h = exaggeration * z;
  return {place.base[0] + h * place.up[0], place.base[1] + h * place.up[1],
          place.base[2] + h * place.up[2]};
}

// The lowest and highest of `heights`' samples with data in columns c0 .. c1 and rows r0 .. r1
// (infinity and -infinity for none).
std::pair<float, float> relief(const Tile<float>& heights, int c0, int r0, int c1, int r1) {
  float lowest = INFINITY, highest = -INFINITY;
  for (int r = r0; r <= r1; ++r)
    for (int c = c0; c <= c1; ++c) {
      const float z = heights.at(c, r);
      if (std::isnan(z)) continue;
      lowest = std::min(lowest, z);
      highest = std::max(highest, z);
    }
  return {lowest, highest};
}

// `datum` when given, else `dem`'s conversion to the ellipsoid.
std::shared_ptr<const EllipsoidalHeights> given_or_made(
    std::shared_ptr<const EllipsoidalHeights> datum, const LayerInfo& dem) {
  return datum ? std::move(datum)
               : std::make_shared<const EllipsoidalHeights>(ellipsoidal_heights(dem));
}

// `cell`'s tile (a full-resolution tile or an overview) with its two rings of halo, from `tiles`:
// each DEM tile decoded once for all the halos that read it (its own and up to eight neighbours').
Tile<float> tile_heights(const Grid& grid, const LayerInfo& dem, CellId cell,
                         LayerSampler::Tiles& tiles) {
  return assemble_halo(grid, cell, dem.tile_size, kHalo,
                       [&tiles](CellId c) { return LayerSampler::tile(tiles, c); });
}

// The vertex numbering write_tile writes, tile_share counts and attribute_tile reads: calls
// visit(vertex, col, row, k) for each vertex of `tile` numbered from `first`: the used samples
// with data in row order (k -1), then the skirt's, each with the ring sample it hangs from, the
// k-th of halo_ring(n). Split: the samples' vertices of rows [r0, r1) (of -1 .. n) numbered from
// `first`, and the skirt's numbered from `first`; both return the number after their last.
template <typename Visit>
size_t each_row_vertex(const SceneTile& tile, int n, int r0, int r1, size_t first, Visit&& visit) {
  const Tile<float>& heights = tile.heights;
  size_t v = first;
  for (int r = r0; r < r1; ++r)
    for (int c = -1; c <= n; ++c)
      if (!std::isnan(heights.at(c, r)) && used(tile, n, c, r)) visit(v++, c, r, -1);
  return v;
}

template <typename Visit>
size_t each_skirt_vertex(const SceneTile& tile, int n, size_t first, Visit&& visit) {
  const Tile<float>& heights = tile.heights;
  size_t v = first;
  const auto ring = halo_ring(n);
  for (size_t k = 0; k < ring.size(); ++k)
    if (!std::isnan(heights.at(ring[k][0], ring[k][1])) &&
        (tile.skirted[k] || tile.skirted[(k + ring.size() - 1) % ring.size()]))
      visit(v++, ring[k][0], ring[k][1], int(k));
  return v;
}

template <typename Visit>
void each_vertex(const SceneTile& tile, int n, size_t first, Visit&& visit) {
  each_skirt_vertex(tile, n, each_row_vertex(tile, n, -1, n + 1, first, visit), visit);
}

// Also sets tile.row_first.
TileShare tile_share(SceneTile& tile, int n) {
  const Tile<float>& heights = tile.heights;
  TileShare t;
  tile.row_first.resize(size_t(n) + 3);
  auto none = [](size_t, int, int, int) {};
  for (int r = -1; r <= n; ++r) {
    tile.row_first[size_t(r + 1)] = uint32_t(t.vertices);
    t.vertices = each_row_vertex(tile, n, r, r + 1, t.vertices, none);
  }
  tile.row_first[size_t(n) + 2] = uint32_t(t.vertices);
  t.vertices = each_skirt_vertex(tile, n, t.vertices, none);
  auto has = [&](int c, int r) { return !std::isnan(heights.at(c, r)); };
  each_patch(n, [&](size_t k, int c0, int r0, int c1, int r1) {
    if (!tile.drawn[k]) return;
    for (int r = r0; r < r1; ++r)
      for (int c = c0; c < c1; ++c)
        if (has(c, r) && has(c + 1, r) && has(c, r + 1) && has(c + 1, r + 1)) t.indices += 6;
  });
  const auto ring = halo_ring(n);
  for (size_t k = 0; k < ring.size(); ++k) {
    const auto& a = ring[k];
    const auto& b = ring[(k + 1) % ring.size()];
    if (tile.skirted[k] && has(a[0], a[1]) && has(b[0], b[1])) t.indices += 6;
  }
  return t;
}

// Writes `tile`'s share of the mesh's positions, indices and block starts (its share counted by
// tile_share) from index `first_index` and block start `first_block` (tile_blocks(n) of them):
// the vertices as each_vertex numbers them (the drawn samples', then the skirt's); the
// squares' triangles in patches of kBlockSquares x kBlockSquares squares (the patches in row
// order, each in row order), then the skirt's, each patch and each side of the skirt starting a
// block.
void write_tile(const Grid& grid, const LayerInfo& dem, CellId cell, const SceneTile& tile,
                const TileShare& share, const PinholeCamera& camera,
                const EllipsoidalHeights& heights, double exaggeration, size_t first_index,
                size_t first_block, RenderMesh& mesh) {
  const int n = dem.tile_size;
  const SamplePlaces& places = *tile.places;
  const int side = n + 2 * kHalo;
  auto slot = [&](int c, int r) { return size_t(r + kHalo) * size_t(side) + size_t(c + kHalo); };
  auto& positions = mesh.positions;
  auto& indices = mesh.indices;
  size_t next_index = first_index;
  // The drawn samples (-1 .. n, the halo's inner ring included) become vertices (scene indices) at
  // their exaggerated positions; heights of the datum run along the ellipsoid's normal. The skirt:
  // a wall hanging from the halo's ring, deeper than the tile's relief (all its samples -1 .. n,
  // drawn or not) plus a sample, so that where a neighbour is drawn at another level (its surface
  // above or below this one near the seam) no ray passes between the two.
  std::vector<uint32_t> vertex(size_t(side) * size_t(side), kNoVertex);
  const auto ring = halo_ring(n);
  std::vector<uint32_t> below(ring.size(), kNoVertex);
  const auto [lowest, highest] = relief(tile.heights, -1, -1, n, n);
  const double sample_m = grid.level_info(cell.level(), n).pixel_m;
  each_vertex(tile, n, tile.first_vertex, [&](size_t v, int c, int r, int k) {
    const float z = tile.heights.at(c, r);
    Vec3d p;
    if (k < 0) {
      vertex[slot(c, r)] = uint32_t(v);
      p = exaggerated(places.ground(c, r), z, exaggeration);
    } else {
      const double depth = exaggeration * (double(highest - lowest) + sample_m);
      const LonLat place = places.at(c, r).position;
      p = camera.frame().to_enu(place.lon, place.lat,
                                heights(place, z) + (exaggeration - 1) * z - depth);
      below[size_t(k)] = uint32_t(v);
    }
    std::copy(p.begin(), p.end(), positions.begin() + std::ptrdiff_t(3 * v));
  });
  auto at = [&](int c, int r) {
    return c < -1 || r < -1 || c > n || r > n ? kNoVertex : vertex[slot(c, r)];
  };
  auto triangles = [&](uint32_t a, uint32_t b, uint32_t c, uint32_t d) {  // a, b, c and a, c, d
    for (const uint32_t k : {a, b, c, a, c, d}) indices[next_index++] = k;
  };
  size_t next_block = first_block;
  auto start_block = [&] { mesh.block_first[next_block++] = uint32_t(next_index / 3); };
  each_patch(n, [&](size_t k, int c0, int r0, int c1, int r1) {
    start_block();  // an empty block when not drawn
    if (!tile.drawn[k]) return;
    for (int r = r0; r < r1; ++r)
      for (int c = c0; c < c1; ++c) {
        const uint32_t a = at(c, r), b = at(c + 1, r), d = at(c, r + 1), e = at(c + 1, r + 1);
        if (a == kNoVertex || b == kNoVertex || d == kNoVertex || e == kNoVertex) continue;
        triangles(a, b, e, d);
      }
  });
  for (size_t k = 0; k < ring.size(); ++k) {
    if (k % size_t(n + 1) == 0) start_block();  // a side of the ring
    const size_t next = (k + 1) % ring.size();
    const uint32_t a = at(ring[k][0], ring[k][1]), b = at(ring[next][0], ring[next][1]);
    if (!tile.skirted[k] || a == kNoVertex || b == kNoVertex) continue;
    triangles(a, b, below[next], below[k]);
  }
  // The arrays were sized by tile_share's counts and are not initialized: a share that differs
  // would leave garbage or overrun a neighbour's, so the triangles' loops are checked against its
  // count (the vertices are numbered by each_vertex for both).
  if (next_index - first_index != share.indices || next_block - first_block != tile_blocks(n))
    throw std::logic_error("panorama mesh of cell " + cell.ToText() + ": wrote " +
                           std::to_string(next_index - first_index) + " indices and " +
                           std::to_string(next_block - first_block) + " block starts, counted " +
                           std::to_string(share.indices) + " and " +
                           std::to_string(tile_blocks(n)));
}

// A thread's memo of one tile's samples' exaggerated, unbent positions (samples -2 .. n + 1),
// each computed when first asked for: an entry is the current tile's when its stamp is.
struct PositionMemo {
  std::vector<Vec3d> position;
  std::vector<uint32_t> stamp;
};

// Rows of samples a task of attribute_vertices looks at (a tile's share of the work varies with
// what the picture shows of it: many small tasks keep both threads busy to the end).
constexpr int kAttributeRows = 16;

// The first vertex of row r of samples -1 .. n + 1 of tile `index` (row n + 1 standing for the
// skirt; n + 2: the tile's end): a row's vertices are consecutive, up to the next row's first (the
// skirt's up to the next tile's first).
size_t row_first(const TerrainScene& scene, size_t index, int n, int r) {
  if (r <= n + 1)
    return scene.tiles[index].first_vertex + scene.tiles[index].row_first[size_t(r + 1)];
  return index + 1 < scene.tiles.size() ? scene.tiles[index + 1].first_vertex : scene.slot.size();
}

// Writes the attributes of `tile`'s vertices asked for (TerrainScene::kAsked) in rows [r0, r1) of
// samples -1 .. n + 1, row n + 1 standing for the skirt, into slots from `next` on in vertex
// order: each that of the sample it is (a skirt's vertex, the ring sample it hangs from). Rows
// without a vertex asked for are passed over. Returns the slot after the last written.
size_t attribute_tile(TerrainScene& scene, size_t index, int n, int r0, int r1, size_t next,
                      PositionMemo& memo) {
  const SceneTile& tile = scene.tiles[index];
  auto asked = [&](int r) {
    const auto begin = scene.slot.begin() + std::ptrdiff_t(row_first(scene, index, n, r)),
               end = scene.slot.begin() + std::ptrdiff_t(row_first(scene, index, n, r + 1));
    return std::find(begin, end, TerrainScene::kAsked) != end;
  };
  const SamplePlaces& places = *tile.places;
  const int side = n + 2 * kHalo;
  const auto stamp = uint32_t(index + 1);
  if (memo.stamp.size() != size_t(side) * size_t(side)) {
    memo.position.resize(size_t(side) * size_t(side));
    memo.stamp.assign(size_t(side) * size_t(side), 0);
  }
  // The sample's position; NaN where it has none. `place`: the sample's, when the caller has it
  // (a shown vertex's, not placed twice).
  auto position = [&](int c, int r, const SamplePlace* place = nullptr) -> const Vec3d& {
    const size_t slot = size_t(r + kHalo) * size_t(side) + size_t(c + kHalo);
    Vec3d& p = memo.position[slot];
    if (memo.stamp[slot] != stamp) {
      memo.stamp[slot] = stamp;
      const float z = tile.heights.at(c, r);
      p = std::isnan(z) ? Vec3d{NAN, NAN, NAN}
                        : exaggerated(place ? *place : places.ground(c, r), z, scene.exaggeration);
    }
    return p;
  };
  auto attribute = [&](size_t v, int c, int r, int) {
    if (scene.slot[v] != TerrainScene::kAsked) return;
    const size_t a = next++;
    scene.slot[v] = uint32_t(a);
    const SamplePlace place = places.at(c, r);
    scene.lonlat[2 * a] = place.position.lon;
    scene.lonlat[2 * a + 1] = place.position.lat;
    scene.plane[2 * a] = place.plane.x;
    scene.plane[2 * a + 1] = place.plane.y;
    scene.altitude[a] = tile.heights.at(c, r);
    // The normal: the cross product of the column and row central differences, turned up;
    // one-sided only where a neighbour has no data.
    const Vec3d pv = position(c, r, &place);
    auto span = [&](int c0, int r0, int c1, int r1) {
      const Vec3d* a = &position(c0, r0);
      const Vec3d* b = &position(c1, r1);
      if (std::isnan((*a)[0])) a = &pv;
      if (std::isnan((*b)[0])) b = &pv;
      return Vec3d{(*b)[0] - (*a)[0], (*b)[1] - (*a)[1], (*b)[2] - (*a)[2]};
    };
    const Vec3d u = span(c - 1, r, c + 1, r), w = span(c, r - 1, c, r + 1);
    Vec3d nrm{u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
    const double len = std::sqrt(nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]);
    // The up direction at the vertex: from the earth's centre, near enough for the sign.
    const double up = nrm[0] * pv[0] + nrm[1] * pv[1] + nrm[2] * (pv[2] + 6.371e6);
    const double s = len == 0 ? 0 : (up < 0 ? -1 : 1) / len;
    for (size_t k = 0; k < 3; ++k) scene.normals[3 * a + k] = float(nrm[k] * s);
    if (len == 0) scene.normals[3 * a + 2] = 1;
  };
  // Each strip of a picture asks again, of every row.
  for (int r = r0; r < r1; ++r) {
    if (!asked(r)) continue;
    if (r <= n)
      each_row_vertex(tile, n, r, r + 1, row_first(scene, index, n, r), attribute);
    else
      each_skirt_vertex(tile, n, row_first(scene, index, n, r), attribute);
  }
  return next;
}

// The nearest horizontal distance (metres, in the eye's ENU frame) from the eye to `cell`: 0 when
// the eye is above it. The cell's boundary is sampled at 4 points per edge.
double horizontal_distance(const Grid& grid, const PinholeCamera& camera, CellId cell) {
  std::vector<std::array<double, 2>> ring;
  for (const LonLat& p : grid.boundary(cell, 4)) {
    const auto e = camera.frame().to_enu(p.lon, p.lat, 0);
    ring.push_back({e[0], e[1]});
  }
  bool inside = false;
  double nearest = INFINITY;
  for (size_t k = 0; k + 1 < ring.size(); ++k) {
    const auto& a = ring[k];
    const auto& b = ring[k + 1];
    if ((a[1] > 0) != (b[1] > 0) && 0 < a[0] + (0 - a[1]) * (b[0] - a[0]) / (b[1] - a[1]))
      inside = !inside;
    const double dx = b[0] - a[0], dy = b[1] - a[1], len2 = dx * dx + dy * dy;
    const double t = len2 == 0 ? 0 : std::clamp(-(a[0] * dx + a[1] * dy) / len2, 0.0, 1.0);
    nearest = std::min(nearest, std::hypot(a[0] + t * dx, a[1] + t * dy));
  }
  return inside ? 0 : nearest;
}

// Heights (metres above the DEM's datum) no DEM on Earth goes beyond, bathymetry included (the
// Challenger Deep: -10,935 m), and the geoid's separation from the ellipsoid.
constexpr double kLowest = -11000, kHighest = 9000, kGeoid = 120;

// Where `points` (the eye's ENU frame), their convex hull widened by `margin` metres, lie: wholly
// beyond one side of the picture (the plane through the eye and that side) or behind the eye (every
// point more than `margin` beyond it), wholly inside the view (every point more than `margin`
// inside every side and in front of the eye), or across.
enum class ViewSide { kOut, kIn, kAcross };
ViewSide view_side(const PinholeCamera& camera, std::span<const Vec3d> points, double margin) {
  const double half_w = camera.spec().width / 2.0 / camera.focal(),
               half_h = camera.spec().height / 2.0 / camera.focal();
  const double norm_w = std::hypot(1.0, half_w), norm_h = std::hypot(1.0, half_h);
  // Signed distances (metres) beyond the planes through the eye and the picture's sides, and
  // behind the eye: positive outside.
  std::array<double, 5> inside{-INFINITY, -INFINITY, -INFINITY, -INFINITY, -INFINITY},
      outside = inside;
  for (const Vec3d& p : points) {
    const Vec3d v = camera.to_view(p);
    const double beyond[5] = {(-v[0] - half_w * v[2]) / norm_w, (v[0] - half_w * v[2]) / norm_w,
                              (-v[1] - half_h * v[2]) / norm_h, (v[1] - half_h * v[2]) / norm_h,
                              -v[2]};
    for (size_t k = 0; k < 5; ++k) inside[k] = std::max(inside[k], -beyond[k]);
    for (size_t k = 0; k < 5; ++k) outside[k] = std::max(outside[k], beyond[k]);
  }
  if (std::any_of(inside.begin(), inside.end(), [&](double d) { return d < -margin; }))
    return ViewSide::kOut;
  return std::all_of(outside.begin(), outside.end(), [&](double d) { return d < -margin; })
             ? ViewSide::kIn
             : ViewSide::kAcross;
}

// Whether `cell`, widened by `margin` metres, between the lowest and highest heights, lies wholly
// beyond one side of the picture or behind the eye. Its boundary is sampled at 8 points per edge
// (the margin covers the chords).
bool out_of_view(const Grid& grid, const PinholeCamera& camera, CellId cell, double margin,
                 double exaggeration) {
  std::vector<Vec3d> points;
  for (const LonLat& p : grid.boundary(cell, 8))
    for (const double h : {kLowest * exaggeration - kGeoid, kHighest * exaggeration + kGeoid})
      points.push_back(camera.frame().to_enu(p.lon, p.lat, h));
  return view_side(camera, points, margin) == ViewSide::kOut;
}

// Where the squares of `tile`'s samples c0 .. c1, r0 .. r1 lie (view_side), for a tile whose
// places are interpolated from a lattice (SamplePlaces::interpolated): their vertices are those
// samples drawn at `exaggeration` times their heights along their places' normals (write_tile),
// within the hull of the four corners' places at the lowest and highest sample's heights. A row or
// column of places turns by at most a hundredth of a radian at a lattice node (h samples apart,
// up to 16 samples a side here), so it departs from its chord by at most 0.01 (16 / h)^2 h / 8 <=
// 0.32 samples (h >= 1), and the places from the corners' bilinear alike. The margin: a sample
// (`sample_m`) and the ellipsoid's bend (the side squared over the earth's radius: a few
// centimetres for 16 samples at level 10). Inside: no data.
ViewSide squares_side(const SceneTile& tile, int c0, int r0, int c1, int r1,
                      const PinholeCamera& camera, double sample_m, double exaggeration) {
  const auto [lowest, highest] = relief(tile.heights, c0, r0, c1, r1);
  if (!(lowest <= highest)) return ViewSide::kIn;  // no sample with data: no square to draw
  std::vector<Vec3d> hull;
  for (const auto& [c, r] : {std::pair{c0, r0}, {c1, r0}, {c0, r1}, {c1, r1}}) {
    const SamplePlace place = tile.places->ground(c, r);
    for (const float z : {lowest, highest}) hull.push_back(exaggerated(place, z, exaggeration));
  }
  const double side = double(std::max(c1 - c0, r1 - r0)) * sample_m;
  return view_side(camera, hull, sample_m + side * side / 6.3e6);
}

// Per patch of `tile`'s squares (each_patch's order), whether it is drawn: with `cull`, not when
// it lies wholly out of the view (squares_side). The patches along the halo's ring (placed
// exactly, perhaps on another face) are always drawn, and so is every patch of a tile placed
// exactly (no lattice: beyond 80 degrees, across the antimeridian or a polar face's diagonal,
// where a row of samples bends by about 50 degrees on the ground and four corners bound nothing;
// bounding by every boundary sample would place each sample exactly again, for a few tiles). The
// others are looked at by groups of kGroupPatches x kGroupPatches: a group wholly out of the view
// or wholly in it decides for its patches, a group across it leaves each to its own test.
constexpr int kGroupPatches = 4;
std::vector<uint8_t> drawn_patches(const SceneTile& tile, int n, const PinholeCamera& camera,
                                   double sample_m, double exaggeration, bool cull) {
  const int patches = tile_patches(n);
  std::vector<uint8_t> drawn(size_t(patches) * size_t(patches), 1);
  if (!cull || !tile.places->interpolated()) return drawn;
  // The inside patches: 1 .. patches - 2 a side (squares from 3 .. n - 1: samples 3 .. n - 1).
  auto first_sample = [](int patch) { return -1 + patch * kBlockSquares; };
  for (int gr = 1; gr < patches - 1; gr += kGroupPatches)
    for (int gc = 1; gc < patches - 1; gc += kGroupPatches) {
      const int gr1 = std::min(patches - 1, gr + kGroupPatches),
                gc1 = std::min(patches - 1, gc + kGroupPatches);
      const ViewSide group =
          squares_side(tile, first_sample(gc), first_sample(gr), first_sample(gc1),
                       first_sample(gr1), camera, sample_m, exaggeration);
      if (group == ViewSide::kIn) continue;
      for (int pr = gr; pr < gr1; ++pr)
        for (int pc = gc; pc < gc1; ++pc)
          drawn[size_t(pr) * size_t(patches) + size_t(pc)] =
              group == ViewSide::kAcross &&
              squares_side(tile, first_sample(pc), first_sample(pr), first_sample(pc + 1),
                           first_sample(pr + 1), camera, sample_m, exaggeration) != ViewSide::kOut;
    }
  return drawn;
}

}  // namespace

std::vector<CellId> scene_cells(const Store& store, const Grid& grid, const LayerInfo& dem,
                                const PinholeCamera& camera, double sample_pixels,
                                double exaggeration, bool cull) {
  const std::vector<CellId> tiles = store.tile_cells(dem.name);
  if (!(sample_pixels > 0) || tiles.empty()) return tiles;
  const std::vector<int> levels = store.stats(dem.name).levels;  // ascending, the base last
  auto holds_tiles = [&](CellId c) {
    const auto it = std::lower_bound(tiles.begin(), tiles.end(), c.range_min());
    return it != tiles.end() && *it <= c.range_max();
  };
  std::vector<CellId> cells;
  std::function<void(CellId)> visit = [&](CellId c) {
    const int level = c.level();
    const LevelInfo info = grid.level_info(level, dem.tile_size);
    const double sample = info.pixel_m;
    // The halo's ring and skirt reach a sample beyond the cell, its boundary's chords cut inside
    // it, and the ground between its edges bulges above them (the earth's curvature).
    const double margin =
        2 * sample + info.cell_side_m / 16 + info.cell_side_m * info.cell_side_m / (4 * 6.3e6);
    if (cull && out_of_view(grid, camera, c, margin, exaggeration)) return;
    if (level == dem.level ||
        (std::binary_search(levels.begin(), levels.end(), level) &&
         sample * camera.focal() <= sample_pixels * horizontal_distance(grid, camera, c))) {
      cells.push_back(c);
      return;
    }
    for (int digit = 0; digit < 4; ++digit)
      if (holds_tiles(c.child(digit))) visit(c.child(digit));
  };
  for (size_t i = 0; i < tiles.size(); ++i) {
    const CellId root = tiles[i].parent(levels.front());
    if (i == 0 || tiles[i - 1].parent(levels.front()) != root) visit(root);
  }
  return cells;
}

void check_exaggeration(double exaggeration) {
  if (!(exaggeration > 0) || !std::isfinite(exaggeration))
    throw Error("--exaggeration " + std::to_string(exaggeration) + " must be positive and finite");
}

TerrainScene build_terrain_scene(const Store& store, const Grid& grid, const LayerInfo& dem,
                                 const PinholeCamera& camera, double exaggeration,
                                 double sample_pixels, bool cull,
                                 std::shared_ptr<const EllipsoidalHeights> datum,
                                 std::shared_ptr<LayerSampler::Tiles> tiles) {
  check_exaggeration(exaggeration);
  if (!(sample_pixels >= 0))
    throw Error("--sample-pixels " + std::to_string(sample_pixels) + " must be 0 or more");
  const std::vector<CellId> cells =
      scene_cells(store, grid, dem, camera, sample_pixels, exaggeration, cull);
  if (cells.empty()) {
    if (store.tile_cells(dem.name).empty())
      throw Error("--dem layer '" + dem.name + "' holds no tiles");
    // Its tiles all out of the view (scene_cells' cull): a camera aimed away or far from the store.
    const LonLatBounds b = lonlat_bounds(grid, store.tile_cells(dem.name));
    throw Error(fmt::format(
        "none of the --dem layer '{}' (lon {:.4f} to {:.4f}, lat {:.4f} to {:.4f}) is in the "
        "camera's view ({}): aim it at the terrain",
        dem.name, b.west, b.east > 180 ? b.east - 360 : b.east, b.south, b.north,
        view_text(camera.spec())));
  }
  TerrainScene scene;
  scene.heights = given_or_made(std::move(datum), dem);
  const EllipsoidalHeights& heights = *scene.heights;
  const int n = dem.tile_size;
  scene.cells = cells;
  scene.exaggeration = exaggeration;
  scene.tiles.resize(cells.size());
  // The tiles read and their shares counted in parallel, then each written in place, in cell order.
  std::vector<TileShare> shares(cells.size());
  {
    // The caller's tiles (kept for its cast shadows), else ours, dropped once the halos are made.
    if (!tiles) tiles = LayerSampler::shared_tiles(store, grid, dem, dem.level);
    std::vector<CellId> sorted_cells = cells;
    std::sort(sorted_cells.begin(), sorted_cells.end());
    tbb::parallel_for(size_t(0), cells.size(), [&](size_t i) {
      SceneTile& tile = scene.tiles[i];
      tile.heights = tile_heights(grid, dem, cells[i], *tiles);
      tile.skirted = skirted_edges(grid, cells[i], n, sorted_cells);
      tile.places.emplace(grid, cells[i], n, kHalo, camera.frame(), heights);
      tile.drawn = drawn_patches(tile, n, camera, grid.level_info(cells[i].level(), n).pixel_m,
                                 exaggeration, cull);
      shares[i] = tile_share(tile, n);
    });
    tiles.reset();
  }
  std::vector<size_t> first_index(cells.size() + 1, 0);
  size_t vertices = 0;
  for (size_t i = 0; i < cells.size(); ++i) {
    scene.tiles[i].first_vertex = vertices;
    vertices += shares[i].vertices;
    first_index[i + 1] = first_index[i] + shares[i].indices;
  }
  // Sized, not filled: each tile writes every element of its share of the mesh. The attributes'
  // room for every vertex reserved (pages untouched until written): attribute_vertices adds slots
  // strip by strip without moving them.
  scene.mesh.positions.resize(3 * vertices);
  scene.mesh.indices.resize(first_index.back());
  scene.mesh.block_first.resize(cells.size() * tile_blocks(n));
  scene.lonlat.reserve(2 * vertices);
  scene.plane.reserve(2 * vertices);
  scene.altitude.reserve(vertices);
  scene.normals.reserve(3 * vertices);
  scene.slot.assign(vertices, TerrainScene::kNoSlot);
  tbb::parallel_for(size_t(0), cells.size(), [&](size_t i) {
    write_tile(grid, dem, cells[i], scene.tiles[i], shares[i], camera, heights, exaggeration,
               first_index[i], i * tile_blocks(n), scene.mesh);
  });
  return scene;
}

void attribute_vertices(TerrainScene& scene, const Fragments* f) {
  auto& slot = scene.slot;
  constexpr uint32_t kNoSlot = TerrainScene::kNoSlot, kAsked = TerrainScene::kAsked;
  if (!f) {
    for (uint32_t& s : slot)
      if (s == kNoSlot) s = kAsked;
  } else {
    // Relaxed atomic stores: two rows may share a triangle's vertex (the same element, the same
    // value).
    tbb::parallel_for(0, f->height, [&](int row) {
      uint32_t previous = Fragments::kSky;
      for (size_t i = size_t(row) * size_t(f->width), end = i + size_t(f->width); i < end; ++i) {
        const uint32_t t = f->triangle[i];
        if (t == Fragments::kSky || t == previous) continue;
        previous = t;
        for (size_t j = 0; j < 3; ++j) {
          std::atomic_ref<uint32_t> s(slot[scene.mesh.indices[3 * size_t(t) + j]]);
          if (s.load(std::memory_order_relaxed) == kNoSlot)
            s.store(kAsked, std::memory_order_relaxed);
        }
      }
    });
  }
  if (scene.tiles.empty()) return;
  const int n = scene.tiles.front().heights.size();
  // Rows -1 .. n + 1 of each tile (n + 1: its skirt) in parts of kAttributeRows; each task's
  // vertices asked for counted, then given the slots after the earlier tasks' (vertex order).
  const int parts = (n + 3 + kAttributeRows - 1) / kAttributeRows;
  const size_t tasks = scene.tiles.size() * size_t(parts);
  auto rows = [&](size_t task) {
    const int r0 = -1 + int(task % size_t(parts)) * kAttributeRows;
    return std::pair{r0, std::min(n + 2, r0 + kAttributeRows)};
  };
  std::vector<size_t> first_slot(tasks + 1, 0);
  tbb::parallel_for(size_t(0), tasks, [&](size_t task) {
    const auto [r0, r1] = rows(task);
    const size_t index = task / size_t(parts);
    first_slot[task + 1] =
        size_t(std::count(slot.begin() + std::ptrdiff_t(row_first(scene, index, n, r0)),
                          slot.begin() + std::ptrdiff_t(row_first(scene, index, n, r1)), kAsked));
  });
  first_slot[0] = scene.altitude.size();
  std::partial_sum(first_slot.begin(), first_slot.end(), first_slot.begin());
  const size_t slots = first_slot.back();
  scene.lonlat.resize(2 * slots);
  scene.plane.resize(2 * slots);
  scene.altitude.resize(slots);
  scene.normals.resize(3 * slots);
  tbb::enumerable_thread_specific<PositionMemo> memos;
  tbb::parallel_for(size_t(0), tasks, [&](size_t task) {
    const auto [r0, r1] = rows(task);
    const size_t end =
        attribute_tile(scene, task / size_t(parts), n, r0, r1, first_slot[task], memos.local());
    if (end != first_slot[task + 1])  // every slot given is written
      throw std::logic_error("panorama attributes of cell " +
                             scene.cells[task / size_t(parts)].ToText() + " rows " +
                             std::to_string(r0) + " to " + std::to_string(r1) + ": wrote " +
                             std::to_string(end - first_slot[task]) + " vertices, counted " +
                             std::to_string(first_slot[task + 1] - first_slot[task]));
  });
}

TerrainHeights::TerrainHeights(const Store& store, const Grid& grid, const LayerInfo& dem,
                               double exaggeration, std::shared_ptr<const EllipsoidalHeights> datum)
    : grid_(grid),
      dem_(dem),
      sampler_(store, grid, dem_, dem_.level, LayerSampler::Read::kBilinear),
      heights_(given_or_made(std::move(datum), dem_)),
      exaggeration_(exaggeration) {
  check_exaggeration(exaggeration);
}

std::optional<double> TerrainHeights::operator()(LonLat p) {
  float z = NAN;
  if (!sampler_.sample(p, grid_.cell_from_point(p, dem_.level), &z) || std::isnan(z))
    return std::nullopt;
  return (*heights_)(p, z) + (exaggeration_ - 1) * z;
}

}  // namespace maquette
