#include "painting_guides.h"

#include <cmath>
#include <utility>

#include "core/error.h"
#include "exemplar.h"
#include "paint_params.h"
#include "panorama_guides.h"
#include "transfer_params.h"

namespace maquette::synthesis {

uint8_t picture_class(const std::map<int, uint8_t>& table, std::optional<uint8_t> sky_class,
                      float land_cover, float distance) {
  if (std::isnan(distance)) return sky_class.value_or(kUnknownLabel);
  return painting_class(table, land_cover);
}

float picture_distance(float metres, const std::array<double, 2>& range) {
  return std::isnan(metres) ? 1.0f : distance_guide(metres, range);
}

float painting_altitude(float metres, const std::array<double, 2>& range) {
  return std::isnan(metres) ? 1.0f : altitude_guide(metres, range);
}

bool from_guides(const nlohmann::json& fields, const std::string& field) {
  return fields.contains("painting_guides") && fields.contains(field) &&
         fields.at(field) == "guides";
}

GuidedMasks guided_masks(const nlohmann::json& fields, const std::string& where, int width,
                         int height) {
  const bool labels = from_guides(fields, "labels"),
             altitude = from_guides(fields, "painting_altitude"),
             distance = from_guides(fields, "painting_distance");
  // Only the bands asked for are read: each is 4 bytes a painting pixel.
  const std::string hint = "not guides of a rendered panorama?";
  std::vector<GuideBand> wanted;
  if (labels) wanted.push_back({"land_cover", "render them with --land-cover"});
  if (altitude) wanted.push_back({"altitude", hint});
  if (labels || distance) wanted.push_back({"distance", hint});
  std::vector<std::vector<float>> bands;
  try {
    bands = read_guide_bands(fields.at("painting_guides").get<std::string>(), width, height,
                             "the painting " + fields.at("painting").get<std::string>(), wanted);
  } catch (const Error& e) {
    throw Error(where + ".painting_guides: " + e.what());
  }
  const auto band = [&](const std::string& name) -> const std::vector<float>& {
    size_t b = 0;
    while (wanted[b].name != name) ++b;
    return bands[b];
  };
  const size_t n = size_t(width) * size_t(height);
  GuidedMasks out;
  if (labels) {
    const auto table = class_table(fields.at("landcover_classes"), where);
    const std::optional<uint8_t> sky =
        fields.contains("sky_class") ? std::optional(uint8_t(fields.at("sky_class").get<int>()))
                                     : std::nullopt;
    const auto &cover = band("land_cover"), &metres = band("distance");
    out.labels.resize(n);
    for (size_t i = 0; i < n; ++i) out.labels[i] = picture_class(table, sky, cover[i], metres[i]);
  }
  if (altitude) {
    const auto range = range_param(fields, "altitude_range", where);
    const auto& metres = band("altitude");
    out.altitude.resize(n);
    for (size_t i = 0; i < n; ++i) out.altitude[i] = painting_altitude(metres[i], range);
  }
  if (distance) {
    const auto range = range_param(fields, "distance_range", where, true);
    const auto& metres = band("distance");
    out.distance.resize(n);
    for (size_t i = 0; i < n; ++i) out.distance[i] = picture_distance(metres[i], range);
  }
  return out;
}

nlohmann::json guided_masks_key(const nlohmann::json& fields) {
  const std::pair<const char*, std::vector<const char*>> uses[] = {
      {"labels", {"landcover_classes", "sky_class"}},
      {"painting_altitude", {"altitude_range"}},
      {"painting_distance", {"distance_range"}}};
  nlohmann::json key = nlohmann::json::object();
  for (const auto& [field, mapping] : uses)
    if (from_guides(fields, field))
      for (const char* m : mapping)
        if (fields.contains(m)) key[m] = fields.at(m);
  return key;
}

}  // namespace maquette::synthesis
