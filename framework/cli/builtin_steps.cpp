#include "cli/builtin_steps.h"

namespace maquette::cli {
namespace {

const LoadedModule& builtin_module() {
  static const MaquetteOperatorEntry entries[] = {{"ingest", &make_ingest_step},
                                                  {"export", &make_export_step}};
  static const MaquetteModuleInfo info = {
      MAQUETTE_ABI_VERSION,
      "maquette",
      MAQUETTE_VERSION_STRING,
      "Built-in steps: ingest sources into a layer, export layers (the options of `maquette "
      "ingest` and `maquette export`)",
      entries,
      uint32_t(std::size(entries))};
  static const LoadedModule module{"(built into the program)", &info};
  return module;
}

}  // namespace

const OperatorRegistry& program_registry() {
  static const OperatorRegistry registry = [] {
    OperatorRegistry r = OperatorRegistry::load(module_search_path());
    r.add(builtin_module());
    return r;
  }();
  return registry;
}

nlohmann::json array_schema(const char* item_type, const std::string& description) {
  return {{"type", "array"}, {"items", {{"type", item_type}}}, {"description", description}};
}

std::string resolve_path(const std::string& base_dir, const std::string& path) {
  return (std::filesystem::path(base_dir) / path).lexically_normal().string();
}

}  // namespace maquette::cli
