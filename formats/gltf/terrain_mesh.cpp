#include "gltf/terrain_mesh.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace maquette {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// The pixel corners of a tile (with one corner of margin for normals), computed on demand.
class CornerField {
 public:
  CornerField(const Grid& grid, CellId cell, const Tile<float>& dem, const LocalFrame& frame,
              const EllipsoidalHeights& heights)
      : grid_(grid),
        cell_(cell),
        dem_(dem),
        frame_(frame),
        heights_(heights),
        n_(dem.size()),
        pixel_level_(cell.level() + log2_tile_size(dem.size())),
        face_pixels_(int64_t(1) << pixel_level_),
        cache_(size_t(n_ + 3) * size_t(n_ + 3)) {}

  struct Corner {
    bool done = false;
    double height = kNaN;
    LonLat lonlat;
    Vec3 pos{};
  };

  // Corner (c, r) of the tile, c and r in [-1, n + 1]; nullptr beyond a face corner or without
  // data.
  const Corner* at(int c, int r) {
    Corner& k = cache_[size_t(r + 1) * size_t(n_ + 3) + size_t(c + 1)];
    if (!k.done) compute(c, r, k);
    return std::isnan(k.height) ? nullptr : &k;
  }

  // Whether corner (c, r) is a corner of the face, where three faces meet.
  bool face_corner(int c, int r) const {
    const int64_t gc = global_col(cell_, n_, c), gr = global_row(cell_, n_, r);
    return (gc == 0 || gc == face_pixels_) && (gr == 0 || gr == face_pixels_);
  }

  const LocalFrame& frame() const { return frame_; }

 private:
  bool outside(int64_t g) const { return g < 0 || g >= face_pixels_; }

  // Where corner (gc, gr) of the face's pixel grid is on the plane: on the face, or on the face
  // across the one edge it is beyond (for normals across face seams); nullopt beyond a face
  // corner. Beyond an edge, the pixels (gc - 1, gr - 1) and (gc, gr) are diagonal neighbours
  // beyond that edge; wrapped onto the next face (turned as the faces meet), the corner is the
  // one they share.
  std::optional<PlanePoint> plane_point(int64_t gc, int64_t gr) const {
    int face = cell_.face();
    const bool col_out = gc < 0 || gc > face_pixels_, row_out = gr < 0 || gr > face_pixels_;
    if (col_out && row_out) return std::nullopt;
    if (col_out || row_out) {
      if ((col_out && (gr < 1 || gr >= face_pixels_)) ||
          (row_out && (gc < 1 || gc >= face_pixels_)))
        return std::nullopt;
      const auto a = grid_.wrap({face, gc - 1, gr - 1}, pixel_level_);
      const auto b = grid_.wrap({face, gc, gr}, pixel_level_);
      if (!a || !b || a->face != b->face) return std::nullopt;
      face = a->face;
      gc = std::max(a->col, b->col);
      gr = std::max(a->row, b->row);
    }
    const PlaneSquare sq = grid_.plane_square(CellId::FromFace(face));
    const double pixel = sq.side / double(face_pixels_);
    return PlanePoint{sq.x_min + double(gc) * pixel, sq.y_max - double(gr) * pixel};
  }

  void compute(int c, int r, Corner& k) {
    k.done = true;
    const int64_t gc = global_col(cell_, n_, c), gr = global_row(cell_, n_, r);
    const auto plane = plane_point(gc, gr);
    if (!plane) return;
    // Mean of the finite pixels around the corner, summed in sorted order so that every cell
    // sharing the corner (whatever its face's orientation) gets the same bits. A halo pixel
    // beyond both edges of a face is a folded copy of another one (core/halo.h): skipped.
    double v[4];
    int count = 0;
    for (int dr = -1; dr <= 0; ++dr)
      for (int dc = -1; dc <= 0; ++dc) {
        if (outside(gc + dc) && outside(gr + dr)) continue;
        const float h = dem_.at(c + dc, r + dr);
        if (!std::isfinite(h)) continue;
        int i = count++;  // insertion into the sorted prefix
        for (; i > 0 && v[i - 1] > h; --i) v[i] = v[i - 1];
        v[i] = h;
      }
    if (count == 0) return;
    double sum = 0;
    for (int i = 0; i < count; ++i) sum += v[i];
    k.lonlat = grid_.inverse(*plane);
    k.height = heights_(k.lonlat, sum / count);
    k.pos = frame_.to_gltf(k.lonlat, k.height);
  }

  const Grid& grid_;
  CellId cell_;
  const Tile<float>& dem_;
  const LocalFrame& frame_;
  const EllipsoidalHeights& heights_;
  int n_;
  int pixel_level_;
  int64_t face_pixels_;
  std::vector<Corner> cache_;
};

// Unit normal at corner (c, r) from central differences of the neighbouring pixel corners, also
// across face seams (one-sided where a neighbour has no data).
Vec3 normal_at(CornerField& f, int c, int r) {
  const Vec3& p = f.at(c, r)->pos;
  if (f.face_corner(c, r)) {
    // Three faces meet here, each with its own two neighbours of the vertex: the ellipsoid's
    // normal, the same from every face.
    const auto* k = f.at(c, r);
    const Vec3 up = sub(f.frame().to_gltf(k->lonlat, k->height + 1), p);
    const double len = std::sqrt(up[0] * up[0] + up[1] * up[1] + up[2] * up[2]);
    return {up[0] / len, up[1] / len, up[2] / len};
  }
  auto pos = [&](int cc, int rr) {
    const auto* k = f.at(cc, rr);
    return k ? k->pos : p;
  };
  Vec3 n = cross(sub(pos(c + 1, r), pos(c - 1, r)), sub(pos(c, r - 1), pos(c, r + 1)));
  const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  if (len == 0) return {0, 1, 0};
  return {n[0] / len, n[1] / len, n[2] / len};
}

class MeshBuilder {
 public:
  MeshBuilder(TerrainMesh& m, size_t max_vertices, size_t max_triangles) : m_(m) {
    m_.positions.reserve(3 * max_vertices);
    m_.normals.reserve(3 * max_vertices);
    m_.texcoords.reserve(2 * max_vertices);
    m_.indices.reserve(3 * max_triangles);
    m_.min_height = std::numeric_limits<double>::max();
    m_.max_height = std::numeric_limits<double>::lowest();
  }
  uint32_t add(const Vec3& p, const Vec3& n, float u, float v, double height) {
    for (int i = 0; i < 3; ++i) {
      m_.positions.push_back(p[size_t(i)]);
      m_.normals.push_back(float(n[size_t(i)]));
    }
    m_.texcoords.push_back(u);
    m_.texcoords.push_back(v);
    m_.min_height = std::min(m_.min_height, height);
    m_.max_height = std::max(m_.max_height, height);
    return uint32_t(m_.vertex_count() - 1);
  }
  void triangle(uint32_t a, uint32_t b, uint32_t c) {
    m_.indices.insert(m_.indices.end(), {a, b, c});
  }

 private:
  TerrainMesh& m_;
};

constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();

}  // namespace

TerrainMesh build_terrain_mesh(const Grid& grid, CellId cell, const Tile<float>& dem,
                               int decimation, const LocalFrame& frame, double skirt_depth,
                               const EllipsoidalHeights& heights) {
  const int n = dem.size(), k = decimation, m = n / k;
  CornerField field(grid, cell, dem, frame, heights);
  TerrainMesh mesh;
  // At most: the grid and a lowered copy of its edge loop; two triangles per grid square and
  // per skirt quad.
  MeshBuilder b(mesh, size_t(m + 1) * size_t(m + 1) + 4 * size_t(m),
                2 * size_t(m) * size_t(m) + 8 * size_t(m));

  // Grid vertices (only corners with data, so that every vertex is referenced).
  std::vector<uint32_t> id(size_t(m + 1) * size_t(m + 1), kNone);
  auto vid = [&](int i, int j) -> uint32_t& { return id[size_t(j) * size_t(m + 1) + size_t(i)]; };
  const double lon0 = grid.centre(cell).lon;
  LonLatBounds& where = mesh.lonlat;
  for (int j = 0; j <= m; ++j)
    for (int i = 0; i <= m; ++i)
      if (const auto* c = field.at(i * k, j * k)) {
        vid(i, j) = b.add(c->pos, normal_at(field, i * k, j * k), float(i) / float(m),
                          float(j) / float(m), c->height);
        const double lon = lon0 + std::remainder(c->lonlat.lon - lon0, 360.0);
        where = {std::min(where.west, lon), std::min(where.south, c->lonlat.lat),
                 std::max(where.east, lon), std::max(where.north, c->lonlat.lat)};
        mesh.at_pole = mesh.at_pole || std::abs(c->lonlat.lat) == 90;
      }
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) {
      const uint32_t a = vid(i, j), r = vid(i + 1, j), d = vid(i, j + 1), dr = vid(i + 1, j + 1);
      if (a != kNone && d != kNone && r != kNone) b.triangle(a, d, r);
      if (r != kNone && d != kNone && dr != kNone) b.triangle(r, d, dr);
    }

  // Skirts: the edge loop (clockwise seen from above: top, right, bottom, left edges) with a
  // lowered copy of each vertex, joined by quads facing outwards.
  std::vector<std::pair<int, int>> loop;
  for (int i = 0; i < m; ++i) loop.emplace_back(i, 0);
  for (int j = 0; j < m; ++j) loop.emplace_back(m, j);
  for (int i = m; i > 0; --i) loop.emplace_back(i, m);
  for (int j = m; j > 0; --j) loop.emplace_back(0, j);
  std::vector<uint32_t> low(loop.size(), kNone);
  for (size_t s = 0; s < loop.size(); ++s) {
    const auto [i, j] = loop[s];
    const uint32_t top = vid(i, j);
    if (top == kNone) continue;
    const auto* c = field.at(i * k, j * k);
    const Vec3 nrm = {mesh.normals[3 * top], mesh.normals[3 * top + 1], mesh.normals[3 * top + 2]};
    low[s] = b.add(frame.to_gltf(c->lonlat, c->height - skirt_depth), nrm, float(i) / float(m),
                   float(j) / float(m), c->height - skirt_depth);
  }
  for (size_t s = 0; s < loop.size(); ++s) {
    const size_t t = (s + 1) % loop.size();
    const uint32_t a = vid(loop[s].first, loop[s].second);
    const uint32_t c = vid(loop[t].first, loop[t].second);
    if (low[s] == kNone || low[t] == kNone) continue;
    b.triangle(a, c, low[s]);
    b.triangle(c, low[t], low[s]);
  }
  return mesh;
}

}  // namespace maquette
