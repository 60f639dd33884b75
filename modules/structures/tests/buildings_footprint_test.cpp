// Footprints that cannot give a valid solid are refused with the reason; tags give the height.
#include <gtest/gtest.h>

#include "../building_height.h"
#include "../footprint.h"

namespace maquette::structures {
namespace {

std::string refusal(std::vector<PlaneRing> rings) {
  try {
    make_footprint(std::move(rings));
  } catch (const InvalidFootprint& e) {
    return e.what();
  }
  return "accepted";
}

TEST(Footprint, OrientsRingsAndKeepsTheFirstPoint) {
  // Outer ring clockwise and closed, hole counter-clockwise, a repeated point.
  const Footprint fp = make_footprint(
      {{{0, 0}, {0, 10}, {0, 10}, {10, 10}, {10, 0}, {0, 0}}, {{2, 2}, {4, 2}, {4, 4}, {2, 4}}});
  ASSERT_EQ(fp.rings[0].size(), 4u);
  EXPECT_EQ(fp.rings[0][0], (PlanePoint2{0, 0}));
  EXPECT_GT(signed_area(fp.rings[0]), 0);
  EXPECT_EQ(fp.rings[1][0], (PlanePoint2{2, 2}));
  EXPECT_LT(signed_area(fp.rings[1]), 0);
  EXPECT_DOUBLE_EQ(fp.area, 96);
}

TEST(Footprint, RefusesWhatGivesNoSolid) {
  EXPECT_NE(refusal({{{0, 0}, {10, 10}, {10, 0}, {0, 20}}}).find("meets"), std::string::npos)
      << "bow tie";
  EXPECT_NE(refusal({{{0, 0}, {5, 0}, {10, 0}}}).find("area of 0"), std::string::npos)
      << "collinear";
  EXPECT_NE(refusal({{{0, 0}, {1, 1}, {0, 0}}}).find("fewer than 3"), std::string::npos);
  EXPECT_NE(refusal({{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{20, 20}, {22, 20}, {22, 22}}})
                .find("outside the outer ring"),
            std::string::npos);
  // A hole touching the outer ring at a corner: a non-manifold vertex of the solid.
  EXPECT_NE(refusal({{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{0, 0}, {4, 2}, {2, 4}}}).find("meets"),
            std::string::npos);
  // A spike folding back along its own edge.
  EXPECT_NE(refusal({{{0, 0}, {10, 0}, {15, 0}, {12, 0}, {10, 10}}}).find("folds back"),
            std::string::npos);
  EXPECT_NE(refusal({{{0, 0}, {10, 0}, {10, 10}, {0, 10}},
                     {{1, 1}, {8, 1}, {8, 8}, {1, 8}},
                     {{2, 2}, {3, 2}, {3, 3}}})
                .find("inside hole 1"),
            std::string::npos);
}

TEST(Footprint, PartsMustBeDisjoint) {
  const Footprint a = make_footprint({{{0, 0}, {10, 0}, {10, 10}, {0, 10}}});
  const Footprint inner = make_footprint({{{2, 2}, {4, 2}, {4, 4}}});
  EXPECT_THROW(check_disjoint({a, inner}), InvalidFootprint);
  const Footprint courtyard =
      make_footprint({{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{1, 1}, {9, 1}, {9, 9}, {1, 9}}});
  EXPECT_NO_THROW(check_disjoint({courtyard, inner}));  // an island in the courtyard
  const Footprint neighbour = make_footprint({{{10, 0}, {20, 0}, {20, 10}, {10, 10}}});
  EXPECT_THROW(check_disjoint({a, neighbour}), InvalidFootprint);  // a shared wall
}

TEST(BuildingHeight, TagsInOrder) {
  const HeightRules rules{9, 3};
  const auto top = [&](const nlohmann::json& tags) {
    return part_heights(building_tags(tags, rules), 0).top();
  };
  EXPECT_DOUBLE_EQ(top({{"height", 21.5}, {"building:levels", 2}}), 21.5);
  EXPECT_DOUBLE_EQ(top({{"height", "14 m"}}), 14);
  EXPECT_DOUBLE_EQ(top({{"building:levels", "4"}, {"roof:shape", "flat"}}), 12);
  EXPECT_DOUBLE_EQ(top({{"height", nullptr}, {"name", "x"}}), 9);
  try {
    building_tags({{"height", "tall"}}, rules);
    FAIL();
  } catch (const InvalidFootprint& e) {
    EXPECT_NE(std::string(e.what()).find("tag height = \"tall\""), std::string::npos) << e.what();
  }
  EXPECT_THROW(building_tags({{"building:levels", -2}}, rules), InvalidFootprint);
}

}  // namespace
}  // namespace maquette::structures
