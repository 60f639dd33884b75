#include "bridge_deck.h"

#include <cmath>
#include <map>
#include <string>

namespace maquette::structures {

std::vector<double> edge_profile(const std::vector<PlanePoint2>& edge, double start, double end) {
  std::vector<double> along{0};
  for (size_t i = 1; i < edge.size(); ++i)
    along.push_back(along.back() +
                    std::hypot(edge[i][0] - edge[i - 1][0], edge[i][1] - edge[i - 1][1]));
  std::vector<double> heights;
  for (const double s : along) heights.push_back(start + (end - start) * (s / along.back()));
  return heights;
}

Solid deck_solid(const std::vector<DeckPoint>& first_edge,
                 const std::vector<DeckPoint>& second_edge, double thickness) {
  // The outline's points keep their top heights through make_footprint (which may reverse the
  // ring and drops repeated points) by their exact coordinates.
  std::map<PlanePoint2, double> top;
  PlaneRing outline;
  const auto add = [&](const DeckPoint& p) {
    outline.push_back({p[0], p[1]});
    top[{p[0], p[1]}] = p[2];
  };
  for (const DeckPoint& p : first_edge) add(p);
  for (auto p = second_edge.rbegin(); p != second_edge.rend(); ++p) add(*p);
  Footprint footprint;
  try {
    footprint = make_footprint({outline});
  } catch (const InvalidFootprint& e) {
    throw InvalidFootprint(std::string("the deck between the edges is not a simple polygon (the "
                                       "edges cross or touch, or enclose no area): ") +
                           e.what());
  }
  Solid solid = extrude(footprint, thickness);
  const size_t n = solid.positions.size() / 6;  // the outline's points
  for (size_t i = 0; i < n; ++i) {
    const double z = top.at({solid.positions[3 * i], solid.positions[3 * i + 1]});
    solid.positions[3 * i + 2] = z - thickness;
    solid.positions[3 * (n + i) + 2] = z;
  }
  // The floor and the top (extrude's first two faces) as one face per triangle.
  const SolidFace floor = solid.faces[0], roof = solid.faces[1];
  std::vector<SolidFace> faces;
  for (const SolidFace& cap : {floor, roof})
    for (uint32_t t = cap.first; t < cap.first + cap.count; ++t) faces.push_back({t, 1});
  faces.insert(faces.end(), solid.faces.begin() + 2, solid.faces.end());
  solid.faces = std::move(faces);
  if (const std::string problem = solid_problem(solid, footprint.area * thickness);
      !problem.empty())
    throw InvalidFootprint("its deck is not a valid solid: " + problem);
  return solid;
}

}  // namespace maquette::structures
