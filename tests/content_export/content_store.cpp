#include "content_store.h"

#include <cmath>
#include <numbers>

#include "content/content_blob.h"
#include "content/instances_codec.h"
#include "gltf/mesh_glb.h"
#include "store/store.h"
#include "test_tiles.h"
#include "vdb/volume_vdb.h"
#include "vdb_fixture.h"

namespace maquette::test {
namespace {

LayerInfo content_layer(const std::string& name, LayerKind kind, int level = kLevel) {
  LayerInfo l;
  l.name = name;
  l.kind = kind;
  l.level = level;
  return l;
}

EnuOrigin centre(const Grid& grid, CellId cell) {
  const PlaneSquare sq = grid.plane_square(cell);
  const LonLat c = grid.inverse({sq.x_min + sq.side / 2, sq.y_max - sq.side / 2});
  return {c.lon, c.lat, kHeight};
}

std::string box_blob(const EnuOrigin& origin) {
  MeshContent m;
  m.origin = origin;
  Material red;
  red.name = "red";
  red.base_colour = {0.9f, 0.02f, 0.02f, 1};
  m.materials = {red};
  MeshObject box;
  box.material = 0;
  box.provenance.object_id = 1;
  const float h = float(kBoxHalf), top = float(kBoxHeight);
  for (int i = 0; i < 8; ++i)
    box.positions.insert(box.positions.end(), {i & 1 ? h : -h, i & 2 ? h : -h, i & 4 ? top : 0});
  // Counter-clockwise seen from outside: bottom, top, then the four sides.
  box.indices = {0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4,
                 2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5};
  m.objects = {box};
  ContentEnvelope e;
  e.kind = ContentKind::Mesh;
  e.origin = origin;
  e.stats = {1, 12, 0};
  return wrap_content(e, encode_mesh_glb(m));
}

std::string trees_blob(const EnuOrigin& origin, const std::string& prototype, int count) {
  InstancesContent c;
  c.origin = origin;
  c.prototypes = {prototype};
  for (int i = 0; i < count; ++i) {
    const auto [e, n] = tree_offset(i);
    c.prototype.push_back(0);
    c.position.insert(c.position.end(), {float(e), float(n), 0});
    const double a = -std::numbers::pi / 6 * i / 2;  // clockwise seen from above: about -z
    c.rotation.insert(c.rotation.end(), {0, 0, float(std::sin(a)), float(std::cos(a))});
    const float s = float(kTreeHeight);
    c.scale.insert(c.scale.end(), {s, s, s});
    c.colour.push_back(kTreeColour);
  }
  return wrap_instances(c);
}

std::string lake_blob(const EnuOrigin& origin) {
  const VolumeContent v = encode_volume(
      {fog_box(openvdb::CoordBBox({-20, -20, 0}, {19, 19, 9}), 2.0, "water")}, origin);
  ContentEnvelope e;
  e.kind = ContentKind::Volume;
  e.origin = origin;
  e.stats = volume_stats(decode_volume(v, "lake"));
  return wrap_content(e, v.vdb);
}

}  // namespace

ContentStore write_content_store(const std::string& path) {
  const Grid& grid = default_grid();
  ContentStore s;
  s.path = path;
  s.block = block_of_four(grid, {7.25, 46.5}, kLevel);
  for (size_t i = 0; i < 4; ++i) s.origins[i] = centre(grid, s.block[i]);
  auto store = Store::open(s.path, Store::Mode::Create);
  LayerInfo dem = layer_info("dem", DType::F32, 1, 16, kLevel);
  dem.units = "m";
  store->create_layer(dem);
  store->create_layer(content_layer("buildings", LayerKind::Mesh));
  store->create_layer(content_layer("trees", LayerKind::Instances));
  store->create_layer(content_layer("lakes", LayerKind::Volume));
  store->create_layer(content_layer("orchard", LayerKind::Instances));
  store->create_layer(content_layer("parks", LayerKind::Mesh, kLevel - 1));
  Store::Batch batch(*store);
  for (CellId c : s.block)
    batch.put_tile(
        "dem", c, make_tile<float>(grid, c, 16, 1, [](const TileSample&, int) { return kHeight; }));
  batch.put_content("buildings", s.block[0], box_blob(s.origins[0]));
  batch.put_content("buildings", s.block[0].parent(), box_blob(s.origins[0]));
  batch.put_content("trees", s.block[1], trees_blob(s.origins[1], "builtin:conifer", kTreeCount));
  batch.put_content("lakes", s.block[2], lake_blob(s.origins[2]));
  batch.put_content("orchard", s.block[3], trees_blob(s.origins[3], "oak", 1));
  batch.commit();
  store->update_overviews("dem");
  return s;
}

std::array<double, 2> tree_offset(int i) {
  return {i % 2 ? 150.0 : -150.0, i / 2 ? 150.0 : -150.0};
}

}  // namespace maquette::test
