// CGAL's Polygon Mesh Processing as the oracle of a solid's validity (val3dity's shell checks).
// GPL: linked into the test binary only.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace maquette::structures {

struct CgalVerdict {
  bool polygon_mesh =
      false;            // a manifold, consistently orientable soup (is_polygon_soup_a_polygon_mesh)
  bool closed = false;  // CGAL::is_closed
  bool outward = false;         // is_outward_oriented
  bool self_intersects = true;  // does_self_intersect (degenerate triangles count)
  double volume = 0;            // PMP::volume, m^3
};

// Triangles as given (x, y, z per vertex, 3 indices per triangle; vertices at one position taken
// as one point, as val3dity reads a solid); the later checks are made
// only when the earlier hold (CGAL's preconditions).
CgalVerdict cgal_verdict(const std::vector<double>& positions,
                         const std::vector<uint32_t>& indices);

// CGAL's verdict on a solid that must be valid, as gtest expectations: a polygon mesh, closed,
// free of self-intersection, outward, of `volume` (m^3) within `relative`.
void expect_valid_solid(const std::vector<double>& positions, const std::vector<uint32_t>& indices,
                        double volume, double relative = 1e-9);

// The area of a polygon (outer ring, holes; open rings of x, y) by CGAL's Polygon_2.
double cgal_area(const std::vector<std::vector<std::array<double, 2>>>& rings);

}  // namespace maquette::structures
