#include "operators.h"
#include "runtime/module_abi.h"

MAQUETTE_MODULE("deform", "0.1.0",
                "Terrain deformation from feature strokes (paper 002 §3): rivers, roads, cliffs, "
                "ridges cut into the DEM by least squares; bodies of water in closed strokes (§4)",
                {"deform.features", &maquette::deform::make_features},
                {"deform.water", &maquette::deform::make_water},
                {"deform.water_bodies", &maquette::deform::make_water_bodies})
