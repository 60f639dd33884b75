// The operators of the loaded modules, by name ("<module>.<verb>").
#pragma once

#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "runtime/module_loader.h"
#include "runtime/operator.h"

namespace maquette {

class OperatorRegistry {
 public:
  // Loads every module found in `dirs` (see find_module_files). Throws maquette::Error on a bad
  // module or an operator name defined twice.
  static OperatorRegistry load(const std::vector<std::string>& dirs);

  // Adds the operators of a module; throws naming both files when an operator already exists,
  // and naming the file when an operator's declared kind does not match its class.
  void add(const LoadedModule& module);

  const Operator* find(const std::string& name) const;           // null when unknown
  const LoadedModule* module_of(const std::string& name) const;  // null when unknown
  const std::vector<LoadedModule>& modules() const { return modules_; }

  // `maquette modules --json`: per module name, version, description, file and operators (kind,
  // inputs, outputs with dtype/channels/semantics/units, halo, params schema). `only`: a module's
  // name (that module) or an operator's (its module with that operator alone); empty: every
  // module. Throws maquette::Error when `only` names neither.
  nlohmann::json to_json(const std::string& only = "") const;
  // `maquette modules`: the same, as text.
  void print(std::ostream& out, const std::string& only = "") const;

 private:
  // The modules and, of each, the operators `only` selects (to_json, print), in their order.
  struct Selected {
    const LoadedModule* module;
    std::vector<const OperatorSpec*> operators;
  };
  std::vector<Selected> select(const std::string& only) const;

  struct Entry {
    std::unique_ptr<Operator> op;
    LoadedModule module;
  };
  std::vector<LoadedModule> modules_;
  std::map<std::string, Entry> operators_;
};

}  // namespace maquette
