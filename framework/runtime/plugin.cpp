#include "runtime/plugin.h"

#include <dlfcn.h>

#include "core/error.h"

namespace maquette {
namespace fs = std::filesystem;

fs::path program_prefix() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) throw Error("cannot find the program's directory: /proc/self/exe: " + ec.message());
  return exe.parent_path().parent_path();
}

void* plugin_symbol(const std::string& file, const char* symbol) {
  const std::string path = (program_prefix() / "lib" / file).string();
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr) throw Error("cannot load the plug-in " + path + ": " + dlerror());
  void* address = dlsym(handle, symbol);
  if (address == nullptr)
    throw Error("the plug-in " + path + " has no entry point " + symbol + ": rebuild it");
  return address;
}

}  // namespace maquette
