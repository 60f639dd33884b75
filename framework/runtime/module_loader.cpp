#include "runtime/module_loader.h"

#include <dlfcn.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <set>

#include "core/error.h"
#include "runtime/plugin.h"

namespace maquette {
namespace fs = std::filesystem;

std::vector<std::string> module_search_path() {
  std::vector<std::string> dirs;
  if (const char* env = std::getenv("MAQUETTE_MODULE_PATH")) {
    const std::string path = env;
    size_t start = 0;
    while (start <= path.size()) {
      const size_t end = std::min(path.find(':', start), path.size());
      if (end > start) dirs.push_back(path.substr(start, end - start));
      start = end + 1;
    }
  }
  dirs.push_back((program_prefix() / "lib" / "maquette").string());
  return dirs;
}

std::vector<std::string> find_module_files(const std::vector<std::string>& dirs) {
  std::vector<std::string> files;
  std::set<std::string> seen_names;
  for (const auto& dir : dirs) {
    std::error_code ec;
    std::vector<fs::path> here;
    for (const auto& entry : fs::directory_iterator(dir, ec)) {
      const std::string name = entry.path().filename().string();
      if (name.starts_with("lib") && name.ends_with(".so") && !entry.is_directory())
        here.push_back(entry.path());
    }
    std::sort(here.begin(), here.end());
    for (const auto& p : here)
      if (seen_names.insert(p.filename().string()).second) files.push_back(p.string());
  }
  return files;
}

LoadedModule load_module(const std::string& file) {
  void* handle = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr) throw Error("cannot load module " + file + ": " + dlerror());
  using Entry = const MaquetteModuleInfo* (*)();
  auto entry = reinterpret_cast<Entry>(dlsym(handle, MAQUETTE_MODULE_ENTRY));
  if (entry == nullptr) {
    dlclose(handle);
    throw Error(file + " is not a Maquette module: no " MAQUETTE_MODULE_ENTRY " entry point");
  }
  const MaquetteModuleInfo* info = entry();
  if (info == nullptr) {
    dlclose(handle);
    throw Error(file + " is not a Maquette module: " MAQUETTE_MODULE_ENTRY " returned null");
  }
  if (info->abi_version != MAQUETTE_ABI_VERSION) {
    const uint32_t abi = info->abi_version;
    dlclose(handle);
    throw Error(file + " was built for module ABI " + std::to_string(abi) +
                ", this maquette has ABI " + std::to_string(MAQUETTE_ABI_VERSION) + ": rebuild it");
  }
  return LoadedModule{file, info};
}

}  // namespace maquette
