#include "operators.h"
#include "runtime/module_abi.h"

MAQUETTE_MODULE("structures", "0.1.0",
                "3D structures of a Digital Earth (paper 002 §5, §7): buildings from footprints, "
                "vegetation in closed strokes, models placed by strokes",
                {"structures.buildings", &maquette::structures::make_buildings},
                {"structures.vegetation", &maquette::structures::make_vegetation},
                {"structures.vegetation_spacing", &maquette::structures::make_vegetation_spacing},
                {"structures.place", &maquette::structures::make_place},
                {"structures.bridge", &maquette::structures::make_bridge})
