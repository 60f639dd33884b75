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
  // inputs, outputs with dtype/channels/semantics/units, halo, params schema).
  nlohmann::json to_json() const;
  // `maquette modules`: the same, as text.
  void print(std::ostream& out) const;

 private:
  struct Entry {
    std::unique_ptr<Operator> op;
    LoadedModule module;
  };
  std::vector<LoadedModule> modules_;
  std::map<std::string, Entry> operators_;
};

}  // namespace maquette
