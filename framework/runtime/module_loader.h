// Finding and opening modules: shared libraries exporting MAQUETTE_MODULE_ENTRY (module_abi.h).
#pragma once

#include <string>
#include <vector>

#include "runtime/module_abi.h"

namespace maquette {

// A module opened with dlopen. The handle stays open for the life of the process, since the
// operators it creates have their code in it.
struct LoadedModule {
  std::string file;
  const MaquetteModuleInfo* info = nullptr;
};

// The directories searched for modules, in order: those of MAQUETTE_MODULE_PATH (colon-separated),
// then <directory of the program>/../lib/maquette.
std::vector<std::string> module_search_path();

// The module files (lib*.so) in `dirs`, sorted by name within each directory. Like PATH, the first
// file of a given name wins: a module in an earlier directory shadows one of the same file name in
// a later one. Missing directories are skipped.
std::vector<std::string> find_module_files(const std::vector<std::string>& dirs);

// Opens one module. Throws maquette::Error naming the file when it cannot be opened, has no entry
// point, or was built for another module ABI.
LoadedModule load_module(const std::string& file);

}  // namespace maquette
