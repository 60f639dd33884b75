// texture.calibrate: a multispectral scene's red, green and blue digital numbers as true-colour
// sRGB (scene_calibration.h), the imagery the other texture operators read: forest green and
// rock red-orange as on the ground, not as a linear stretch of each band shows them.
#include <string>

#include "core/error.h"
#include "operators.h"
#include "runtime/params_schema.h"
#include "scene_calibration.h"

namespace maquette::texture {
namespace {

constexpr const char* kBands[] = {"red", "green", "blue"};

json triple(const std::string& description) {
  return {{"type", "array"},
          {"items", {{"type", "number"}}},
          {"minItems", 3},
          {"maxItems", 3},
          {"description", description}};
}

OperatorSpec calibrate_spec() {
  OperatorSpec s;
  s.name = "texture.calibrate";
  s.description =
      "Red, green and blue digital numbers of a multispectral scene as true-colour sRGB: "
      "top-of-atmosphere reflectance, haze removed by dark-object subtraction";
  s.kind = OperatorKind::Cell;
  for (const char* band : kBands) {
    s.inputs.push_back({band, std::string(band) + " band, digital numbers", false});
    s.inputs.back().channels = {1};
  }
  s.outputs = {{"rgb", "true colour, sRGB 1..255", DType::U8, 3, Semantics::Continuous, "", 0.0}};
  s.params_schema = {
      {"type", "object"},
      {"additionalProperties", false},
      {"required", {"reflectance_mult", "reflectance_add", "sun_elevation"}},
      {"properties",
       {{"reflectance_mult",
         triple("per band (red, green, blue): reflectance x sin(sun elevation) per digital "
                "number (Landsat MTL REFLECTANCE_MULT_BAND_n)")},
        {"reflectance_add", triple("per band: its offset (REFLECTANCE_ADD_BAND_n)")},
        {"sun_elevation", number_param(0.1, 90, 90, "degrees (MTL SUN_ELEVATION)")},
        {"dark_object_dn",
         triple("per band: the dark object's digital number (e.g. the band's 0.01 percentile); "
                "its reflectance less dark_object_reflectance is subtracted as haze")},
        {"dark_object_reflectance",
         number_param(0, 0.2, 0.01, "a dark object's reflectance without the atmosphere")},
        {"white", number_param(0.01, 2, 0.3, "reflectance above the haze shown as 255")}}}};
  return s;
}

SceneCalibration calibration_of(const json& p) {
  SceneCalibration cal;
  cal.sun_elevation_deg = p.at("sun_elevation").get<double>();
  cal.white = p.at("white").get<double>();
  for (int b = 0; b < 3; ++b) {
    cal.bands[size_t(b)].mult = p.at("reflectance_mult")[size_t(b)].get<double>();
    cal.bands[size_t(b)].add = p.at("reflectance_add")[size_t(b)].get<double>();
    if (p.contains("dark_object_dn"))
      cal.set_haze_from_dark_object(b, p["dark_object_dn"][size_t(b)].get<double>(),
                                    p.at("dark_object_reflectance").get<double>());
  }
  return cal;
}

class CalibrateOp : public CellOperator {
 public:
  const OperatorSpec& spec() const override { return spec_; }

  void run(const CellContext& ctx, CellData& data) const override {
    const SceneCalibration cal = calibration_of(*ctx.params);
    Tile<float>& rgb = data.output("rgb");
    for (int b = 0; b < 3; ++b) {
      const Tile<float>& dn = data.input(kBands[b]);
      for (int r = 0; r < ctx.tile_size; ++r)
        for (int c = 0; c < ctx.tile_size; ++c) rgb.at(c, r, b) = cal.display(b, dn.at(c, r));
    }
  }

 private:
  OperatorSpec spec_ = calibrate_spec();
};

}  // namespace

std::unique_ptr<Operator> make_calibrate() { return std::make_unique<CalibrateOp>(); }

}  // namespace maquette::texture
