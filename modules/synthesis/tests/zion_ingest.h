// The Zion tests' data (../shared/data) and first steps: NLCD land cover ("landcover") and SRTM
// heights ("dem") ingested at level 10.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace maquette::synthesis {

inline const std::string kShared = MAQUETTE_SHARED_DIR "/data";
inline const std::string kPainting = kShared + "/painting/bruegel_the_harvesters_1565.png";

inline nlohmann::json zion_ingest_steps() {
  const auto ingest = [](const std::string& file, const std::string& as) {
    return nlohmann::json{
        {"op", "ingest"},
        {"outputs", {{"layer", as}}},
        {"params", {{"sources", {kShared + "/zion/" + file}}, {"as", as}, {"level", 10}}}};
  };
  return nlohmann::json::array({ingest("nlcd.tif", "landcover"), ingest("srtm.tif", "dem")});
}

}  // namespace maquette::synthesis
