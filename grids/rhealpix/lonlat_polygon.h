// A polygon in the lon/lat plane (edges are straight lines in degrees, as in GeoJSON), with
// rings whose longitudes are continuous (they may go beyond +-180 to cross the antimeridian).
// Longitudes are periodic: a point or rectangle is tested also shifted by +-360 degrees.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/grid.h"

namespace maquette {

// An axis-aligned lon/lat rectangle; east may exceed 180 (unwrapped longitudes).
struct LonLatRect {
  double west = 0;
  double south = 0;
  double east = 0;
  double north = 0;
};

enum class Relation { Disjoint, Inside, Crosses };

class LonLatPolygon {
 public:
  // Rings: the outer ring then holes (even-odd rule), open or closed. Throws maquette::Error for
  // a ring with fewer than 3 distinct points or a latitude outside +-90.
  explicit LonLatPolygon(const std::vector<std::vector<LonLat>>& rings);

  size_t num_edges() const { return edges_.size(); }
  // Disjoint: the interiors do not meet; Inside: the closed rectangle lies in the closed
  // polygon; else Crosses. Only `candidates` edges are tested for crossing (the edges crossing
  // an enclosing rectangle); those crossing this one are written to `crossing`.
  Relation relate(const LonLatRect& r, std::span<const uint32_t> candidates,
                  std::vector<uint32_t>& crossing) const;
  // A closed ring (a simple polygon, closed by repeating its first point, with continuous
  // longitudes, e.g. a densified cell boundary) against the polygon: Disjoint if their interiors
  // do not meet, Inside if the ring lies in the polygon, else Crosses. A ring touching the
  // polygon's boundary counts as crossing it. Only `candidates` edges are tested for meeting the
  // ring (the edges meeting an open rectangle holding it); containment uses every edge.
  Relation relate_ring(std::span<const LonLat> ring, std::span<const uint32_t> candidates) const;
  bool contains(LonLat p) const;

 private:
  struct Edge {
    LonLat a;
    LonLat b;
  };
  bool contains_unshifted(double lon, double lat) const;
  bool crosses_interior(const Edge& e, const LonLatRect& r) const;
  Relation relate_ring_shifted(std::span<const LonLat> ring, double shift,
                               std::span<const uint32_t> candidates) const;

  std::vector<Edge> edges_;
  LonLatRect bounds_;
};

}  // namespace maquette
