#include "render/terrain_scene.h"

#include <tbb/parallel_for.h>

#include <cmath>
#include <limits>

#include "core/error.h"
#include "core/halo.h"
#include "core/tile_frame.h"
#include "gdal/vertical_datum.h"
#include "image/layer_sampler.h"

namespace maquette {
namespace {

constexpr uint32_t kNoVertex = std::numeric_limits<uint32_t>::max();

// One tile's share of the mesh, with indices local to its vertices.
TerrainScene tile_part(const Store& store, const Grid& grid, const LayerInfo& dem, CellId cell,
                       const PinholeCamera& camera, const EllipsoidalHeights& heights,
                       double exaggeration) {
  const int n = dem.tile_size;
  const double* nodata = dem.nodata ? &*dem.nodata : nullptr;
  const Tile<float> tile =
      assemble_halo(grid, cell, n, 1, [&](CellId c) -> std::optional<Tile<float>> {
        const auto raw = store.get_tile(dem.name, c);
        if (!raw) return std::nullopt;
        return to_tile<float>(*raw, nodata);
      });
  const TileFrame frame(grid, cell, n);
  const int side = n + 1;  // samples 0 .. n (n: the halo's)
  std::vector<uint32_t> vertex(size_t(side) * size_t(side), kNoVertex);
  TerrainScene part;
  for (int r = 0; r <= n; ++r)
    for (int c = 0; c <= n; ++c) {
      const float z = tile.at(c, r);
      if (std::isnan(z) || !frame.known(c, r)) continue;
      const LonLat p = frame.position(c, r);
      const double h = heights(p, z) + (exaggeration - 1) * z;
      const auto e = camera.frame().to_enu(p.lon, p.lat, h);
      vertex[size_t(r) * size_t(side) + size_t(c)] = uint32_t(part.altitude.size());
      part.mesh.positions.insert(part.mesh.positions.end(), e.begin(), e.end());
      part.lonlat.insert(part.lonlat.end(), {p.lon, p.lat});
      part.altitude.push_back(z);
    }
  auto at = [&](int c, int r) {
    return c < 0 || r < 0 || c > n || r > n ? kNoVertex
                                            : vertex[size_t(r) * size_t(side) + size_t(c)];
  };
  // Normals: the cross product of the column and row differences, turned up.
  part.normals.resize(part.altitude.size() * 3);
  for (int r = 0; r <= n; ++r)
    for (int c = 0; c <= n; ++c) {
      const uint32_t v = at(c, r);
      if (v == kNoVertex) continue;
      auto diff = [&](uint32_t a, uint32_t b) {
        const double* pa = &part.mesh.positions[3 * size_t(a)];
        const double* pb = &part.mesh.positions[3 * size_t(b)];
        return Vec3d{pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2]};
      };
      auto span = [&](uint32_t before, uint32_t after) {
        if (before == kNoVertex) before = v;
        if (after == kNoVertex) after = v;
        return diff(before, after);
      };
      const Vec3d u = span(at(c - 1, r), at(c + 1, r)), w = span(at(c, r - 1), at(c, r + 1));
      Vec3d nrm{u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
      const double len = std::sqrt(nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]);
      // The up direction at the vertex: from the earth's centre, near enough for the sign.
      const double* pv = &part.mesh.positions[3 * size_t(v)];
      const double up = nrm[0] * pv[0] + nrm[1] * pv[1] + nrm[2] * (pv[2] + 6.371e6);
      const double s = len == 0 ? 0 : (up < 0 ? -1 : 1) / len;
      for (int k = 0; k < 3; ++k)
        part.normals[3 * size_t(v) + size_t(k)] = float(nrm[size_t(k)] * s);
      if (len == 0) part.normals[3 * size_t(v) + 2] = 1;
    }
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) {
      const uint32_t a = at(c, r), b = at(c + 1, r), d = at(c, r + 1), e = at(c + 1, r + 1);
      if (a == kNoVertex || b == kNoVertex || d == kNoVertex || e == kNoVertex) continue;
      part.mesh.indices.insert(part.mesh.indices.end(), {a, b, e, a, e, d});
    }
  return part;
}

}  // namespace

TerrainScene build_terrain_scene(const Store& store, const Grid& grid, const LayerInfo& dem,
                                 const PinholeCamera& camera, double exaggeration) {
  if (!(exaggeration > 0))
    throw Error("vertical exaggeration " + std::to_string(exaggeration) + " must be positive");
  const std::vector<CellId> cells = store.tile_cells(dem.name);
  if (cells.empty()) throw Error("--dem layer '" + dem.name + "' holds no tiles");
  const EllipsoidalHeights heights = ellipsoidal_heights(dem);
  std::vector<TerrainScene> parts(cells.size());
  tbb::parallel_for(size_t(0), cells.size(), [&](size_t i) {
    parts[i] = tile_part(store, grid, dem, cells[i], camera, heights, exaggeration);
  });
  TerrainScene scene;
  for (const TerrainScene& part : parts) {
    const auto base = uint32_t(scene.altitude.size());
    auto append = [](auto& to, const auto& from) { to.insert(to.end(), from.begin(), from.end()); };
    append(scene.mesh.positions, part.mesh.positions);
    append(scene.lonlat, part.lonlat);
    append(scene.altitude, part.altitude);
    append(scene.normals, part.normals);
    for (const uint32_t i : part.mesh.indices) scene.mesh.indices.push_back(base + i);
  }
  return scene;
}

std::optional<double> terrain_ellipsoidal_height(const Store& store, const Grid& grid,
                                                 const LayerInfo& dem, LonLat p) {
  LayerSampler sampler(store, grid, dem, dem.level, true);
  float z = NAN;
  if (!sampler.sample(p, grid.cell_from_point(p, dem.level), &z) || std::isnan(z))
    return std::nullopt;
  return ellipsoidal_heights(dem)(p, z);
}

}  // namespace maquette
