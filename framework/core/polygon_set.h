// Points in lon/lat polygons: edges straight in degrees, the even-odd rule (holes, and parts of
// a ring covered twice, are outside); polygons must not cross the antimeridian.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/geojson.h"

namespace maquette {

bool polygon_contains(const PolygonRings& polygon, LonLat p);

// Many points against fixed polygons (e.g. every pixel of a tile): each polygon's edges are
// bucketed by latitude band, so a point tests only the edges of its band rather than every
// vertex of the rings. Same answer as polygon_contains on each polygon (points beyond a
// polygon's bounding box are outside without a test, which only rounding could make differ).
class PolygonSet {
 public:
  explicit PolygonSet(const std::vector<PolygonRings>& polygons);

  bool empty() const { return polygons_.empty(); }
  bool contains(LonLat p) const;  // in any of the polygons

 private:
  struct Edge {
    LonLat a, b;
  };
  struct Banded {
    double west = 0, south = 0, east = 0, north = 0;
    double bands_per_degree = 0;
    std::vector<uint32_t> first;  // band k's edges: edges[first[k] .. first[k + 1])
    std::vector<Edge> edges;
    size_t band(double lat) const;
  };
  std::vector<Banded> polygons_;
};

}  // namespace maquette
