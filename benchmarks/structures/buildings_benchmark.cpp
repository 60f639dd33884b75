// structures.buildings' work per footprint (building_mesh.h: height, lowest terrain, extrusion,
// the validity checks, the mesh in the cell's frame) on London Soho's 158 OSM footprints over a
// synthetic DEM (modules/structures/tests/soho_scene.h), each thread building all of them once
// per iteration, all flat or every fifth pitched. Goal: >= 20,000 buildings per second on 2 cores
// (items_per_second, wall time). Side by side, CGAL's extrusion of the same footprints' outer
// rings (Polygon_mesh_processing::extrude_mesh, then triangulate_faces: an LoD1 block without
// terrain, holes, texture coordinates, normals or validity checks), the peer the issue quotes at
// about 68k buildings per second. CGAL is GPL: it serves this benchmark only, never the program.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/extrude.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

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

using CgalPoint = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
using CgalMesh = CGAL::Surface_mesh<CgalPoint>;

// Each footprint's outer ring in metres east and north of its first point (equirectangular: the
// same work for CGAL whatever the projection), counter-clockwise, without its closing point.
std::vector<std::vector<CgalPoint>> outer_rings_m() {
  std::vector<std::vector<CgalPoint>> rings;
  for (const maquette::VectorFeature& f : scene().footprints) {
    const auto& ring = f.geometry.polygons.at(0).rings.at(0);
    const double lon0 = ring[0].lon, lat0 = ring[0].lat;
    const double east = 111320 * std::cos(lat0 * std::numbers::pi / 180), north = 110540;
    std::vector<CgalPoint> points;
    for (size_t i = 0; i + 1 < ring.size(); ++i)
      points.emplace_back((ring[i].lon - lon0) * east, (ring[i].lat - lat0) * north, 0);
    double area2 = 0;
    for (size_t i = 0; i < points.size(); ++i) {
      const CgalPoint& a = points[i];
      const CgalPoint& b = points[(i + 1) % points.size()];
      area2 += a.x() * b.y() - b.x() * a.y();
    }
    if (area2 < 0) std::reverse(points.begin(), points.end());
    rings.push_back(std::move(points));
  }
  return rings;
}

void BM_CgalExtrude(benchmark::State& state) {
  const std::vector<std::vector<CgalPoint>> rings = outer_rings_m();
  size_t triangles = 0;
  for (auto _ : state) {
    triangles = 0;
    for (const auto& ring : rings) {
      CgalMesh footprint, block;
      std::vector<CgalMesh::Vertex_index> vertices;
      for (const CgalPoint& p : ring) vertices.push_back(footprint.add_vertex(p));
      footprint.add_face(vertices);
      CGAL::Polygon_mesh_processing::extrude_mesh(footprint, block,
                                                  CGAL::Epick::Vector_3(0, 0, 10));
      CGAL::Polygon_mesh_processing::triangulate_faces(block);
      triangles += block.number_of_faces();
      benchmark::DoNotOptimize(block.number_of_vertices());
    }
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(rings.size()));
  state.counters["triangles"] = double(triangles);
}
BENCHMARK(BM_CgalExtrude)->Threads(1)->Threads(2)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
