// structures.buildings' work per footprint (building_mesh.h: height, lowest terrain, extrusion,
// the validity checks, the mesh in the cell's frame) on London Soho's 158 OSM footprints over a
// synthetic DEM (modules/structures/tests/soho_scene.h), each thread building all of them once
// per iteration, all flat or every fifth pitched. Goal: >= 20,000 buildings per second on 2 cores
// (items_per_second, wall time).
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

// Soho's footprints, every fifth (`pitched_every`) with a pitched roof 3 m high, the four shapes
// in turn (OSM tags none; tests/buildings tags them so too); 0: all flat.
std::vector<maquette::VectorFeature> footprints(size_t pitched_every) {
  std::vector<maquette::VectorFeature> out = scene().footprints;
  constexpr const char* kShapes[] = {"gabled", "hipped", "pyramidal", "skillion"};
  for (size_t i = 0; pitched_every > 0 && i < out.size(); i += pitched_every)
    out[i].attributes.update({{"roof:shape", kShapes[i / pitched_every % 4]}, {"roof:height", 3}});
  return out;
}

void BM_Buildings(benchmark::State& state) {
  const SohoScene& s = scene();
  const std::vector<maquette::VectorFeature> features = footprints(size_t(state.range(0)));
  std::vector<BuildingSite> sites;
  for (const auto& f : features) sites.push_back(s.site(f));
  size_t triangles = 0;
  for (auto _ : state) {
    triangles = 0;
    for (size_t i = 0; i < features.size(); ++i) {
      const maquette::MeshObject m =
          maquette::with_facet_normals(building_mesh(features[i], {}, sites[i]));
      triangles += m.indices.size() / 3;
      benchmark::DoNotOptimize(m.positions.data());
    }
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(features.size()));
  state.counters["triangles"] = double(triangles);
}
// Argument: one footprint in that many pitched (0: none).
BENCHMARK(BM_Buildings)->Arg(0)->Arg(5)->Threads(1)->Threads(2)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
