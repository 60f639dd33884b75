// A module built against an older module ABI (1, before operators got the store): the loader
// must refuse it, naming the file.
#include "runtime/module_abi.h"

extern "C" __attribute__((visibility("default"))) const MaquetteModuleInfo* maquette_module_info() {
  static const MaquetteModuleInfo info = {1, "bad_abi", "0.0.0", "built for ABI 1", nullptr, 0};
  return &info;
}
