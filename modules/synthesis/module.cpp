#include "operators.h"
#include "runtime/module_abi.h"

MAQUETTE_MODULE("synthesis", "0.1.0",
                "Example-based texture transfer from hand-painted panoramas (paper 000)",
                {"synthesis.transfer", &maquette::synthesis::make_transfer},
                {"synthesis.assess", &maquette::synthesis::make_assess},
                {"synthesis.inpaint", &maquette::synthesis::make_inpaint},
                {"synthesis.clone", &maquette::synthesis::make_clone},
                {"synthesis.apply", &maquette::synthesis::make_apply})
