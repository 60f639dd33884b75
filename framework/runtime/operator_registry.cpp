#include "runtime/operator_registry.h"

#include <cmath>

#include "core/error.h"
#include "runtime/task_operator.h"

namespace maquette {
namespace {

bool kind_matches(const Operator& op) {
  switch (op.spec().kind) {
    case OperatorKind::Cell:
      return dynamic_cast<const CellOperator*>(&op) != nullptr;
    case OperatorKind::Reduce:
      return dynamic_cast<const ReduceOperator*>(&op) != nullptr;
    case OperatorKind::Region:
      return dynamic_cast<const RegionOperator*>(&op) != nullptr;
    case OperatorKind::Task:
      return dynamic_cast<const TaskOperator*>(&op) != nullptr;
  }
  return false;
}

// Ports the runner can serve: inputs of raster or features layers (features with a finite reach
// >= 0, not for tasks), outputs of raster or 3D content layers (content for cell and region
// operators only). Returns what is wrong, or "".
std::string port_error(const OperatorSpec& spec) {
  for (const auto& in : spec.inputs) {
    const std::string where = "input '" + in.name + "' ";
    if (in.kind != LayerKind::Raster && in.kind != LayerKind::Features)
      return where + "takes " + std::string(layer_kind_name(in.kind)) +
             " layers (ports take raster or features layers)";
    if (in.kind == LayerKind::Features && !(in.reach_m >= 0 && std::isfinite(in.reach_m)))
      return where + "has reach_m " + std::to_string(in.reach_m) + " (a distance >= 0 is needed)";
    if (in.kind == LayerKind::Features && spec.kind == OperatorKind::Task)
      return where + "takes features, which tasks are not given";
  }
  for (const auto& out : spec.outputs) {
    if (out.kind != LayerKind::Raster && !layer_content_kind(out.kind))
      return "output '" + out.name + "' writes " + std::string(layer_kind_name(out.kind)) +
             " layers (outputs write raster or 3D content layers)";
    if (out.kind != LayerKind::Raster && spec.kind != OperatorKind::Cell &&
        spec.kind != OperatorKind::Region)
      return "output '" + out.name + "' writes 3D content, which only cell and region operators do";
  }
  return "";
}

nlohmann::json operator_json(const OperatorSpec& spec) {
  nlohmann::json inputs = nlohmann::json::array();
  for (const auto& in : spec.inputs) {
    nlohmann::json i = {{"name", in.name},
                        {"description", in.description},
                        {"optional", in.optional},
                        {"kind", layer_kind_name(in.kind)}};
    if (in.kind == LayerKind::Features) i["reach_m"] = in.reach_m;
    inputs.push_back(i);
  }
  nlohmann::json outputs = nlohmann::json::array();
  for (const auto& out : spec.outputs) {
    nlohmann::json o = {{"name", out.name},
                        {"description", out.description},
                        {"dtype", dtype_name(out.dtype)},
                        {"channels", out.channels},
                        {"semantics", semantics_name(out.semantics)},
                        {"units", out.units},
                        {"kind", layer_kind_name(out.kind)}};
    if (out.nodata) o["nodata"] = *out.nodata;
    outputs.push_back(o);
  }
  return {{"name", spec.name},
          {"description", spec.description},
          {"kind", operator_kind_name(spec.kind)},
          {"inputs", inputs},
          {"outputs", outputs},
          {"halo", spec.halo},
          {"params", spec.params_schema}};
}

// One line per parameter: "name type = default [min..max] {enum} (required)".
void print_params(std::ostream& out, const nlohmann::json& schema) {
  if (!schema.contains("properties")) return;
  const nlohmann::json required = schema.value("required", nlohmann::json::array());
  for (const auto& [name, p] : schema.at("properties").items()) {
    out << "      " << name << " " << p.value("type", std::string("any"));
    if (p.contains("default")) out << " = " << p.at("default").dump();
    if (p.contains("minimum") || p.contains("maximum"))
      out << " [" << (p.contains("minimum") ? p.at("minimum").dump() : "") << ".."
          << (p.contains("maximum") ? p.at("maximum").dump() : "") << "]";
    if (p.contains("enum")) out << " one of " << p.at("enum").dump();
    for (const auto& r : required)
      if (r == name) out << " (required)";
    if (p.contains("description")) out << ": " << p.at("description").get<std::string>();
    out << "\n";
  }
}

}  // namespace

OperatorRegistry OperatorRegistry::load(const std::vector<std::string>& dirs) {
  OperatorRegistry registry;
  for (const auto& file : find_module_files(dirs)) registry.add(load_module(file));
  return registry;
}

void OperatorRegistry::add(const LoadedModule& module) {
  const MaquetteModuleInfo& info = *module.info;
  for (uint32_t i = 0; i < info.operator_count; ++i) {
    const std::string name = info.operators[i].name;
    if (const auto it = operators_.find(name); it != operators_.end())
      throw Error("operator '" + name + "' is defined twice: in " + it->second.module.file +
                  " and in " + module.file);
    std::unique_ptr<Operator> op = info.operators[i].create();
    if (!op || op->spec().name != name)
      throw Error(module.file + ": operator '" + name +
                  "' does not create an operator of that name");
    if (!kind_matches(*op))
      throw Error(module.file + ": operator '" + name + "' declares kind " +
                  std::string(operator_kind_name(op->spec().kind)) + " but is not of that class");
    if (const std::string what = port_error(op->spec()); !what.empty())
      throw Error(module.file + ": operator '" + name + "': " + what);
    operators_.emplace(name, Entry{std::move(op), module});
  }
  modules_.push_back(module);
}

const Operator* OperatorRegistry::find(const std::string& name) const {
  const auto it = operators_.find(name);
  return it == operators_.end() ? nullptr : it->second.op.get();
}

const LoadedModule* OperatorRegistry::module_of(const std::string& name) const {
  const auto it = operators_.find(name);
  return it == operators_.end() ? nullptr : &it->second.module;
}

std::vector<OperatorRegistry::Selected> OperatorRegistry::select(const std::string& only) const {
  std::vector<Selected> out;
  for (const auto& m : modules_) {
    Selected s{&m, {}};
    for (uint32_t i = 0; i < m.info->operator_count; ++i)
      if (only.empty() || only == m.info->name || only == m.info->operators[i].name)
        s.operators.push_back(&find(m.info->operators[i].name)->spec());
    if (!s.operators.empty() || (only.empty() || only == m.info->name)) out.push_back(s);
  }
  if (!only.empty() && out.empty()) {
    std::string names;
    for (const auto& m : modules_) names += (names.empty() ? "" : ", ") + std::string(m.info->name);
    throw Error("no module or operator '" + only +
                "' (the modules: " + (names.empty() ? "none found" : names) + ")");
  }
  return out;
}

nlohmann::json OperatorRegistry::to_json(const std::string& only) const {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& [module, operators] : select(only)) {
    const LoadedModule& m = *module;
    nlohmann::json ops = nlohmann::json::array();
    for (const OperatorSpec* s : operators) ops.push_back(operator_json(*s));
    out.push_back({{"name", m.info->name},
                   {"version", m.info->version},
                   {"description", m.info->description},
                   {"file", m.file},
                   {"operators", ops}});
  }
  return out;
}

void OperatorRegistry::print(std::ostream& out, const std::string& only) const {
  if (modules_.empty())
    out << "no modules found (searched MAQUETTE_MODULE_PATH and lib/maquette)\n";
  for (const auto& [module, operators] : select(only)) {
    const LoadedModule& m = *module;
    out << m.info->name << " " << m.info->version << ": " << m.info->description << "\n  " << m.file
        << "\n";
    for (const OperatorSpec* spec : operators) {
      const OperatorSpec& s = *spec;
      out << "  " << s.name << " (" << operator_kind_name(s.kind);
      if (s.halo > 0) out << ", halo " << s.halo;
      out << "): " << s.description << "\n";
      for (const auto& in : s.inputs)
        out << "    input  " << in.name << (in.optional ? " (optional)" : "")
            << (in.kind == LayerKind::Features
                    ? " (features within " + nlohmann::json(in.reach_m).dump() + " m)"
                    : std::string())
            << ": " << in.description << "\n";
      for (const auto& o : s.outputs) {
        if (s.kind == OperatorKind::Task) {  // the layer's type comes from the task's params
          out << "    output " << o.name << ": " << o.description << "\n";
          continue;
        }
        out << "    output " << o.name << " " << dtype_name(o.dtype) << " x" << o.channels << " "
            << semantics_name(o.semantics);
        if (!o.units.empty()) out << " [" << o.units << "]";
        if (o.nodata) out << " nodata " << nlohmann::json(*o.nodata).dump();
        out << ": " << o.description << "\n";
      }
      if (s.params_schema.contains("properties") && !s.params_schema.at("properties").empty())
        out << "    params\n";
      print_params(out, s.params_schema);
    }
  }
}

}  // namespace maquette
