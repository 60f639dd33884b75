// RHealpixGrid: the rHEALPix DGGS on WGS84 with N_side 2 (see README.md and DESIGN.md).
#pragma once

#include <algorithm>

#include "core/grid.h"
#include "projection.h"

namespace maquette {

class RHealpixGrid final : public Grid {
 public:
  std::string name() const override { return "rhealpix"; }
  int num_faces() const override { return CellId::kNumFaces; }

  PlanePoint forward(LonLat p) const override;
  LonLat inverse(PlanePoint p) const override;

  CellId cell_from_point(LonLat p, int level) const override {
    CellId::CheckLevel(level);
    return cell_at(projection_.to_face(p), level);
  }
  void cells_from_points(std::span<const LonLat> points, int level,
                         std::span<CellId> out) const override;

  LonLat centre(CellId cell) const override;
  PlaneSquare plane_square(CellId cell) const override;
  std::vector<LonLat> boundary(CellId cell, int points_per_edge) const override;
  double area(int level) const override;
  LevelInfo level_info(int level, int tile_size) const override;

  std::optional<FaceCoord> wrap(FaceCoord c, int level) const override;
  std::array<CellId, 4> edge_neighbours(CellId cell) const override;
  std::vector<CellId> vertex_neighbours(CellId cell) const override;

  std::vector<CellId> cover_bbox(double west, double south, double east, double north, int level,
                                 Containment mode) const override;
  std::vector<CellId> cover_polygon(const std::vector<std::vector<LonLat>>& rings, int level,
                                    Containment mode) const override;
  void visit_cover_bbox(double west, double south, double east, double north, int level,
                        Containment mode, const std::function<void(CellId)>& visit) const override;
  void visit_cover_polygons(const std::vector<std::vector<std::vector<LonLat>>>& polygons,
                            int level, Containment mode,
                            const std::function<void(CellId)>& visit) const override;

  const RHealpixProjection& projection() const { return projection_; }

 private:
  static void check_cell(CellId cell);

  // The floor rule, clamped to the face: a point on an inner edge goes to the lower row and
  // the right column.
  static CellId cell_at(FacePoint p, int level) {
    const int64_t n = int64_t(1) << level;
    const auto index = [n](double x) { return uint32_t(std::min(int64_t(x * double(n)), n - 1)); };
    return CellId::FromFaceColRow(p.face, level, index(p.u), index(p.v));
  }

  RHealpixProjection projection_;
};

}  // namespace maquette
