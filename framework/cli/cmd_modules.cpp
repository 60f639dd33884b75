// maquette modules: the modules found, their operators, inputs, outputs and parameters.
#include <iostream>
#include <memory>
#include <string>

#include "cli/builtin_steps.h"
#include "cli/commands.h"
#include "runtime/operator_registry.h"

namespace maquette::cli {

void add_modules_command(CLI::App& app) {
  auto as_json = std::make_shared<bool>(false);
  auto only = std::make_shared<std::string>();
  CLI::App* modules = app.add_subcommand(
      "modules",
      "List modules (from MAQUETTE_MODULE_PATH, then lib/maquette next to the program) and their "
      "operators with inputs, outputs and parameters (each module's README in the source tree, "
      "modules/NAME/README.md, tells how they work)");
  modules->add_option("name", *only,
                      "Only this module (e.g. synthesis) or operator (e.g. synthesis.transfer)");
  modules->add_flag("--json", *as_json, "Print JSON");
  modules->callback([as_json, only] {
    const OperatorRegistry& registry = program_registry();
    if (*as_json)
      std::cout << registry.to_json(*only).dump(2) << "\n";
    else
      registry.print(std::cout, *only);
  });
}

}  // namespace maquette::cli
