// structures.buildings' work per footprint (building_mesh.h: height, lowest terrain, extrusion,
// the validity checks, the mesh in the cell's frame) on London Soho's 158 OSM footprints over a
// synthetic DEM (modules/structures/tests/soho_scene.h), each thread building all of them once
// per iteration. Goal: >= 20,000 buildings per second on 2 cores (items_per_second, wall time).
#include <benchmark/benchmark.h>

#include "building_mesh.h"
#include "content/facet_normals.h"
#include "tests/soho_scene.h"

namespace {

using namespace maquette::structures;

const SohoScene& scene() {
  static const SohoScene s(std::string(MAQUETTE_SHARED_DIR) +
                           "/data/buildings/london_soho_buildings_wgs84.geojson");
  return s;
}

void BM_Buildings(benchmark::State& state) {
  const SohoScene& s = scene();
  std::vector<BuildingSite> sites;
  for (const auto& f : s.footprints) sites.push_back(s.site(f));
  size_t triangles = 0;
  for (auto _ : state) {
    triangles = 0;
    for (size_t i = 0; i < s.footprints.size(); ++i) {
      const maquette::MeshObject m =
          maquette::with_facet_normals(building_mesh(s.footprints[i], {}, sites[i]));
      triangles += m.indices.size() / 3;
      benchmark::DoNotOptimize(m.positions.data());
    }
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(s.footprints.size()));
  state.counters["triangles"] = double(triangles);
}
BENCHMARK(BM_Buildings)->Threads(1)->Threads(2)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
