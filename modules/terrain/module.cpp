#include "operators.h"
#include "runtime/module_abi.h"

MAQUETTE_MODULE("terrain", "1.0.0", "Synthetic terrain and terrain derivatives",
                {"terrain.synthesize", &maquette::terrain::make_synthesize},
                {"terrain.derive", &maquette::terrain::make_derive})
