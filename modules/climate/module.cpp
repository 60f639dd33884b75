#include "operators.h"
#include "runtime/module_abi.h"

MAQUETTE_MODULE("climate", "1.0.0",
                "Climate layers from stations and terrain: regionalized temperature and "
                "precipitation, potential solar radiation, orographic precipitation",
                {"climate.fit_stations", &maquette::climate::make_fit_stations},
                {"climate.regionalize", &maquette::climate::make_regionalize},
                {"climate.solar", &maquette::climate::make_solar},
                {"climate.orographic", &maquette::climate::make_orographic})
