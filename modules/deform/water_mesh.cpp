#include "water_mesh.h"

#include <geos_c.h>

#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

namespace maquette::deform {
namespace {

using Corner = std::pair<int64_t, int64_t>;  // (col, row) of the corner lattice
using Point = std::array<double, 2>;         // (col, row)

Point point(Corner c) { return {double(c.first), double(c.second)}; }

// GEOS's reentrant API with its handle freed on scope exit.
struct Geos {
  GEOSContextHandle_t h = GEOS_init_r();
  Geos() = default;
  Geos(const Geos&) = delete;
  Geos& operator=(const Geos&) = delete;
  ~Geos() { GEOS_finish_r(h); }
  struct Free {
    GEOSContextHandle_t h;
    void operator()(GEOSGeometry* g) const { GEOSGeom_destroy_r(h, g); }
  };
  using Ptr = std::unique_ptr<GEOSGeometry, Free>;
  Ptr own(GEOSGeometry* g, const char* what) const {
    if (!g) throw std::runtime_error(std::string("GEOS failed: ") + what);
    return Ptr(g, Free{h});
  }
};

// The wet pixels' squares as one GEOS MultiPolygon, in (x, y) = (col, -row).
Geos::Ptr wet_squares(const Geos& geos, const BasinRaster& basin, const WaterBody& body) {
  std::vector<GEOSGeometry*> squares;
  for (const int64_t i : body.wet) {
    const double c = double(i % basin.width), r = double(i / basin.width);
    GEOSCoordSequence* s = GEOSCoordSeq_create_r(geos.h, 5, 2);
    const double xy[5][2] = {{c, -r - 1}, {c + 1, -r - 1}, {c + 1, -r}, {c, -r}, {c, -r - 1}};
    for (unsigned k = 0; k < 5; ++k) GEOSCoordSeq_setXY_r(geos.h, s, k, xy[k][0], xy[k][1]);
    squares.push_back(
        GEOSGeom_createPolygon_r(geos.h, GEOSGeom_createLinearRing_r(geos.h, s), nullptr, 0));
  }
  return geos.own(GEOSGeom_createCollection_r(geos.h, GEOS_MULTIPOLYGON, squares.data(),
                                              unsigned(squares.size())),
                  "wet squares");
}

// The top's triangles, counter-clockwise in (col, -row), as corner triples.
std::vector<std::array<Corner, 3>> top_triangles(const BasinRaster& basin, const WaterBody& body) {
  const Geos geos;
  const Geos::Ptr squares = wet_squares(geos, basin, body);
  const Geos::Ptr shore = geos.own(GEOSCoverageUnion_r(geos.h, squares.get()), "shoreline");
  const Geos::Ptr tris =
      geos.own(GEOSConstrainedDelaunayTriangulation_r(geos.h, shore.get()), "triangulation");
  std::vector<std::array<Corner, 3>> out;
  for (int k = 0; k < GEOSGetNumGeometries_r(geos.h, tris.get()); ++k) {
    const GEOSGeometry* ring =
        GEOSGetExteriorRing_r(geos.h, GEOSGetGeometryN_r(geos.h, tris.get(), k));
    const GEOSCoordSequence* s = GEOSGeom_getCoordSeq_r(geos.h, ring);
    std::array<Corner, 3> t;
    for (unsigned v = 0; v < 3; ++v) {
      double x = 0, y = 0;
      GEOSCoordSeq_getXY_r(geos.h, s, v, &x, &y);
      t[v] = {std::llround(x), -std::llround(y)};
    }
    // Counter-clockwise in (col, -row) is clockwise in (col, row).
    const int64_t cross = (t[1].first - t[0].first) * (t[2].second - t[0].second) -
                          (t[1].second - t[0].second) * (t[2].first - t[0].first);
    if (cross > 0) std::swap(t[1], t[2]);
    if (cross != 0) out.push_back(t);
  }
  return out;
}

// Vertices by corner. Where only two diagonal pixels around a corner are wet (the lake touches
// itself there, 8-connected), each of them gets its own vertices at the corner, so that every
// edge stays in two triangles. The pixel a corner is used for is its quadrant: 0 (col - 1,
// row - 1), 1 (col, row - 1), 2 (col - 1, row), 3 (col, row).
class Builder {
 public:
  Builder(const BasinRaster& basin, const WaterBody& body) : basin_(basin), body_(body) {
    wet_.assign(size_t(basin.width) * size_t(basin.height), 0);
    for (const int64_t i : body.wet) wet_[size_t(i)] = 1;
  }

  bool wet(int64_t col, int64_t row) const {
    return col >= 0 && row >= 0 && col < basin_.width && row < basin_.height &&
           wet_[size_t(row) * size_t(basin_.width) + size_t(col)];
  }

  uint32_t top(Corner c, int quadrant) { return vertex(c, quadrant, true); }
  uint32_t bottom(Corner c, int quadrant) { return vertex(c, quadrant, false); }

  // The top vertex at corner p of a triangle whose other vertices are at a and b: its quadrant
  // is where the triangle's angle at p opens (the bisector of its two edges).
  uint32_t top_at(Corner p, Point a, Point b) {
    const double ac = a[0] - double(p.first), ar = a[1] - double(p.second);
    const double bc = b[0] - double(p.first), br = b[1] - double(p.second);
    const double la = std::hypot(ac, ar), lb = std::hypot(bc, br);
    const double dc = ac / la + bc / lb, dr = ar / la + br / lb;
    return top(p, (dr > 0 ? 2 : 0) + (dc > 0 ? 1 : 0));
  }

  // A top vertex off the corner lattice (a fan's centroid).
  uint32_t top_point(Point p) {
    mesh_.vertices.push_back({p[0], p[1], body_.level});
    return uint32_t(mesh_.vertices.size() - 1);
  }

  void triangle(uint32_t a, uint32_t b, uint32_t c) {
    mesh_.indices.insert(mesh_.indices.end(), {a, b, c});
  }

  LakeMesh take() { return std::move(mesh_); }

 private:
  bool quadrant_wet(Corner c, int q) const {
    return wet(c.first - 1 + (q & 1), c.second - 1 + (q >> 1));
  }

  bool touches_itself(Corner c) const {
    const bool w0 = quadrant_wet(c, 0), w1 = quadrant_wet(c, 1), w2 = quadrant_wet(c, 2),
               w3 = quadrant_wet(c, 3);
    return (w0 && w3 && !w1 && !w2) || (w1 && w2 && !w0 && !w3);
  }

  uint32_t vertex(Corner c, int quadrant, bool top) {
    const int part = touches_itself(c) ? quadrant : -1;
    auto& ids = top ? top_ : bottom_;
    const auto [it, added] =
        ids.emplace(std::tuple(c.first, c.second, part), uint32_t(mesh_.vertices.size()));
    if (!added) return it->second;
    double height = body_.level;
    if (!top) {  // the mean terrain of the wet pixels around the corner (of the part's pixel)
      double sum = 0;
      int count = 0;
      for (int q = 0; q < 4; ++q)
        if ((part < 0 || q == part) && quadrant_wet(c, q)) {
          const size_t i = size_t(c.second - 1 + (q >> 1)) * size_t(basin_.width) +
                           size_t(c.first - 1 + (q & 1));
          sum += double(basin_.terrain[i]);
          ++count;
        }
      height = sum / count;
    }
    mesh_.vertices.push_back({double(c.first), double(c.second), height});
    return it->second;
  }

  const BasinRaster& basin_;
  const WaterBody& body_;
  std::vector<uint8_t> wet_;
  std::map<std::tuple<int64_t, int64_t, int>, uint32_t> top_, bottom_;
  LakeMesh mesh_;
};

// The corners from a to b (axis-aligned), a included, b excluded.
std::vector<Corner> steps(Corner a, Corner b) {
  std::vector<Corner> out;
  const int64_t n = std::max(std::abs(b.first - a.first), std::abs(b.second - a.second));
  for (int64_t k = 0; k < n; ++k)
    out.push_back(
        {a.first + (b.first - a.first) / n * k, a.second + (b.second - a.second) / n * k});
  return out;
}

}  // namespace

LakeMesh lake_mesh(const BasinRaster& basin, const WaterBody& body) {
  if (body.wet.empty()) throw std::invalid_argument("lake_mesh: an empty body");
  Builder m(basin, body);

  // Top: the shoreline's triangles; one with a shoreline edge spanning several pixel sides is
  // fanned from its centroid through every corner of that edge, where the walls meet it.
  const auto tris = top_triangles(basin, body);
  std::map<std::pair<Corner, Corner>, int> uses;
  for (const auto& t : tris)
    for (size_t e = 0; e < 3; ++e) ++uses[std::minmax(t[e], t[(e + 1) % 3])];
  const auto shore = [&](Corner a, Corner b) { return uses[std::minmax(a, b)] == 1; };
  for (const auto& t : tris) {
    bool long_shore = false;
    for (size_t e = 0; e < 3; ++e)
      long_shore =
          long_shore || (shore(t[e], t[(e + 1) % 3]) && steps(t[e], t[(e + 1) % 3]).size() > 1);
    if (!long_shore) {
      m.triangle(m.top_at(t[0], point(t[1]), point(t[2])), m.top_at(t[1], point(t[2]), point(t[0])),
                 m.top_at(t[2], point(t[0]), point(t[1])));
      continue;
    }
    const Point g = {double(t[0].first + t[1].first + t[2].first) / 3,
                     double(t[0].second + t[1].second + t[2].second) / 3};
    const uint32_t centroid = m.top_point(g);
    for (size_t e = 0; e < 3; ++e) {
      const Corner a = t[e], b = t[(e + 1) % 3];
      const std::vector<Corner> path = shore(a, b) ? steps(a, b) : std::vector<Corner>{a};
      for (size_t k = 0; k < path.size(); ++k) {
        const Corner p = path[k], q = k + 1 < path.size() ? path[k + 1] : b;
        m.triangle(centroid, m.top_at(p, point(q), g), m.top_at(q, g, point(p)));
      }
    }
  }

  for (const int64_t i : body.wet) {
    const int64_t c = i % basin.width, r = i / basin.width;
    const Corner c00{c, r}, c10{c + 1, r}, c01{c, r + 1}, c11{c + 1, r + 1};
    // The pixel is quadrant 3 of its corner c00, 2 of c10, 1 of c01, 0 of c11.
    const auto quadrant = [&](Corner k) { return int(k.second == r) * 2 + int(k.first == c); };
    const auto bottom = [&](Corner k) { return m.bottom(k, quadrant(k)); };
    const auto top = [&](Corner k) { return m.top(k, quadrant(k)); };
    // Bottom, facing down.
    m.triangle(bottom(c00), bottom(c10), bottom(c11));
    m.triangle(bottom(c00), bottom(c11), bottom(c01));
    // Walls on the dry sides, along the shore with the water on the left seen from above.
    const std::array<std::pair<Corner, Corner>, 4> sides = {
        {{c01, c11}, {c11, c10}, {c10, c00}, {c00, c01}}};
    const std::array<bool, 4> dry = {!m.wet(c, r + 1), !m.wet(c + 1, r), !m.wet(c, r - 1),
                                     !m.wet(c - 1, r)};
    for (size_t s = 0; s < 4; ++s) {
      if (!dry[s]) continue;
      const auto [a, b] = sides[s];
      m.triangle(bottom(a), bottom(b), top(b));
      m.triangle(bottom(a), top(b), top(a));
    }
  }
  return m.take();
}

}  // namespace maquette::deform
