// The Zion tests' first steps: NLCD land cover ("landcover") and SRTM heights ("dem") from
// `data` (../shared/data) ingested at level 10.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace maquette::synthesis {

inline nlohmann::json zion_ingest_steps(const std::string& data) {
  const auto ingest = [&](const std::string& file, const std::string& as) {
    return nlohmann::json{
        {"op", "ingest"},
        {"outputs", {{"layer", as}}},
        {"params", {{"sources", {data + "/zion/" + file}}, {"as", as}, {"level", 10}}}};
  };
  return nlohmann::json::array({ingest("nlcd.tif", "landcover"), ingest("srtm.tif", "dem")});
}

}  // namespace maquette::synthesis
