// The painting's masks from its guides (maquette-paint's "painting_guides": the float GeoTIFF
// `render fit --panorama` writes of the store under the painting's fitted camera, or `render
// panorama`'s, of the painting's size), so that an exemplar gets its masks without hand work
// (issue 19): each of "labels", "painting_altitude" and "painting_distance" that is "guides"
// made from its band exactly as the picture's guides are made (paint_panorama.h), so that the
// painting's and the picture's compare like for like.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace maquette::synthesis {

// The painting class of a pixel of a rendered picture: on the sky (its distance NaN)
// `sky_class`, else kUnknownLabel; on the terrain its land cover's class through the table
// (kUnknownLabel: NaN, or not in the table).
uint8_t picture_class(const std::map<int, uint8_t>& table, std::optional<uint8_t> sky_class,
                      float land_cover, float distance);

// The distance guide of a pixel of a rendered picture: distance_guide (paint_params.h), the sky
// (NaN) 1, far.
float picture_distance(float metres, const std::array<double, 2>& range);

// The painting's altitude guide of one pixel: altitude_guide (transfer_params.h), the sky (NaN)
// 1: the exemplar's guides are averaged down its pyramid, so they take a value everywhere (the
// picture's sky has none, so it matches any), and the sky is above the land ("rows" has it high
// too).
float painting_altitude(float metres, const std::array<double, 2>& range);

// The painting's masks from its guides; each empty when its field is not "guides".
struct GuidedMasks {
  std::vector<uint8_t> labels;  // picture_class; kUnknownLabel: never copied
  std::vector<float> altitude;  // painting_altitude through altitude_range
  std::vector<float> distance;  // picture_distance through distance_range
};

// The masks `fields` (the validated params, "painting_guides" given) asks of its guides file, for
// a painting of width x height pixels: its bands land_cover and distance for "labels" (through
// "landcover_classes" and "sky_class": the sky's pixels of class sky_class, or never copied
// without it; land cover the table does not name never copied), altitude for
// "painting_altitude" (through "altitude_range"), distance for "painting_distance" (through
// "distance_range"). Throws maquette::Error naming `where`.painting_guides and the file: not
// the painting's size (both sizes named), a band missing, unreadable.
GuidedMasks guided_masks(const nlohmann::json& fields, const std::string& where, int width,
                         int height);

// What of `fields` the guided masks are made with, for the exemplar's cache key: the class table
// and sky_class with "labels" "guides", altitude_range and distance_range with their guides;
// empty without "painting_guides".
nlohmann::json guided_masks_key(const nlohmann::json& fields);

// Whether `fields` (the params) makes `field` from its guides: "guides" with "painting_guides".
bool from_guides(const nlohmann::json& fields, const std::string& field);

}  // namespace maquette::synthesis
