#include "operators.h"
#include "runtime/module_abi.h"

MAQUETTE_MODULE("texture", "1.0.0",
                "Procedural surface-layer textures fitted to imagery (paper 001)",
                {"texture.procedural", &maquette::texture::make_procedural},
                {"texture.classify", &maquette::texture::make_classify},
                {"texture.cluster", &maquette::texture::make_cluster},
                {"texture.fit", &maquette::texture::make_fit},
                {"texture.assess", &maquette::texture::make_assess},
                {"texture.calibrate", &maquette::texture::make_calibrate},
                {"texture.landcover_share", &maquette::texture::make_landcover_share})
