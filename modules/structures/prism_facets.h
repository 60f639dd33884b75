// structures.prism's facets, which of them the photo shows (paper 002 §7.3's ray test) and where
// the hidden ones take their texture from (symmetry: the most similar visible parallel facet).
#pragma once

#include <vector>

#include "prism_solver.h"

namespace maquette::structures {

struct PrismFacet {
  std::vector<Vec3> corners;  // counter-clockwise seen from outside, in the solution's frame
  Vec3 normal;                // outward, unit
};

// The facets of `prism`: the profile (P_i), the far cap (Q_i), then the side of each profile edge
// P_i -> P_i+1 (P_i, P_i+1, Q_i+1, Q_i). Precondition: the profile is a simple polygon.
std::vector<PrismFacet> prism_facets(const PrismSolution& prism);

// Paper 002 §7.3's visibility test: a ray cast toward each facet's centre; the facet is hidden
// when the ray meets another facet first. The paper casts it orthogonally to the image plane; in
// the camera's frame (perspective) that is the ray from the camera's centre (the origin) through
// the facet's centre, which is what is cast here. A facet facing away from the camera is hidden
// by the facets the ray crosses on its way in. Precondition: the facets close a solid whose every
// facet's vertex mean lies inside the facet (convex profiles; for a concave profile the
// profile's own caps may be misjudged).
std::vector<bool> visible_facets(const std::vector<PrismFacet>& facets);

// For each facet, the facet its texture comes from: itself when visible, else the visible facet
// parallel to it (normals within 1 degree, either way round) most similar in shape (the smallest
// sum of the differences of their extents in their planes, along the first edge and across it,
// each pair sorted), or -1 when no visible facet is parallel to it.
std::vector<int> texture_sources(const std::vector<PrismFacet>& facets,
                                 const std::vector<bool>& visible);

}  // namespace maquette::structures
