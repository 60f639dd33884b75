#include "city_content.h"

#include <GeographicLib/LocalCartesian.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <numeric>
#include <random>

#include "content/prototypes.h"
#include "core/error.h"
#include "gdal/image_file.h"
#include "rhealpix/rhealpix_grid.h"

namespace maquette::bench {
namespace {

using Point = std::array<double, 2>;
using Ring = std::vector<Point>;  // lon, lat or east, north; no repeated closing vertex

double unit(std::mt19937& rng) { return double(rng()) / 4294967296.0; }  // [0, 1), any library

// The east-north-up frame of a cell's centre at height 0.
GeographicLib::LocalCartesian cell_frame(const RHealpixGrid& grid, CellId cell, EnuOrigin& origin) {
  const LonLat c = grid.centre(cell);
  origin = {c.lon, c.lat, 0};
  return GeographicLib::LocalCartesian(c.lat, c.lon, 0);
}

}  // namespace

std::map<CellId, InstancesContent> town_trees(const TownSettings& s) {
  const RHealpixGrid grid;
  const GeographicLib::LocalCartesian corner(s.south, s.west, 0);
  std::mt19937 rng(s.seed);
  struct Tree {
    double lon, lat;
    uint16_t prototype;
    float heading, height, width;
    uint32_t colour;
    int64_t stroke;
  };
  std::map<CellId, std::vector<Tree>> trees;
  for (size_t i = 0; i < s.instances; ++i) {
    const double east = unit(rng) * s.side_m, north = unit(rng) * s.side_m;
    Tree t{};
    double h = 0;
    corner.Reverse(east, north, 0, t.lat, t.lon, h);
    t.prototype = uint16_t(rng() % 3);  // conifer, broadleaf, shrub
    t.heading = float(unit(rng) * 2 * M_PI);
    // Heights in metres: conifers 8-25, broadleaves 6-20, shrubs 0.5-2.5; crowns vary by 20 %.
    const std::array<std::array<double, 2>, 3> heights{{{8, 25}, {6, 20}, {0.5, 2.5}}};
    t.height = float(heights[t.prototype][0] +
                     unit(rng) * (heights[t.prototype][1] - heights[t.prototype][0]));
    t.width = float(t.height * (0.9 + 0.2 * unit(rng)));
    t.colour = 0xff000000u;  // a tint near white, opaque
    for (int k = 0; k < 3; ++k) t.colour |= uint32_t(200 + rng() % 56) << (8 * k);
    // The vegetation stroke that planted it: one per square kilometre.
    t.stroke = int64_t(north / 1000) * int64_t(std::ceil(s.side_m / 1000)) + int64_t(east / 1000);
    trees[grid.cell_from_point({t.lon, t.lat}, s.level)].push_back(t);
  }
  const std::vector<std::string>& names = builtin_prototype_names();
  std::map<CellId, InstancesContent> cells;
  uint64_t next_id = 1;
  for (const auto& [cell, list] : trees) {
    InstancesContent& c = cells[cell];
    const GeographicLib::LocalCartesian frame = cell_frame(grid, cell, c.origin);
    c.prototypes = names;
    for (const Tree& t : list) {
      double x = 0, y = 0, z = 0;
      frame.Forward(t.lat, t.lon, 0, x, y, z);
      c.prototype.push_back(t.prototype);
      c.position.insert(c.position.end(), {float(x), float(y), float(z)});
      c.rotation.insert(c.rotation.end(), {0, 0, std::sin(t.heading / 2), std::cos(t.heading / 2)});
      c.scale.insert(c.scale.end(), {t.width, t.width, t.height});
      c.colour.push_back(t.colour);
      c.provenance.push_back(
          {next_id++, t.stroke, "structures.vegetation", nlohmann::json::object()});
    }
  }
  return cells;
}

namespace {

Ring read_ring(const nlohmann::json& polygon, const std::string& where) {
  if (!polygon.is_array() || polygon.size() != 1)
    throw Error(where + ": a footprint is not a polygon of one ring");
  Ring ring;
  for (const auto& p : polygon[0]) {
    const Point q{p.at(0).get<double>(), p.at(1).get<double>()};
    if (ring.empty() || ring.back() != q) ring.push_back(q);
  }
  if (ring.size() > 1 && ring.front() == ring.back()) ring.pop_back();
  if (ring.size() < 3) throw Error(where + ": a footprint has fewer than 3 vertices");
  return ring;
}

std::vector<Ring> read_footprints(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Error("cannot read " + path);
  const nlohmann::json doc = nlohmann::json::parse(in, nullptr, false);
  if (doc.is_discarded() || !doc.contains("features")) throw Error(path + ": not GeoJSON features");
  std::vector<Ring> rings;
  for (const auto& f : doc["features"])
    rings.push_back(read_ring(f["geometry"]["coordinates"], path));
  return rings;
}

double cross(const Point& a, const Point& b, const Point& c) {
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

// Triangles of a simple counter-clockwise polygon by ear clipping (footprints have < 100
// vertices: the quadratic search is no concern).
std::vector<uint32_t> triangulate(const Ring& p) {
  std::vector<uint32_t> left(p.size()), triangles;
  std::iota(left.begin(), left.end(), 0u);
  while (left.size() > 3) {
    const size_t n = left.size();
    size_t ear = n;
    for (size_t i = 0; i < n && ear == n; ++i) {
      const uint32_t a = left[(i + n - 1) % n], b = left[i], c = left[(i + 1) % n];
      if (cross(p[a], p[b], p[c]) <= 0) continue;  // reflex (or flat) corner
      const bool empty = std::none_of(left.begin(), left.end(), [&](uint32_t q) {
        return q != a && q != b && q != c && cross(p[a], p[b], p[q]) >= 0 &&
               cross(p[b], p[c], p[q]) >= 0 && cross(p[c], p[a], p[q]) >= 0;
      });
      if (empty) {
        ear = i;
        triangles.insert(triangles.end(), {a, b, c});
      }
    }
    if (ear == n) throw Error("a footprint is not a simple polygon (no ear left to clip)");
    left.erase(left.begin() + ptrdiff_t(ear));
  }
  triangles.insert(triangles.end(), left.begin(), left.end());
  return triangles;
}

double signed_area(const Ring& r) {
  double a = 0;
  for (size_t i = 0; i < r.size(); ++i)
    a += r[i][0] * r[(i + 1) % r.size()][1] - r[(i + 1) % r.size()][0] * r[i][1];
  return a / 2;
}

// A prism over `ring` (east, north; counter-clockwise) from z = 0 to `height`: a flat roof and
// one quad per wall, flat normals; uvs in the texture's two halves (roof left, walls right: each
// wall spans the wall half once).
MeshObject prism(const Ring& ring, float height) {
  MeshObject o;
  const auto vertex = [&](const Point& p, float z, std::array<float, 3> n, float u, float v) {
    o.positions.insert(o.positions.end(), {float(p[0]), float(p[1]), z});
    o.normals.insert(o.normals.end(), n.begin(), n.end());
    o.uvs.insert(o.uvs.end(), {u, v});
  };
  double x0 = ring[0][0], x1 = x0, y0 = ring[0][1], y1 = y0;
  for (const Point& p : ring) {
    x0 = std::min(x0, p[0]), x1 = std::max(x1, p[0]);
    y0 = std::min(y0, p[1]), y1 = std::max(y1, p[1]);
  }
  const double side = std::max(x1 - x0, y1 - y0);
  for (const Point& p : ring)
    vertex(p, height, {0, 0, 1}, float(0.5 * (p[0] - x0) / side), float((y1 - p[1]) / side));
  o.indices = triangulate(ring);
  double roof = 0;  // the triangles must cover the footprint once
  for (size_t t = 0; t < o.indices.size(); t += 3)
    roof += cross(ring[o.indices[t]], ring[o.indices[t + 1]], ring[o.indices[t + 2]]) / 2;
  if (std::abs(roof - signed_area(ring)) > 1e-6 * signed_area(ring))
    throw Error("a footprint's roof triangles do not cover it once");
  for (size_t i = 0; i < ring.size(); ++i) {
    const Point& a = ring[i];
    const Point& b = ring[(i + 1) % ring.size()];
    const double dx = b[0] - a[0], dy = b[1] - a[1], len = std::hypot(dx, dy);
    const std::array<float, 3> n{float(dy / len), float(-dx / len), 0};  // outwards: the right
    const auto base = uint32_t(o.positions.size() / 3);
    vertex(a, 0, n, 0.5f, 1), vertex(b, 0, n, 1, 1), vertex(b, height, n, 1, 0);
    vertex(a, height, n, 0.5f, 0);
    o.indices.insert(o.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
  }
  return o;
}

// 128 x 64 pixels: a roof of grey slates (left) and a brick wall with windows (right).
std::string building_texture() {
  constexpr int w = 128, h = 64;
  std::vector<uint8_t> rgb(size_t(w) * h * 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      uint8_t* p = &rgb[(size_t(y) * w + x) * 3];
      if (x < 64) {
        const int shade = 90 + ((x / 8 + (y / 4) % 2) % 2) * 20 - (y % 4 == 0) * 30;
        p[0] = p[1] = uint8_t(shade), p[2] = uint8_t(shade + 10);
      } else {
        const bool window = (x - 64) % 16 >= 5 && (x - 64) % 16 < 12 && y % 16 >= 4 && y % 16 < 12;
        const bool mortar = y % 4 == 0 || (x + (y / 4) % 2 * 4) % 8 == 0;
        const std::array<uint8_t, 3> c = window   ? std::array<uint8_t, 3>{60, 80, 110}
                                         : mortar ? std::array<uint8_t, 3>{190, 180, 160}
                                                  : std::array<uint8_t, 3>{150, 75, 50};
        std::copy(c.begin(), c.end(), p);
      }
    }
  const std::vector<uint8_t> jpeg = encode_image(rgb, w, h, 3, {"JPEG", {"QUALITY=85"}});
  return {jpeg.begin(), jpeg.end()};
}

}  // namespace

std::map<CellId, MeshContent> city_buildings(const std::string& geojson, const CitySettings& s) {
  const std::vector<Ring> soho = read_footprints(geojson);
  double west = 180, east = -180, south = 90, north = -90;
  for (const Ring& r : soho)
    for (const Point& p : r) {
      west = std::min(west, p[0]), east = std::max(east, p[0]);
      south = std::min(south, p[1]), north = std::max(north, p[1]);
    }
  // Copies side by side with a street of ~60 m between them.
  const double step_lon = east - west + 0.0009, step_lat = north - south + 0.0005;
  const RHealpixGrid grid;
  struct Building {
    Ring lonlat;
    size_t index;
  };
  std::map<CellId, std::vector<Building>> by_cell;
  for (size_t i = 0; i < s.buildings; ++i) {
    const size_t copy = i / soho.size();
    const double dlon = double(copy % size_t(s.copies_wide)) * step_lon;
    const double dlat = double(copy / size_t(s.copies_wide)) * step_lat;
    Ring r = soho[i % soho.size()];
    for (Point& p : r) p = {p[0] + dlon, p[1] + dlat};
    by_cell[grid.cell_from_point({r[0][0], r[0][1]}, s.level)].push_back({std::move(r), i});
  }
  const Material material{"building", {1, 1, 1, 1}, 0, 0.9f, building_texture(), "image/jpeg"};
  std::map<CellId, MeshContent> cells;
  for (const auto& [cell, buildings] : by_cell) {
    MeshContent& c = cells[cell];
    const GeographicLib::LocalCartesian frame = cell_frame(grid, cell, c.origin);
    c.materials = {material};
    for (const Building& b : buildings) {
      Ring enu;
      for (const Point& p : b.lonlat) {
        double x = 0, y = 0, z = 0;
        frame.Forward(p[1], p[0], 0, x, y, z);
        enu.push_back({x, y});
      }
      // Counter-clockwise, the first vertex (the anchor) kept first.
      if (signed_area(enu) < 0) std::reverse(enu.begin() + 1, enu.end());
      const auto height = float(6 + 3 * (b.index * 7 % 9));  // 6 to 30 m
      MeshObject o = prism(enu, height);
      o.material = 0;
      o.provenance = {b.index + 1, int64_t(b.index), "structures.buildings", {{"height", height}}};
      c.objects.push_back(std::move(o));
    }
  }
  return cells;
}

std::string soho_footprints_path() {
  return std::string(MAQUETTE_SHARED_DIR) + "/data/buildings/london_soho_buildings_wgs84.geojson";
}

ContentStats mesh_stats(const std::map<CellId, MeshContent>& cells) {
  ContentStats s;
  for (const auto& [cell, c] : cells)
    for (const MeshObject& o : c.objects) {
      ++s.objects;
      s.triangles += o.indices.size() / 3;
    }
  return s;
}

}  // namespace maquette::bench
