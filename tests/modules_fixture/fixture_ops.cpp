// Operators for the runtime tests, one of each kind:
//   fixture.fill         cell, no input: a value of the global pixel coordinates and a seed;
//   fixture.blur         cell, halo 1: 3x3 NaN-aware mean, so a result depends on neighbours;
//   fixture.sum          reduce: float sum of a layer, merged in float, so merge order shows;
//   fixture.region_scan  region: a running sum along each mosaic row (depends on the whole row);
//   and the operators on features of fixture_features.cpp and across face seams of
//   fixture_seams.cpp.
// fill refuses a seed of 20000 or more (its check_params, beyond its schema). fill and blur take
// sleep_ms (per cell, to make runs slow enough to kill), fail_on (a cell id:
// they throw on it and its descendants) and fail_with ("exception": a std::runtime_error, "int":
// an int). They record the threads they run on: fixture_thread_count() (a C entry point the tests
// find with dlsym) tells how many distinct threads ran them since fixture_reset_threads(); with
// meet_threads N each cell waits until N distinct threads have run one (a latch: a test of the
// threads' use that does not depend on how fast a loaded machine wakes a worker; 60 s at most).
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstddef>
#include <memory>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>

#include "core/error.h"
#include "fixture_features.h"
#include "fixture_seams.h"
#include "runtime/module_abi.h"

namespace {

using maquette::CellContext;
using maquette::CellData;
using maquette::json;
using maquette::OperatorSpec;

const json kSlowAndFailing = {
    {"sleep_ms", {{"type", "integer"}, {"minimum", 0}, {"maximum", 10000}, {"default", 0}}},
    {"fail_on", {{"type", "string"}, {"default", ""}}},
    {"fail_with", {{"type", "string"}, {"enum", {"exception", "int"}}, {"default", "exception"}}},
    {"meet_threads", {{"type", "integer"}, {"minimum", 0}, {"maximum", 64}, {"default", 0}}}};

std::mutex threads_mutex;
std::condition_variable threads_met;
std::set<std::thread::id> threads_seen;

json schema(json properties, json required = json::array()) {
  properties.update(kSlowAndFailing);
  return {{"type", "object"},
          {"properties", properties},
          {"required", required},
          {"additionalProperties", false}};
}

OperatorSpec make_spec(const std::string& name, const std::string& description,
                       maquette::OperatorKind kind, const std::string& input,
                       const std::string& output, const json& params) {
  OperatorSpec s;
  s.name = name;
  s.description = description;
  s.kind = kind;
  if (!input.empty()) s.inputs.push_back({input, "any layer", false});
  maquette::OutputSpec out;
  out.name = output;
  out.description = "the result";
  s.outputs.push_back(out);
  s.params_schema = params;
  return s;
}

void slow_and_failing(const CellContext& ctx) {
  const json& p = *ctx.params;
  {
    std::unique_lock lock(threads_mutex);
    threads_seen.insert(std::this_thread::get_id());
    threads_met.notify_all();
    const size_t meet = p.at("meet_threads").get<size_t>();
    threads_met.wait_for(lock, std::chrono::seconds(60),
                         [&] { return threads_seen.size() >= meet; });
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(p.at("sleep_ms").get<int>()));
  const std::string fail_on = p.at("fail_on").get<std::string>();
  if (!fail_on.empty() && ctx.cell.ToText().starts_with(fail_on)) {
    if (p.at("fail_with") == "int") throw 42;
    throw std::runtime_error("fixture failure requested");
  }
}

class Fill : public maquette::CellOperator {
 public:
  const OperatorSpec& spec() const override {
    static const OperatorSpec s = [] {
      OperatorSpec s = make_spec(
          "fixture.fill", "Deterministic values of the global pixel coordinates",
          maquette::OperatorKind::Cell, "", "value",
          schema(
              {{"seed", {{"type", "number"}}},
               {"mode", {{"type", "string"}, {"enum", {"wave", "ramp"}}, {"default", "wave"}}},
               {"weights",
                {{"type", "array"}, {"items", {{"type", "number"}}}, {"default", json::array()}}}},
              {"seed"}));
      // A check beyond the schema (OperatorSpec::check_params), for the runtime's tests of it.
      s.check_params = [](const json& params, const std::set<std::string>&) {
        if (params.at("seed").get<double>() >= 20000)
          throw maquette::Error("params.seed: " + params.at("seed").dump() +
                                " is 20000 or more (the fixture's check)");
      };
      return s;
    }();
    return s;
  }
  void run(const CellContext& ctx, CellData& data) const override {
    slow_and_failing(ctx);
    const double seed = ctx.params->at("seed").get<double>();
    const bool wave = ctx.params->at("mode") == "wave";
    auto& out = data.output("value");
    for (int r = 0; r < out.size(); ++r)
      for (int c = 0; c < out.size(); ++c) {
        const double x = double(maquette::global_col(ctx.cell, out.size(), c));
        const double y = double(maquette::global_row(ctx.cell, out.size(), r));
        // Magnitudes from 1e-3 to 1e3, so that float sums depend on their order.
        out.at(c, r) = wave ? float(1000 * std::sin(x * 0.37 + seed) * std::cos(y * 0.11) +
                                    1e-3 * (x + y) + ctx.cell.face())
                            : float(x + y);
      }
  }
};

class Blur : public maquette::CellOperator {
 public:
  const OperatorSpec& spec() const override {
    static const OperatorSpec s = [] {
      OperatorSpec s =
          make_spec("fixture.blur", "3x3 mean of the neighbours (NaN-aware)",
                    maquette::OperatorKind::Cell, "src", "dst", schema(json::object()));
      s.outputs[0].nodata = -9999;
      s.halo = 1;
      return s;
    }();
    return s;
  }
  void run(const CellContext& ctx, CellData& data) const override {
    slow_and_failing(ctx);
    const auto& in = data.input("src");
    auto& out = data.output("dst");
    for (int r = 0; r < out.size(); ++r)
      for (int c = 0; c < out.size(); ++c) {
        float sum = 0;
        int n = 0;
        for (int dr = -1; dr <= 1; ++dr)
          for (int dc = -1; dc <= 1; ++dc)
            if (const float v = in.at(c + dc, r + dr); !std::isnan(v)) {
              sum += v;
              ++n;
            }
        out.at(c, r) = n > 0 ? sum / float(n) : NAN;
      }
  }
};

class Sum : public maquette::ReduceOperator {
 public:
  const OperatorSpec& spec() const override {
    static const OperatorSpec s =
        make_spec("fixture.sum", "Float sum and count of a layer's samples",
                  maquette::OperatorKind::Reduce, "src", "total", schema(json::object()));
    return s;
  }
  json map(const CellContext&, const CellData& data) const override {
    float sum = 0;
    int64_t count = 0;
    for (const float v : data.input("src").data())
      if (!std::isnan(v)) {
        sum += v;
        ++count;
      }
    return {{"sum", sum}, {"count", count}};
  }
  json merge(const json& a, const json& b) const override {
    return {{"sum", a.at("sum").get<float>() + b.at("sum").get<float>()},
            {"count", a.at("count").get<int64_t>() + b.at("count").get<int64_t>()}};
  }
  maquette::Artifact finish(const json& merged, const maquette::StepContext&) const override {
    return maquette::Artifact::FromText("", merged.dump(), {{"operator", "fixture.sum"}});
  }
};

class RegionScan : public maquette::RegionOperator {
 public:
  const OperatorSpec& spec() const override {
    static const OperatorSpec s =
        make_spec("fixture.region_scan", "Running sum along each row of the region",
                  maquette::OperatorKind::Region, "src", "dst", OperatorSpec().params_schema);
    return s;
  }
  void run(const maquette::StepContext&, const maquette::Mosaic& input,
           maquette::Mosaic& output) const override {
    const auto& in = input.layers.at("src");
    auto& out = output.layers.at("dst");
    for (int r = 0; r < in.size(); ++r) {
      float acc = 0;
      for (int c = 0; c < in.size(); ++c) {
        if (!std::isnan(in.at(c, r))) acc = 0.5f * acc + in.at(c, r);
        out.at(c, r) = acc;
      }
    }
  }
};

template <typename T>
std::unique_ptr<maquette::Operator> make() {
  return std::make_unique<T>();
}

}  // namespace

MAQUETTE_MODULE("fixture", "0.0.1", "Operators for the runtime tests",
                {"fixture.fill", &make<Fill>}, {"fixture.blur", &make<Blur>},
                {"fixture.sum", &make<Sum>}, {"fixture.region_scan", &make<RegionScan>},
                {"fixture.near_features", &make_near_features},
                {"fixture.region_features", &make_region_features},
                {"fixture.features_total", &make_features_total},
                {"fixture.content", &make_content},
                {"fixture.region_content", &make_region_content},
                {"fixture.pixel_lonlat", &make_pixel_lonlat},
                {"fixture.region_seams", &make_region_seams})

extern "C" __attribute__((visibility("default"))) size_t fixture_thread_count() {
  std::lock_guard lock(threads_mutex);
  return threads_seen.size();
}

extern "C" __attribute__((visibility("default"))) void fixture_reset_threads() {
  std::lock_guard lock(threads_mutex);
  threads_seen.clear();
}
