// The runner's checks of a cell's content (runtime/content_output.h) on their own: anchors just
// beyond an edge of the cell (within and beyond kAnchorToleranceM, placed with GeographicLib and
// checked outside with the grid), and each fault of a mesh object, named with its feature id.
#include <gtest/gtest.h>

#include <GeographicLib/LocalCartesian.hpp>
#include <cmath>
#include <string>

#include "content/instances_codec.h"
#include "runtime/content_output.h"
#include "test_util.h"

namespace maquette {
namespace {

const CellId kCell = default_grid().cell_from_point({10.05, 45.05}, 12);

EnuOrigin cell_origin() {
  const LonLat c = default_grid().centre(kCell);
  return {c.lon, c.lat, 0};
}

// One tree at `xyz` (ENU of the cell's origin), feature 7.
CellContent one_tree(const std::array<double, 3>& xyz) {
  CellContent content;
  InstancesContent& trees = content.instances["trees"];
  trees.origin = cell_origin();
  trees.prototypes = {"builtin:conifer"};
  trees.prototype = {0};
  trees.position = {float(xyz[0]), float(xyz[1]), float(xyz[2])};
  trees.rotation = {0, 0, 0, 1};
  trees.scale = {1, 1, 1};
  trees.colour = {0xffffffff};
  trees.provenance = {{7, 7, "test", nlohmann::json::object()}};
  return content;
}

// The point `beyond` metres outside the middle of the cell's first edge, in the origin's frame:
// moved away from the centre (the origin), about square to the edge there.
std::array<double, 3> beyond_edge(double beyond) {
  const LonLat middle = default_grid().boundary(kCell, 3)[1];  // corner, middle, corner, ...
  const EnuOrigin o = cell_origin();
  std::array<double, 3> xyz{};
  GeographicLib::LocalCartesian(o.lat, o.lon, o.height)
      .Forward(middle.lat, middle.lon, 0, xyz[0], xyz[1], xyz[2]);
  const double scale = 1 + beyond / std::hypot(xyz[0], xyz[1]);
  return {xyz[0] * scale, xyz[1] * scale, xyz[2]};
}

TEST(ContentCheck, AnchorsJustBeyondTheEdgeWithinTheTolerance) {
  const auto inside_tolerance = beyond_edge(0.5 * kAnchorToleranceM);
  const auto outside_tolerance = beyond_edge(5 * kAnchorToleranceM);
  for (const auto& p : {inside_tolerance, outside_tolerance}) {  // both outside the cell
    const float xyz[3] = {float(p[0]), float(p[1]), float(p[2])};
    const EnuOrigin o = cell_origin();
    double lat = 0, lon = 0, h = 0;
    GeographicLib::LocalCartesian(o.lat, o.lon, o.height)
        .Reverse(xyz[0], xyz[1], xyz[2], lat, lon, h);
    EXPECT_NE(default_grid().cell_from_point({lon, lat}, 12), kCell);
  }
  EXPECT_EQ(encode_cell_content(one_tree(inside_tolerance), kCell, default_grid()).size(), 1u);
  EXPECT_NE(test::error_of([&] {
              encode_cell_content(one_tree(outside_tolerance), kCell, default_grid());
            }).find("outputs.trees: instance 0 (feature 7): its anchor at lon "),
            std::string::npos);
  EXPECT_EQ(encode_cell_content(one_tree({10, -20, 3}), kCell, default_grid()).size(), 1u);
}

// The origin is checked before the anchors are taken through it.
TEST(ContentCheck, OriginsOffTheGlobeAreRefused) {
  CellContent content = one_tree({10, -20, 3});
  content.instances["trees"].origin.lat = NAN;
  EXPECT_EQ(test::error_of([&] { encode_cell_content(content, kCell, default_grid()); }),
            "outputs.trees: origin is not finite");
  content.instances["trees"].origin.lat = 91;
  EXPECT_NE(test::error_of([&] {
              encode_cell_content(content, kCell, default_grid());
            }).find("outputs.trees: origin lon "),
            std::string::npos);
}

// A prototype is a built-in name or one of the store's model layers, which the runner passes.
TEST(ContentCheck, PrototypesAreBuiltInOrModelLayers) {
  CellContent content = one_tree({10, -20, 3});
  content.instances["trees"].prototypes = {"oak"};
  EXPECT_EQ(encode_cell_content(content, kCell, default_grid(), {"oak"}).size(), 1u);
  EXPECT_NE(test::error_of([&] { encode_cell_content(content, kCell, default_grid(), {"elm"}); })
                .find("instance 0 (feature 7): unknown prototype 'oak' (known: builtin:conifer, "
                      "builtin:broadleaf, builtin:shrub, elm)"),
            std::string::npos);
}

TEST(ContentCheck, MeshFaultsNameTheObjectAndFeature) {
  const auto with = [](auto change) {
    CellContent content;
    MeshContent& mesh = content.meshes["mesh"];
    mesh.origin = cell_origin();
    MeshObject o;
    o.provenance.feature_id = 42;
    o.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    o.indices = {0, 1, 2};
    change(o);
    mesh.objects.push_back(o);
    return test::error_of([&] { encode_cell_content(content, kCell, default_grid()); });
  };
  const std::string object = "outputs.mesh: mesh object 0 (feature 42): ";
  EXPECT_EQ(with([](MeshObject& o) {
              o.indices = {0, 1, 3};
            }),
            object + "index 3 is out of range (3 vertices)");
  EXPECT_EQ(with([](MeshObject& o) {
              o.indices = {0, 1};
            }),
            object + "2 indices: not whole triangles, or none");
  EXPECT_EQ(with([](MeshObject& o) { o.positions.pop_back(); }),
            object + "8 position values: not 3 per vertex, or none");
  EXPECT_EQ(with([](MeshObject& o) {
              o.normals = {0, 0, 1};
            }),
            object + "3 normal values for 3 vertices");
  EXPECT_EQ(with([](MeshObject& o) { o.uvs = {0, 0}; }), object + "2 uv values for 3 vertices");
  EXPECT_EQ(with([](MeshObject& o) { o.material = 0; }),
            object + "material 0 is out of range (0 materials)");
  EXPECT_EQ(with([](MeshObject& o) { o.positions[4] = INFINITY; }),
            object + "vertex 1 at (1, inf, 0) is not finite");
}

TEST(ContentCheck, EmptyContentWritesNothing) {
  CellContent content;
  content.meshes["mesh"].origin = cell_origin();
  content.instances["trees"].origin = cell_origin();
  content.volumes["volume"].origin = cell_origin();
  EXPECT_TRUE(encode_cell_content(content, kCell, default_grid()).empty());
}

}  // namespace
}  // namespace maquette
