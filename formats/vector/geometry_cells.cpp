#include "vector/geometry_cells.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <optional>

#include "core/error.h"

namespace maquette {
namespace {

class Collector {
 public:
  Collector(const Grid& grid, int level)
      : grid_(grid), level_(level), spacing_m_(grid.level_info(level, 1).cell_side_m / 4) {}

  void add(const OGRGeometry& g) {
    if (g.hasCurveGeometry()) {
      const std::unique_ptr<OGRGeometry> linear(g.getLinearGeometry());
      add(*linear);
      return;
    }
    switch (wkbFlatten(g.getGeometryType())) {
      case wkbPoint: {
        const auto& p = *g.toPoint();
        cells_.push_back(grid_.cell_from_point({p.getX(), p.getY()}, level_));
        return;
      }
      case wkbLineString:
      case wkbLinearRing:
        add_line(*g.toSimpleCurve());
        return;
      case wkbPolygon:
        add_polygon(*g.toPolygon());
        return;
      case wkbMultiPoint:
      case wkbMultiLineString:
      case wkbMultiPolygon:
      case wkbGeometryCollection:
        for (const OGRGeometry* part : *g.toGeometryCollection()) add(*part);
        return;
      default:
        throw Error(std::string("geometry type ") + g.getGeometryName() + " is not supported");
    }
  }

  std::vector<CellId> take() {
    std::sort(cells_.begin(), cells_.end());
    cells_.erase(std::unique(cells_.begin(), cells_.end()), cells_.end());
    return std::move(cells_);
  }

 private:
  // Longitudes are made continuous along each ring (a ring crossing the antimeridian goes
  // beyond +-180), as LonLatPolygon expects.
  void add_polygon(const OGRPolygon& polygon) {
    std::vector<std::vector<LonLat>> rings;
    std::optional<double> start;  // the outer ring's first longitude: where every ring starts
    for (const OGRLinearRing* ring : polygon) {
      auto& r = rings.emplace_back();
      for (const OGRPoint& p : *ring) {
        const double reference = r.empty() ? start.value_or(p.getX()) : r.back().lon;
        r.push_back({reference + std::remainder(p.getX() - reference, 360.0), p.getY()});
        if (!start) start = r.back().lon;
      }
    }
    const auto cover = grid_.cover_polygon(rings, level_, Containment::Overlap);
    cells_.insert(cells_.end(), cover.begin(), cover.end());
  }

  void add_line(const OGRSimpleCurve& line) {
    const int n = line.getNumPoints();
    if (n == 0) return;
    CellId previous = grid_.cell_from_point({line.getX(0), line.getY(0)}, level_);
    cells_.push_back(previous);
    for (int i = 1; i < n; ++i) {
      const LonLat a{line.getX(i - 1), line.getY(i - 1)}, b{line.getX(i), line.getY(i)};
      const double dlon = std::remainder(b.lon - a.lon, 360.0);
      const int steps = std::max(1, int(std::ceil(approx_distance_m(a, b) / spacing_m_)));
      for (int k = 1; k <= steps; ++k) {
        const double t = double(k) / steps;
        const CellId cell =
            grid_.cell_from_point({a.lon + t * dlon, a.lat + t * (b.lat - a.lat)}, level_);
        if (cell != previous) add_step(previous, cell);
        previous = cell;
      }
    }
  }

  // Consecutive samples in cells that share no edge: the segment between them may pass
  // through any cell touching both.
  void add_step(CellId from, CellId to) {
    cells_.push_back(to);
    const auto edge = grid_.edge_neighbours(from);
    if (std::find(edge.begin(), edge.end(), to) != edge.end()) return;
    const auto around_to = grid_.vertex_neighbours(to);
    for (CellId c : grid_.vertex_neighbours(from))
      if (std::find(around_to.begin(), around_to.end(), c) != around_to.end()) cells_.push_back(c);
  }

  const Grid& grid_;
  const int level_;
  const double spacing_m_;
  std::vector<CellId> cells_;
};

}  // namespace

double approx_distance_m(LonLat a, LonLat b) {
  constexpr double kEarthRadiusM = 6371008.8;  // mean radius
  constexpr double rad = std::numbers::pi / 180;
  const double dx =
      std::remainder(b.lon - a.lon, 360.0) * rad * std::cos((a.lat + b.lat) / 2 * rad);
  return kEarthRadiusM * std::hypot(dx, (b.lat - a.lat) * rad);
}

std::vector<CellId> geometry_cells(const Grid& grid, const OGRGeometry& lonlat, int level) {
  Collector collector(grid, level);
  collector.add(lonlat);
  return collector.take();
}

}  // namespace maquette
