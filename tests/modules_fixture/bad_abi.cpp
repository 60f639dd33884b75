// A module built against another module ABI (7): the loader must refuse it, naming the file.
#include "runtime/module_abi.h"

extern "C" __attribute__((visibility("default"))) const MaquetteModuleInfo* maquette_module_info() {
  static const MaquetteModuleInfo info = {7, "bad_abi", "0.0.0", "built for ABI 7", nullptr, 0};
  return &info;
}
