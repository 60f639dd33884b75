// The one C entry point of a module. A module is a shared library exporting
//
//   extern "C" const MaquetteModuleInfo* maquette_module_info(void);
//
// The loader reads abi_version first and refuses a module built against another framework
// ABI, naming the file. Bump MAQUETTE_ABI_VERSION whenever operator.h, tile.h, grid.h or
// store.h change in a way that breaks binary compatibility.
#pragma once

#include <cstdint>

#include "runtime/operator.h"

// 2: operators get the run's store (CellContext::store, StepContext for finish() and regions).
// 3: outputs finer than the inputs (OperatorSpec::refinable, CellContext::refine).
// 4: OperatorSpec::writes_all_samples; Tile's samples in a default-initializing vector.
// 5: OperatorSpec::fills_footprint.
// 6: OutputSpec::codec.
// 7: features ports (InputSpec::kind, reach_m; CellData::features, Mosaic::features) and content
//    output ports (OutputSpec::kind).
// 8: content outputs written (CellContent in CellData::content and Mosaic::content,
//    CellContext::owns).
// 9: the layers the raster ports read (CellContext::input_layer, StepContext::input_layer: a
//    DEM's vertical datum); region operators across rHEALPix face seams
//    (OperatorSpec::spans_faces, a Mosaic unfolded around one face); refinable region steps.
// 10: OperatorSpec::max_refine.
// 11: InputSpec::semantics and channels (the layers a raster port takes).
#define MAQUETTE_ABI_VERSION 12u
#define MAQUETTE_MODULE_ENTRY "maquette_module_info"

extern "C" {

struct MaquetteOperatorEntry {
  const char* name;  // "<module>.<verb>"
  maquette::OperatorFactory create;
};

struct MaquetteModuleInfo {
  uint32_t abi_version;  // MAQUETTE_ABI_VERSION the module was built with
  const char* name;      // "terrain"
  const char* version;   // "1.0.0"
  const char* description;
  const MaquetteOperatorEntry* operators;
  uint32_t operator_count;
};

}  // extern "C"

// In a module's one source file that lists its operators:
//   MAQUETTE_MODULE("terrain", "1.0.0", "Terrain derivatives",
//                   {"terrain.derive", &make_derive}, {"terrain.fill_voids", &make_fill})
#define MAQUETTE_MODULE(NAME, VERSION, DESCRIPTION, ...)                                \
  extern "C" __attribute__((visibility("default"))) const MaquetteModuleInfo*           \
  maquette_module_info() {                                                              \
    static const MaquetteOperatorEntry entries[] = {__VA_ARGS__};                       \
    static const MaquetteModuleInfo info = {                                            \
        MAQUETTE_ABI_VERSION, NAME,    VERSION,                                         \
        DESCRIPTION,          entries, uint32_t(sizeof(entries) / sizeof(entries[0]))}; \
    return &info;                                                                       \
  }
