// deform.features on a sinusoidal terrain near Zion (samples of ~1.2 m): a 1 M-sample region
// (1024 x 1024) with one river 1 km long, its bed (the curve) 5 m below the terrain under it, banks
// 28 m on each side, so about 40,000 unknowns in the cross sections' solve (the issue's "one
// feature edit on a 1 M-sample region"); and the refined edits (1 to 3 levels finer) of a 150 m
// river, banks 20 m on each side, on a 256 x 256 region; and many strokes in one edit (parallel
// rivers in one GeoJSON, as a river network or a road net gives), whose time must grow with the
// strokes as their unknowns do, not faster. Times the whole step as the runner calls
// it, without reading or writing the store. Beside it, CGAL's ARAP deformation of the same
// 1 M-sample region (the band's samples free, the curve's moved to our solve's heights), the ratio
// printed.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_deformation.h>
#include <benchmark/benchmark.h>

#include <GeographicLib/LocalCartesian.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <ctime>
#include <numbers>
#include <string>
#include <vector>

#include "core/halo.h"
#include "main_thread_cpu.h"
#include "operators.h"

namespace {

using namespace maquette;

struct Scene {
  Mosaic input, output;
  std::vector<VectorFeature> rivers;
  // Every sample's position (e, n) in metres on the site's tangent plane, row by row, and the
  // first river's curve from `start` to `end` there.
  std::vector<std::array<double, 2>> samples;
  std::array<double, 2> start, end;
};

// The sinusoidal terrain's height at (e, n) metres of the site's tangent plane.
double terrain(double e, double n) {
  return 1500 +
         3 * std::sin(2 * std::numbers::pi * e / 80) * std::cos(2 * std::numbers::pi * n / 110);
}

// A region of side x side samples of ~1.2 m (pixel level 23) and `rivers` parallel rivers
// `length` m long, 3 x `bank` m apart, their banks `bank` m from their curves, output `refine`
// levels finer.
Scene make_scene(int side, double length, double bank, int refine, int rivers = 1) {
  const int pixel_level = 23, cell_level = pixel_level - int(std::log2(side));
  const CellId cell = default_grid().cell_from_point({-113.0, 37.2}, cell_level);
  const LonLat site = default_grid().centre(cell);
  const GeographicLib::LocalCartesian plane(site.lat, site.lon, 0);
  Scene s;
  s.input.face = cell.face();
  s.input.level = pixel_level;
  s.input.origin_col = int64_t(cell.col()) * side;
  s.input.origin_row = int64_t(cell.row()) * side;
  Tile<float> dem(side, 1);
  for (int r = 0; r < side; ++r)
    for (int c = 0; c < side; ++c) {
      const LonLat p =
          pixel_centre(default_grid(),
                       {s.input.face, s.input.origin_col + c, s.input.origin_row + r}, pixel_level);
      double e = 0, n = 0, u = 0;
      plane.Forward(p.lat, p.lon, 0, e, n, u);
      dem.at(c, r) = float(terrain(e, n));
      s.samples.push_back({e, n});
    }
  s.input.layers.emplace("dem", std::move(dem));
  s.output = s.input;
  s.output.level += refine;
  s.output.layers.at("dem") = Tile<float>(side << refine, 1, 0, NAN);

  auto lonlat = [&](double e, double n) {
    double lat = 0, lon = 0, h = 0;
    plane.Reverse(e, n, 0, lat, lon, h);
    return GeoPoint{lon, lat};
  };
  const double heading = 30 * std::numbers::pi / 180;
  const std::array<double, 2> along = {std::cos(heading), std::sin(heading)},
                              across = {-along[1], along[0]};
  for (int k = 0; k < rivers; ++k) {
    // Centred on the site, the rivers side by side across it.
    const double shift = 3 * bank * (k - 0.5 * (rivers - 1));
    const double e0 = -0.433 * length + shift * across[0], n0 = -0.25 * length + shift * across[1];
    VectorFeature river;
    river.id = k + 1;
    river.geometry.type = GeometryType::LineString;
    const std::array<double, 2> a = {e0, n0}, b = {e0 + length * along[0], n0 + length * along[1]};
    if (k == 0) s.start = a, s.end = b;
    river.geometry.lines = {{lonlat(a[0], a[1]), lonlat(b[0], b[1])}};
    // The curve is the bed, 5 m below the terrain under it (a profile every metre), the banks at
    // the terrain's height (dz 5 m): the curve's elevation holds at offset 0.
    json profile = json::array();
    for (double d = 0; d < length + 1; d += 1) {
      const double t = std::min(d, length);
      profile.push_back({t, terrain(e0 + t * along[0], n0 + t * along[1]) - 5});
    }
    river.attributes = {
        {"tool", "feature"},
        {"profile", profile},
        {"cross_section", {{-bank, 5}, {-0.3 * bank, 0}, {0.3 * bank, 0}, {bank, 5}}}};
    s.rivers.push_back(std::move(river));
  }
  return s;
}

// The process's CPU time (every thread), in ms.
double process_cpu_ms() { return 1e3 * double(std::clock()) / CLOCKS_PER_SEC; }

// deform.features's step on the scene, as the runner calls it: s.output's dem is the edit.
void edit(Scene& s) {
  auto& strokes = s.input.features["strokes"];  // the copy's own features
  strokes.clear();
  for (const VectorFeature& river : s.rivers) strokes.push_back(&river);
  const json params = {{"energy_weight", 0.01}, {"subdivision", "adaptive"}};  // the defaults
  const auto op = deform::make_features();
  static_cast<const RegionOperator&>(*op).run({&default_grid(), &params, nullptr}, s.input,
                                              s.output);
}

// CPU time (all threads) per base-level edit of the 1 M-sample region, for CgalArap's ratio.
double base_level_edit_cpu_ms = 0;

// state.range: samples a side, river length (m), bank offset (m), refine.
void one_feature_edit(benchmark::State& state) {
  Scene s = make_scene(int(state.range(0)), double(state.range(1)), double(state.range(2)),
                       int(state.range(3)));
  maquette::bench::MainThreadCpu main_cpu(state);
  const double start = process_cpu_ms();
  for (auto _ : state) {
    edit(s);
    benchmark::DoNotOptimize(s.output.layers.at("dem").data());
  }
  main_cpu.stop();
  if (state.range(3) == 0)
    base_level_edit_cpu_ms = (process_cpu_ms() - start) / double(state.iterations());
}

BENCHMARK(one_feature_edit)
    ->Name("DeformFeatures")
    ->Args({1024, 1000, 28, 0})
    ->Args({256, 150, 20, 1})
    ->Args({256, 150, 20, 2})
    ->Args({256, 150, 20, 3})
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime();

// state.range: strokes in one edit (parallel rivers 100 m long, banks 5 m, 15 m apart, on the
// 1 M-sample region). The time per stroke should stay about flat as the strokes grow: each adds
// its own unknowns and constraints, not work over the others'.
void many_strokes_edit(benchmark::State& state) {
  Scene s = make_scene(1024, 100, 5, 0, int(state.range(0)));
  for (auto _ : state) {
    edit(s);
    benchmark::DoNotOptimize(s.output.layers.at("dem").data());
  }
  state.counters["s_per_stroke"] =
      benchmark::Counter(double(state.range(0)) * double(state.iterations()),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

BENCHMARK(many_strokes_edit)
    ->Name("DeformFeaturesStrokes")
    ->Arg(1)
    ->Arg(8)
    ->Arg(64)
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime();

// The peer: CGAL's as-rigid-as-possible deformation (GPL: linked into this benchmark binary only)
// of the same region as a triangle mesh, the DEM's samples its vertices (tangent-plane metres).

using ArapPoint = CGAL::Simple_cartesian<double>::Point_3;
using ArapMesh = CGAL::Surface_mesh<ArapPoint>;
// CGAL's deformation with tag (ORIGINAL_ARAP: Sorkine and Alexa's; SPOKES_AND_RIMS, CGAL's
// default: Chao et al.'s) and its default solver, Eigen's SparseLU.
template <CGAL::Deformation_algorithm_tag tag>
using Arap = CGAL::Surface_mesh_deformation<ArapMesh, CGAL::Default, CGAL::Default, tag>;
constexpr unsigned arap_iterations = 5;  // CGAL's default count; tolerance 0 so all of them run

// Whether p is within `half_width` of the segment a-b, across it and not beyond its ends (the band
// whose samples deform.features frees).
bool in_band(const std::array<double, 2>& p, const std::array<double, 2>& a,
             const std::array<double, 2>& b, double half_width) {
  const double ex = b[0] - a[0], ey = b[1] - a[1], length = std::hypot(ex, ey);
  const double along = ((p[0] - a[0]) * ex + (p[1] - a[1]) * ey) / length;
  const double across = ((p[1] - a[1]) * ex - (p[0] - a[0]) * ey) / length;
  return along >= 0 && along <= length && std::abs(across) <= half_width;
}

struct ArapScene {
  ArapMesh mesh;                // two triangles per square of four samples
  std::vector<ArapPoint> rest;  // every vertex's position before the deformation
  // The region of interest (the samples between the river's banks, which our solve frees: as many
  // as its unknowns) and its handles (the samples within half a spacing of the curve), moved to
  // the heights deform.features gives them; the rest of the mesh is fixed.
  std::vector<ArapMesh::Vertex_index> roi, handles;
  std::vector<ArapPoint> targets;
};

ArapScene make_arap_scene(int side, double length, double bank) {
  Scene s = make_scene(side, length, bank, 0);
  edit(s);
  const Tile<float>& before = s.input.layers.at("dem");
  const Tile<float>& after = s.output.layers.at("dem");
  const double spacing =
      std::hypot(s.samples[1][0] - s.samples[0][0], s.samples[1][1] - s.samples[0][1]);
  ArapScene a;
  for (int r = 0; r < side; ++r)
    for (int c = 0; c < side; ++c) {
      const auto& en = s.samples[size_t(r) * size_t(side) + size_t(c)];
      a.rest.emplace_back(en[0], en[1], before.at(c, r));
      const ArapMesh::Vertex_index v = a.mesh.add_vertex(a.rest.back());
      if (in_band(en, s.start, s.end, bank)) a.roi.push_back(v);
      if (in_band(en, s.start, s.end, spacing / 2)) {
        a.handles.push_back(v);
        a.targets.emplace_back(en[0], en[1], after.at(c, r));
      }
    }
  auto vertex = [&](int c, int r) { return ArapMesh::Vertex_index(uint32_t(r * side + c)); };
  for (int r = 0; r + 1 < side; ++r)
    for (int c = 0; c + 1 < side; ++c) {
      a.mesh.add_face(vertex(c, r), vertex(c + 1, r), vertex(c + 1, r + 1));
      a.mesh.add_face(vertex(c, r), vertex(c + 1, r + 1), vertex(c, r + 1));
    }
  return a;
}

// The like-for-like check (not a quality comparison): the handles at their targets within 1 mm,
// every vertex outside the region of interest where it was. Returns an error or "".
std::string arap_error(const ArapScene& a) {
  for (size_t i = 0; i < a.handles.size(); ++i)
    if (std::sqrt(CGAL::squared_distance(a.mesh.point(a.handles[i]), a.targets[i])) > 1e-3)
      return "a handle more than 1 mm from its target";
  std::vector<bool> in_roi(a.rest.size(), false);
  for (const auto v : a.roi) in_roi[v.idx()] = true;
  for (const auto v : a.mesh.vertices())
    if (!in_roi[v.idx()] && a.mesh.point(v) != a.rest[v.idx()])
      return "a vertex outside the region of interest moved";
  return "";
}

// state.range: as DeformFeatures's at the base level (samples a side, length, bank).
template <CGAL::Deformation_algorithm_tag tag>
void cgal_arap(benchmark::State& state) {
  ArapScene a =
      make_arap_scene(int(state.range(0)), double(state.range(1)), double(state.range(2)));
  double preprocess_ms = 0, deform_ms = 0, max_move_m = 0;
  for (auto _ : state) {
    state.PauseTiming();
    for (const auto v : a.roi) a.mesh.point(v) = a.rest[v.idx()];
    state.ResumeTiming();
    const double start = maquette::bench::thread_cpu_ms();
    Arap<tag> arap(a.mesh);
    arap.insert_roi_vertices(a.roi.begin(), a.roi.end());
    arap.insert_control_vertices(a.handles.begin(), a.handles.end());
    if (!arap.preprocess()) {
      state.SkipWithError("CGAL's ARAP preprocess failed (a singular system)");
      return;
    }
    const double preprocessed = maquette::bench::thread_cpu_ms();
    for (size_t i = 0; i < a.handles.size(); ++i)
      arap.set_target_position(a.handles[i], a.targets[i]);
    arap.deform(arap_iterations, 0);
    const double deformed = maquette::bench::thread_cpu_ms();
    preprocess_ms += preprocessed - start;
    deform_ms += deformed - preprocessed;
  }
  if (const std::string error = arap_error(a); !error.empty()) {
    state.SkipWithError(error.c_str());
    return;
  }
  for (const auto v : a.roi)
    max_move_m =
        std::max(max_move_m, std::sqrt(CGAL::squared_distance(a.mesh.point(v), a.rest[v.idx()])));
  const double iterations = double(state.iterations());
  state.counters["roi_vertices"] = double(a.roi.size());
  state.counters["handles"] = double(a.handles.size());
  state.counters["preprocess_ms"] = preprocess_ms / iterations;
  state.counters["deform_ms"] = deform_ms / iterations;
  state.counters["max_move_m"] = max_move_m;
  if (base_level_edit_cpu_ms > 0)
    state.counters["cgal_over_ours"] =
        (preprocess_ms + deform_ms) / iterations / base_level_edit_cpu_ms;
}

// After DeformFeatures (registered first, so run first): its base level gives the ratio.
BENCHMARK(cgal_arap<CGAL::ORIGINAL_ARAP>)
    ->Name("CgalArap")
    ->Args({1024, 1000, 28})
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime();
BENCHMARK(cgal_arap<CGAL::SPOKES_AND_RIMS>)
    ->Name("CgalArapSpokesAndRims")
    ->Args({1024, 1000, 28})
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime();

}  // namespace

BENCHMARK_MAIN();
