#include "runtime/pipeline.h"

#include <algorithm>
#include <climits>
#include <filesystem>
#include <set>

#include "core/error.h"
#include "core/json_file.h"
#include "core/tile.h"
#include "runtime/artifact_refs.h"
#include "runtime/params_schema.h"
#include "runtime/pipeline_region.h"

namespace maquette {
namespace {

using json = nlohmann::json;

[[noreturn]] void fail(const std::string& context, const std::string& path,
                       const std::string& what) {
  throw Error(context + ": " + (path.empty() ? "" : path + ": ") + what);
}

void check_fields(const json& obj, const std::set<std::string>& known, const std::string& context,
                  const std::string& path) {
  for (const auto& [key, _] : obj.items())
    if (!known.count(key)) fail(context, path, "unknown field '" + excerpt(key) + "'");
}

// An integer field within lo..hi (lo <= 0 <= hi). JSON integers are 64-bit, positive ones
// unsigned: they are compared as such, not truncated to int first.
int integer(const json& obj, const char* key, int lo, int hi, const std::string& context) {
  const json& v = obj.at(key);
  if (!v.is_number_integer()) fail(context, key, "expected an integer, got " + excerpt(v));
  const bool in_range = v.is_number_unsigned() ? v.get<uint64_t>() <= uint64_t(hi)
                                               : v.get<int64_t>() >= lo && v.get<int64_t>() <= hi;
  if (!in_range)
    fail(context, key,
         excerpt(v) + " is outside " + std::to_string(lo) + ".." + std::to_string(hi));
  return int(v.get<int64_t>());
}

// A step's "inputs" or "outputs": an object mapping port names to layer names.
std::map<std::string, std::string> port_map(const json& step, const char* key,
                                            const std::string& label) {
  std::map<std::string, std::string> out;
  if (!step.contains(key)) return out;
  const json& ports = step.at(key);
  if (!ports.is_object())
    fail(label, key, "expected an object of port: layer, got " + excerpt(ports));
  for (const auto& [port, layer] : ports.items()) {
    if (!layer.is_string() || layer.get<std::string>().empty())
      fail(label, std::string(key) + "." + excerpt(port),
           "expected a layer name, got " + excerpt(layer));
    out[port] = layer.get<std::string>();
  }
  return out;
}

void check_ports(const PipelineStep& step) {
  const OperatorSpec& spec = step.op->spec();
  const std::string label = step.label();
  auto names = [](const auto& specs) {
    std::string s;
    for (const auto& p : specs) s += (s.empty() ? "" : ", ") + p.name;
    return s.empty() ? std::string("none") : s;
  };
  // Ports by name (not structured bindings): clang before 16 cannot capture those in lambdas.
  for (const auto& input : step.inputs)
    if (std::none_of(spec.inputs.begin(), spec.inputs.end(),
                     [&](auto& i) { return i.name == input.first; }))
      fail(label, "inputs." + input.first,
           "unknown input port (the operator has: " + names(spec.inputs) + ")");
  for (const auto& in : spec.inputs)
    if (!in.optional && !step.inputs.count(in.name))
      fail(label, "inputs", "missing required input '" + in.name + "'");
  for (const auto& output : step.outputs)
    if (std::none_of(spec.outputs.begin(), spec.outputs.end(),
                     [&](auto& o) { return o.name == output.first; }))
      fail(label, "outputs." + output.first,
           "unknown output port (the operator has: " + names(spec.outputs) + ")");
  if (step.outputs.empty() && !spec.outputs.empty())  // a task may write no layer (export)
    fail(label, "outputs", "map at least one of: " + names(spec.outputs));
  if (spec.kind == OperatorKind::Reduce && step.outputs.size() != 1)
    fail(label, "outputs", "a reduce operator writes exactly one artifact");
  for (const auto& [port, layer] : step.outputs)
    for (const auto& [in_port, in_layer] : step.inputs)
      if (layer == in_layer)
        fail(label, "outputs." + port, "layer '" + layer + "' is also the step's input");
}

PipelineStep parse_step(const json& s, int index, const OperatorRegistry& registry) {
  PipelineStep step;
  step.index = index;
  const std::string where = "step " + std::to_string(index);
  if (!s.is_object()) fail(where, "", "expected an object, got " + excerpt(s));
  if (!s.contains("op") || !s.at("op").is_string()) fail(where, "op", "missing operator name");
  step.op_name = s.at("op").get<std::string>();
  const std::string label = step.label();
  check_fields(s, {"op", "inputs", "outputs", "params", "refine"}, label, "");
  step.op = registry.find(step.op_name);
  if (step.op == nullptr)
    fail(label, "op",
         "unknown operator '" + excerpt(step.op_name) +
             "' (no loaded module has it; see `maquette modules`)");
  const MaquetteModuleInfo& module = *registry.module_of(step.op_name)->info;
  step.module = std::string(module.name) + " " + module.version;
  step.inputs = port_map(s, "inputs", label);
  step.outputs = port_map(s, "outputs", label);
  check_ports(step);
  if (s.contains("refine")) {
    step.refine = integer(s, "refine", 0, kMaxRefine, label);
    const OperatorKind kind = step.op->spec().kind;
    if (step.refine > 0 && ((kind != OperatorKind::Cell && kind != OperatorKind::Region) ||
                            !step.op->spec().refinable))
      fail(label, "refine",
           "the operator writes its outputs at its inputs' resolution only (not refinable)");
    if (step.refine > step.op->spec().max_refine)
      fail(label, "refine",
           std::to_string(step.refine) + " is more than the operator takes (at most " +
               std::to_string(step.op->spec().max_refine) + ")");
  }
  step.params =
      validate_params(step.op->spec().params_schema, s.value("params", json::object()), label);
  if (artifact_refs(step.params).empty()) check_step_params(step, step.params);
  return step;
}

// A layer written by two steps would be overwritten by the second.
void check_distinct_outputs(const std::vector<PipelineStep>& steps) {
  std::map<std::string, int> writer;
  for (const auto& step : steps)
    for (const auto& [port, layer] : step.outputs)
      if (const auto [it, fresh] = writer.emplace(layer, step.index); !fresh)
        fail(step.label(), "outputs." + port,
             "layer '" + layer + "' is already written by step " + std::to_string(it->second));
}

}  // namespace

void check_step_params(const PipelineStep& step, const json& params) {
  const auto& check = step.op->spec().check_params;
  if (!check) return;
  std::set<std::string> mapped;
  for (const auto& [port, layer] : step.inputs) mapped.insert(port);
  try {
    check(params, mapped);
  } catch (const Error& e) {
    throw Error(step.label() + ": " + e.what());
  }
}

std::string PipelineStep::label() const {
  return "step " + std::to_string(index) + " (" + excerpt(op_name) + ")";
}

Pipeline parse_pipeline(std::string_view text, const std::string& source,
                        const std::string& base_dir, const OperatorRegistry& registry) {
  Pipeline p;
  p.source = source;
  p.base_dir = base_dir;
  p.document = parse_json(text, source);
  const json& doc = p.document;
  if (!doc.is_object()) throw Error(source + ": expected a JSON object, got " + doc.dump());
  check_fields(doc, {"store", "region", "level", "tile_size", "steps"}, source, "");
  for (const char* key : {"store", "region", "level", "steps"})
    if (!doc.contains(key)) fail(source, key, "missing required field");

  if (!doc.at("store").is_string())
    fail(source, "store", "expected a path, got " + excerpt(doc.at("store")));
  p.store_path = (std::filesystem::path(base_dir) / doc.at("store").get<std::string>()).string();
  p.level = integer(doc, "level", 0, CellId::kMaxLevel, source);
  if (doc.contains("tile_size")) {
    p.tile_size = integer(doc, "tile_size", INT_MIN, INT_MAX, source);
    try {
      check_overview_tile_size(p.tile_size);
    } catch (const Error& e) {
      fail(source, "tile_size", e.what());
    }
  }

  const json& steps = doc.at("steps");
  if (!steps.is_array() || steps.empty())
    fail(source, "steps", "expected a non-empty array of steps");
  try {  // a step's errors name it ("step 2 (op)"), and the file here
    for (size_t i = 0; i < steps.size(); ++i)
      p.steps.push_back(parse_step(steps[i], int(i) + 1, registry));
    check_distinct_outputs(p.steps);
  } catch (const Error& e) {
    fail(source, "", e.what());
  }

  p.region = region_cells(doc.at("region"), p.level, base_dir, source);
  return p;
}

Pipeline load_pipeline(const std::string& path, const OperatorRegistry& registry) {
  return parse_pipeline(read_text_file(path), path,
                        std::filesystem::path(path).parent_path().string(), registry);
}

}  // namespace maquette
