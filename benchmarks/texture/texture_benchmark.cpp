// texture module speed, through the loaded module as the runner calls it (inputs with halos
// prepared beforehand, as the runner's tile cache does):
//  - Procedural: texture.procedural with refine 2 on 2 cells of a 30 m DEM (level 10, input
//    tiles of 256 with 35 m pixels) -> 2 output tiles of 1024 x 1024 with 8.8 m pixels: how a
//    texture is made (finer than its DEM; at the DEM's own resolution the 50 to 300 m noise
//    would be a pixel or two). A model of 8 layers constrained by 5 quantities (height, slope,
//    temperature, rainfall, radiation), 3 octaves, wavelengths 50 to 300 m (6 to 34 output
//    pixels: every octave is evaluated), 2 threads; Mpx/s of output. The relief is
//    mountainous at that scale (0 to 3000 m, slopes up to ~45 degrees, ~9 km wavelength), so
//    every layer is active somewhere.
//  - Fit: texture.classify + texture.fit (map, merge in cell order, finish) on a 2400 x 2200
//    scene, 2 threads.
#include <benchmark/benchmark.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <ctime>
#include <map>

#include "core/halo.h"
#include "core/malloc_tuning.h"
#include "runtime/operator_registry.h"
#include "runtime/params_schema.h"

namespace maquette {
namespace {

using json = nlohmann::json;
constexpr int kSize = 256, kThreads = 2;
constexpr int kDemLevel = 10, kRefine = 2, kFitLevel = 6;

const Operator& op(const std::string& name) {
  static const OperatorRegistry registry = [] {
    OperatorRegistry r;
    r.add(load_module(MAQUETTE_MODULE_DIR "/libmaquette_texture.so"));
    return r;
  }();
  return *registry.find(name);
}

// Continental relief (wavelengths of tens of degrees) for the fit's scene at level 6, and a
// mountain relief (wavelengths of ~9 km) for the procedural tiles.
double relief(LonLat p) { return 1500 + 1450 * std::sin(p.lon * 9) * std::cos(p.lat * 7); }
double mountains(LonLat p) { return 1500 + 1450 * std::sin(p.lon * 80) * std::cos(p.lat * 60); }

Tile<float> sample(CellId cell, const std::function<double(LonLat)>& f, int channels = 1) {
  const int level = cell.level() + log2_tile_size(kSize);
  Tile<float> t(kSize, channels);
  for (int r = 0; r < kSize; ++r)
    for (int c = 0; c < kSize; ++c) {
      const double v = f(pixel_centre(
          default_grid(), {cell.face(), global_col(cell, kSize, c), global_row(cell, kSize, r)},
          level));
      for (int k = 0; k < channels; ++k) t.at(c, r, k) = float(v);
    }
  return t;
}

Tile<float> halo(CellId cell, int h, const std::function<double(LonLat)>& f) {
  return assemble_halo(default_grid(), cell, kSize, h,
                       [&](CellId n) { return std::optional(sample(n, f)); });
}

json hat(double a, double b, double c, double d) { return {{"hat", {a, b, c, d}}}; }

// 8 layers: root, 4 types constrained by all 5 quantities, 3 noisy children.
json model() {
  json q = json::array();
  for (const auto& [name, lo, hi] :
       std::vector<std::tuple<std::string, double, double>>{{"height", 0, 3000},
                                                            {"slope", 0, 90},
                                                            {"temperature", -10, 20},
                                                            {"rainfall", 0, 2000},
                                                            {"radiation", 0, 2e6}})
    q.push_back({{"name", name}, {"range", {lo, hi}}});
  json root = {{"colour", {150, 110, 90}}, {"class", 0}, {"children", json::array()}};
  for (int i = 0; i < 4; ++i) {
    const double h0 = 700.0 * i;
    json l = {{"class", i + 1},
              {"colour", {40 * i, 200 - 30 * i, 60}},
              {"noise_scale", 0.2},
              {"roughness_m", 2},
              {"noise", {{"seed", i + 2}, {"octaves", 3}, {"wavelength_m", 300}}},
              {"constraints",
               {{"height", hat(h0 - 200, h0, h0 + 900, h0 + 1100)},
                {"slope", hat(0, 0, 30 + 5 * i, 45 + 5 * i)},
                {"temperature", hat(-10, -5, 15, 20)},
                {"rainfall", hat(0, 100, 1800, 2000)},
                {"radiation", hat(0, 1e5, 1.8e6, 2e6)}}}};
    if (i < 3)
      l["children"] = {{{"colour", {90, 120, 50}},
                        {"bias", 0.5},
                        {"noise_scale", 0.6},
                        {"noise", {{"seed", 20 + i}}}}};
    root["children"].push_back(l);
  }
  return {{"format", "maquette.texture.model"}, {"version", 1}, {"quantities", q}, {"root", root}};
}

// cols x rows cells of `level` at the same place on face P (the cell (30, 30) of level 6).
std::vector<CellId> cells(int level, int cols, int rows) {
  const uint32_t first = 30u << (level - 6);
  std::vector<CellId> out;
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c)
      out.push_back(CellId::FromFaceColRow(2, level, first + uint32_t(c), first + uint32_t(r)));
  return out;
}

// CPU time of the process (all threads): the machine is shared, wall times are noisy.
double process_cpu_s() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

// On kThreads threads that live from one call to the next, as the runner's tbb arena runs cells
// (so what an operator keeps per thread lives on from tile to tile, as in a run).
void parallel(size_t n, const std::function<void(size_t)>& f) {
  static tbb::task_arena arena(kThreads);
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 1),
                      [&](const tbb::blocked_range<size_t>& r) {
                        for (size_t i = r.begin(); i != r.end(); ++i) f(i);
                      });
  });
}

void Procedural(benchmark::State& state) {
  const auto& proc = static_cast<const CellOperator&>(op("texture.procedural"));
  const json params = validate_params(proc.spec().params_schema, {{"model", model()}}, "bench");
  const std::vector<CellId> cs = cells(kDemLevel, 2, 1);
  std::vector<CellData> inputs(cs.size());
  for (size_t i = 0; i < cs.size(); ++i) {
    const int h = proc.spec().halo;
    inputs[i].inputs.emplace("dem", halo(cs[i], h, mountains));
    inputs[i].inputs.emplace("temperature",
                             halo(cs[i], h, [](LonLat p) { return 20 - 0.0065 * mountains(p); }));
    inputs[i].inputs.emplace("rainfall",
                             halo(cs[i], h, [](LonLat p) { return 300 + 0.5 * mountains(p); }));
    inputs[i].inputs.emplace("radiation",
                             halo(cs[i], h, [](LonLat p) { return 1e6 + 300 * mountains(p); }));
  }
  double cpu_s = 0;
  for (auto _ : state) {
    const double cpu0 = process_cpu_s();
    parallel(cs.size(), [&](size_t i) {
      CellData d = inputs[i];
      for (const OutputSpec& o : proc.spec().outputs)  // as the runner makes them (StepIO::load)
        d.outputs.emplace(o.name, proc.spec().writes_all_samples
                                      ? Tile<float>::uninitialized(kSize << kRefine, o.channels)
                                      : Tile<float>(kSize << kRefine, o.channels, 0, NAN));
      proc.run({cs[i], kSize, kRefine, &default_grid(), &params, nullptr}, d);
      benchmark::DoNotOptimize(d.outputs);
    });
    cpu_s += process_cpu_s() - cpu0;
  }
  const double mpx = double(cs.size()) * double(kSize << kRefine) * double(kSize << kRefine) *
                     1e-6 * double(state.iterations());
  state.counters["Mpx/cpu_s"] = mpx / cpu_s;  // both threads: 2 x this on 2 idle cores
  state.counters["Mpx/s"] = benchmark::Counter(mpx, benchmark::Counter::kIsRate);
}
BENCHMARK(Procedural)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(3);

void Fit(benchmark::State& state) {
  const auto& classify = static_cast<const CellOperator&>(op("texture.classify"));
  const auto& fit = static_cast<const ReduceOperator&>(op("texture.fit"));
  const json cp = validate_params(classify.spec().params_schema, json::parse(R"({"boxes": [
    {"id": 3, "hue": [290, 310], "value": [0.8, 1]}, {"id": 0, "hue": [0, 60]},
    {"id": 1, "hue": [60, 180], "value": [0.45, 1]}, {"id": 2, "hue": [60, 180], "value": [0, 0.45]}]})"),
                                  "bench");
  const json fp =
      validate_params(fit.spec().params_schema, {{"ranges", {{"height", {0, 3000}}}}}, "bench");
  // 10 x 9 tiles of 256, cropped to 2400 x 2200 pixels (NaN beyond).
  const std::vector<CellId> cs = cells(kFitLevel, 10, 9);
  const auto& proc = static_cast<const CellOperator&>(op("texture.procedural"));
  const json pp = validate_params(proc.spec().params_schema, {{"model", model()}}, "bench");
  std::vector<Tile<float>> rgb(cs.size()), dem(cs.size());
  parallel(cs.size(), [&](size_t i) {
    CellData d;
    d.inputs.emplace("dem", halo(cs[i], proc.spec().halo, relief));
    for (const char* q : {"temperature", "rainfall", "radiation"})
      d.inputs.emplace(q, halo(cs[i], proc.spec().halo, [](LonLat) { return 500.0; }));
    d.outputs.emplace("imagery", Tile<float>(kSize, 3));
    proc.run({cs[i], kSize, 0, &default_grid(), &pp, nullptr}, d);
    rgb[i] = d.outputs.at("imagery");
    for (int r = 0; r < kSize; ++r)
      for (int c = 0; c < kSize; ++c)
        for (int k = 0; k < 3; ++k) {
          float& v = rgb[i].at(c, r, k);
          v = (int(i % 10) * kSize + c >= 2400 || int(i / 10) * kSize + r >= 2200) ? NAN
                                                                                   : std::round(v);
        }
    dem[i] = d.inputs.at("dem");
  });
  for (auto _ : state) {
    std::vector<json> partials(cs.size());
    parallel(cs.size(), [&](size_t i) {
      CellData c;
      c.inputs.emplace("rgb", rgb[i]);
      c.outputs.emplace("classes", Tile<float>(kSize, 1));
      classify.run({cs[i], kSize, 0, &default_grid(), &cp, nullptr}, c);
      CellData f;
      f.inputs.emplace("classes", c.outputs.at("classes"));
      f.inputs.emplace("rgb", rgb[i]);
      f.inputs.emplace("dem", dem[i]);
      partials[i] = fit.map({cs[i], kSize, 0, &default_grid(), &fp, nullptr}, f);
    });
    json merged;
    for (const json& p : partials) merged = fit.merge(merged, p);
    benchmark::DoNotOptimize(fit.finish(merged, {&default_grid(), &fp, nullptr}));
  }
}
BENCHMARK(Fit)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(3);

}  // namespace
}  // namespace maquette

// With the maquette program's allocator settings.
int main(int argc, char** argv) {
  maquette::keep_tile_buffers_mapped();
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
}
