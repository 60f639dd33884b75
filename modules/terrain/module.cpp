#include "operators.h"
#include "runtime/module_abi.h"

MAQUETTE_MODULE("terrain", "1.0.0", "Synthetic terrain, terrain derivatives and DEM void filling",
                {"terrain.synthesize", &maquette::terrain::make_synthesize},
                {"terrain.derive", &maquette::terrain::make_derive},
                {"terrain.fill_voids", &maquette::terrain::make_fill_voids})
