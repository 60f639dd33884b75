// structures.place's model bases (model_base.h) against bases known by construction: the corners
// of a box's floor, a plinth within 5 cm of the lowest vertex counted and a step above it not, the
// interior and collinear points of the floor left out, an L-shaped floor's outline (not its hull),
// two legs' hull, and the models that have no base refused.
#include "model_base.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "core/error.h"

namespace maquette::structures {
namespace {

MeshContent model_of(const std::vector<std::array<float, 3>>& vertices) {
  MeshContent m;
  MeshObject& o = m.objects.emplace_back();
  for (const auto& v : vertices) o.positions.insert(o.positions.end(), v.begin(), v.end());
  return m;
}

void expect_error(const MeshContent& model, const std::string& part) {
  try {
    model_base(model, "model 'm'");
    ADD_FAILURE() << "no error; expected one containing " << part;
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind("model 'm': ", 0), 0u) << what;
    EXPECT_NE(what.find(part), std::string::npos) << what;
  }
}

TEST(PlaceModelBase, BoxFloorIsItsCornersCounterClockwise) {
  // A 2 m x 1 m x 3 m box lifted 0.5 m: its floor's corners, whatever the height.
  std::vector<std::array<float, 3>> box;
  for (float z : {0.5f, 3.5f})
    for (float x : {-1.f, 1.f})
      for (float y : {-0.5f, 0.5f}) box.push_back({x, y, z});
  const Ring base = model_base(model_of(box), "box");
  const Ring want = {{-1, -0.5}, {1, -0.5}, {1, 0.5}, {-1, 0.5}};  // from the lowest x, then y
  EXPECT_EQ(base, want);
}

TEST(PlaceModelBase, PlinthCountsStepAboveDoesNot) {
  // A floor with points inside it and along its edges (left out), a plinth 4 cm above the floor
  // reaching to x = 3 (in), a step 6 cm above reaching to y = 5 (out), a roof over all of it.
  const MeshContent m = model_of({{0, 0, 10},
                                  {2, 0, 10.001f},
                                  {2, 2, 10},
                                  {0, 2, 10},
                                  {1, 1, 10},
                                  {1, 0, 10},
                                  {0, 1, 10.02f},
                                  {3, 1, 10.04f},
                                  {1, 5, 10.06f},
                                  {-5, -5, 20},
                                  {9, 9, 20}});
  const Ring base = model_base(m, "house");
  const Ring want = {{0, 0}, {2, 0}, {3, 1}, {2, 2}, {0, 2}};
  EXPECT_EQ(base, want);
}

// A prism of `height` over the counter-clockwise polygons `floors` (each a fan from its first
// corner): floors facing down, roofs up, walls (their bottom corners on the floor, projecting to
// nothing from above), as a closed outward mesh.
MeshContent prism_of(const std::vector<Ring>& floors, float height) {
  MeshContent m;
  MeshObject& o = m.objects.emplace_back();
  const auto vertex = [&](const Point2& p, float z) {
    o.positions.insert(o.positions.end(), {float(p[0]), float(p[1]), z});
    return uint32_t(o.positions.size() / 3 - 1);
  };
  for (const Ring& floor : floors) {
    for (size_t i = 1; i + 1 < floor.size(); ++i) {
      o.indices.insert(o.indices.end(),
                       {vertex(floor[0], 0), vertex(floor[i + 1], 0), vertex(floor[i], 0)});
      o.indices.insert(o.indices.end(), {vertex(floor[0], height), vertex(floor[i], height),
                                         vertex(floor[i + 1], height)});
    }
    for (size_t i = 0; i < floor.size(); ++i) {
      const Point2 &a = floor[i], &b = floor[(i + 1) % floor.size()];
      o.indices.insert(o.indices.end(), {vertex(a, 0), vertex(b, 0), vertex(b, height)});
      o.indices.insert(o.indices.end(), {vertex(a, 0), vertex(b, height), vertex(a, height)});
    }
  }
  return m;
}

TEST(PlaceModelBase, ConcaveFloorIsItsOutlineNotItsHull) {
  // An L of 3 m x 3 m arms 1 m wide: its six corners (a hull would add the notch's 2 m^2 and
  // place the model sqrt(5 / 7) too small).
  const Ring l = {{0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 3}, {0, 3}};
  EXPECT_EQ(model_base(prism_of({l}, 4), "L"), l);
}

TEST(PlaceModelBase, FloorOfSeveralPiecesIsTheirHull) {
  // Two legs 1 m apart: the stroke goes around both.
  const Ring left = {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, right = {{2, 0}, {3, 0}, {3, 1}, {2, 1}};
  const Ring want = {{0, 0}, {3, 0}, {3, 1}, {0, 1}};
  EXPECT_EQ(model_base(prism_of({left, right}, 2), "table"), want);
}

TEST(PlaceModelBase, ModelsWithoutBaseAreRefused) {
  // A cone on its tip, a wedge on its edge, nothing, a vertex that is not a number.
  expect_error(model_of({{0, 0, 0}, {-1, -1, 2}, {1, -1, 2}, {0, 1, 2}}), "stands on a point");
  expect_error(model_of({{0, 0, 0}, {1, 0, 0}, {0, -1, 1}, {0, 1, 1}}), "or an edge");
  expect_error(MeshContent{}, "has no vertex");
  expect_error(model_of({{0, 0, 0}, {1, 0, 0}, {0, std::numeric_limits<float>::quiet_NaN(), 0}}),
               "not finite");
}

}  // namespace
}  // namespace maquette::structures
