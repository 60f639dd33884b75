// gltf/terrain_level.h streams a level's terrain cell by cell, yet quantizes every cell on the
// lattice of the level's widest mesh: a cell built before a wider one is built again. Checked
// with one worker thread on a flat cell and a much taller neighbour (either way round), given in
// both orders: the same meshes and Draco bytes, on the lattice of the taller mesh as computed from
// each cell's own unquantized mesh, and the flat cell rebuilt when it was built first.
#include "gltf/terrain_level.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <map>

#include "gltf/lattice.h"
#include "gltf/terrain_source.h"
#include "run_cli.h"
#include "test_tiles.h"
#include "tiles3d_fixture.h"

namespace maquette::test {
namespace {

// The extent of `cell`'s mesh before quantization.
double unquantized_extent(const TerrainSource& source, const LocalFrame& frame, CellId cell) {
  const auto dem = dem_with_halo(source.store, source.grid, source.dem, cell);
  const TerrainMesh mesh = build_terrain_mesh(
      source.grid, cell, *dem, 1, frame, 2 * source.vertex_spacing(cell.level()), source.heights);
  return extent(mesh.positions);
}

struct Delivery {
  CellId cell;
  CellTerrain terrain;
};

// The terrain for_each_terrain hands over, in order, built on one thread.
std::vector<Delivery> stream(const TerrainSource& source, const LocalFrame& frame,
                             const std::vector<CellId>& cells) {
  std::vector<Delivery> out;
  tbb::task_arena(1).execute([&] {
    for_each_terrain(source, frame, cells, [&](size_t i, CellTerrain&& t) {
      out.push_back({cells[i], std::move(t)});
    });
  });
  return out;
}

// Two neighbouring cells: `narrow` flat, `wide` a ramp rising 300 km from west to east, so that
// its mesh is about twice as tall as a cell is wide.
std::string ramp_store(CellId narrow, CellId wide) {
  const Grid& grid = default_grid();
  const std::string path = temp_dir() + "/ramp.maquette";
  auto store = Store::open(path, Store::Mode::Create);
  store->create_layer(layer_info("dem", DType::F32, 1, kTileSize, kLevel));
  Store::Batch batch(*store);
  batch.put_tile(
      "dem", narrow,
      make_tile<float>(grid, narrow, kTileSize, 1, [](const TileSample&, int) { return 1000.0; }));
  const int64_t west = global_col(wide, kTileSize, 0);
  batch.put_tile("dem", wide,
                 make_tile<float>(grid, wide, kTileSize, 1, [&](const TileSample& s, int) {
                   return 1000.0 + 300e3 * double(s.col - west) / (kTileSize - 1);
                 }));
  batch.commit();
  return path;
}

// The last terrain delivered for each cell.
std::map<CellId, const CellTerrain*> last(const std::vector<Delivery>& deliveries) {
  std::map<CellId, const CellTerrain*> out;
  for (const Delivery& d : deliveries) out[d.cell] = &d.terrain;
  return out;
}

TEST(Tiles3d, LatticeOfTheWidestMeshWhateverTheOrder) {
  const Grid& grid = default_grid();
  const std::vector<CellId> block = block_of_four(grid, {10, 1}, kLevel);
  const LocalFrame frame = frame_for(grid, block);
  size_t rebuilt = 0;
  for (int tall : {0, 1}) {  // the ramp on either cell, so that the flat one is built first once
    const CellId flat = block[size_t(1 - tall)], wide = block[size_t(tall)];
    SCOPED_TRACE("ramp on " + wide.ToText());
    const auto store = Store::open(ramp_store(flat, wide), Store::Mode::ReadOnly);
    TerrainSettings settings;
    settings.dem = "dem";
    const TerrainSource source(*store, grid, settings);
    const int bits = settings.bits.position;
    const double fine = Lattice::for_extent(unquantized_extent(source, frame, flat), bits).step;
    const double step = Lattice::for_extent(unquantized_extent(source, frame, wide), bits).step;
    ASSERT_GT(step, fine);

    const auto flat_first = stream(source, frame, {flat, wide});
    const auto wide_first = stream(source, frame, {wide, flat});
    rebuilt += flat_first.size() - 2 + wide_first.size() - 2;
    auto a = last(flat_first), b = last(wide_first);
    ASSERT_EQ(a.size(), 2u);
    ASSERT_EQ(b.size(), 2u);
    // The same bits in both orders, on the tall mesh's lattice.
    for (CellId c : {flat, wide}) {
      SCOPED_TRACE(c.ToText());
      EXPECT_EQ(a[c]->lattice_step, step);
      EXPECT_EQ(b[c]->lattice_step, step);
      EXPECT_EQ(a[c]->mesh.positions, b[c]->mesh.positions);
      EXPECT_EQ(a[c]->mesh.offset, b[c]->mesh.offset);
      EXPECT_EQ(a[c]->draco.data, b[c]->draco.data);
      // On the lattice: multiples of the step, measured from an offset that is one too.
      for (double v : a[c]->mesh.positions) ASSERT_EQ(v / step, std::round(v / step)) << v;
      for (double v : a[c]->mesh.offset) ASSERT_EQ(v / step, std::round(v / step)) << v;
    }
  }
  // Whichever cell is built first, the flat one came first in one of the runs: quantized on its
  // own, finer lattice, then built again.
  EXPECT_GE(rebuilt, 1u);
}

}  // namespace
}  // namespace maquette::test
