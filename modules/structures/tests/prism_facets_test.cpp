// structures.prism's ray test and symmetry sources against the synthetic photos' cameras: a facet
// of a convex prism is visible exactly when it faces the camera's centre.
#include "../prism_facets.h"

#include <gtest/gtest.h>

#include <iostream>

#include "prism_synthetic.h"

namespace maquette::structures {
namespace {

TEST(PrismFacets, RayTestMatchesTheCamerasOfOneThousandNoisyPhotos) {
  int facets = 0, wrong = 0, hidden = 0;
  for (int k = 0; k < 1000; ++k) {
    const SyntheticPhoto p = synthetic_photo(20261129, k, 1.0);
    const PrismSolution s = solve_prism(p.clicks, p.camera, "photo");
    const std::vector<bool> visible = visible_facets(prism_facets(s));
    ASSERT_EQ(visible.size(), p.facet_visible.size());
    for (size_t i = 0; i < visible.size(); ++i) {
      ++facets;
      hidden += !p.facet_visible[i];
      wrong += visible[i] != p.facet_visible[i];
    }
  }
  std::cout << "ray test: " << facets << " facets of 1000 photos with 1-pixel noise, " << hidden
            << " hidden, " << wrong << " misclassified\n";
  EXPECT_EQ(wrong, 0);
  EXPECT_GT(hidden, facets / 4);
}

TEST(PrismFacets, HiddenFacetsTakeTheirParallelTwin) {
  // Rectangular profiles: a hidden facet takes its opposite facet when that one is visible (the
  // roof and the ground may both be hidden: nothing to copy).
  int rectangles = 0, copies = 0;
  for (int k = 0; k < 200; ++k) {
    const SyntheticPhoto p = synthetic_photo(20261129, k, 0);
    if (p.profile.size() != 4 || p.right_angles.size() != 3) continue;
    ++rectangles;
    const PrismSolution s = solve_prism(p.exact, p.camera, "photo");
    const std::vector<PrismFacet> facets = prism_facets(s);
    const std::vector<bool> visible = visible_facets(facets);
    const std::vector<int> source = texture_sources(facets, visible);
    // The caps are facets 0 and 1, the sides 2..5 in profile order: opposite sides differ by 2.
    for (int i = 0; i < 6; ++i) {
      const int twin = i < 2 ? 1 - i : 2 + (i - 2 + 2) % 4;
      const int expected = visible[size_t(i)] ? i : visible[size_t(twin)] ? twin : -1;
      EXPECT_EQ(source[size_t(i)], expected) << "photo " << k << " facet " << i;
      copies += expected != i && expected >= 0;
    }
  }
  EXPECT_GT(rectangles, 20);
  EXPECT_GT(copies, rectangles);
}

TEST(PrismFacets, OutwardNormalsOfAUnitCube) {
  PrismSolution cube;
  cube.profile = {{0, 0, 5}, {0, 1, 5}, {1, 1, 5}, {1, 0, 5}};
  cube.extrusion = {0, 0, 1};
  const std::vector<PrismFacet> facets = prism_facets(cube);
  ASSERT_EQ(facets.size(), 6u);
  Vec3 centre(0.5, 0.5, 5.5);
  for (const PrismFacet& f : facets) {
    Vec3 mid = Vec3::Zero();
    for (const Vec3& c : f.corners) mid += c / 4;
    EXPECT_NEAR(f.normal.dot((mid - centre).normalized()), 1, 1e-12);
    // Counter-clockwise seen from outside: the corners' Newell normal is the outward one.
    Vec3 newell = Vec3::Zero();
    for (size_t i = 0; i < 4; ++i) newell += f.corners[i].cross(f.corners[(i + 1) % 4]);
    EXPECT_NEAR(newell.normalized().dot(f.normal), 1, 1e-12);
  }
  // Seen from the origin, straight down +z: only the near face z = 5.
  const std::vector<bool> visible = visible_facets(facets);
  EXPECT_EQ(visible, (std::vector<bool>{true, false, false, false, false, false}));
}

}  // namespace
}  // namespace maquette::structures
