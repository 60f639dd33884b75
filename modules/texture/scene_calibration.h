// A multispectral scene's digital numbers as true colour (texture.calibrate): per band, top-of-
// atmosphere reflectance from the scene's metadata (the linear rescaling of Landsat's MTL file,
// REFLECTANCE_MULT_BAND_n and REFLECTANCE_ADD_BAND_n, divided by the sine of SUN_ELEVATION), the
// haze removed by dark-object subtraction (Chavez 1988; the dark object taken as 1 % reflectance,
// Chavez 1996's DOS1), shown as sRGB with reflectance `white` as 255. Reflectance is linear in
// light, so the sRGB encoding keeps dark forest green instead of crushing it to black as a
// linear stretch of the digital numbers does.
#pragma once

#include <array>

namespace maquette::texture {

struct BandCalibration {
  double mult = 1, add = 0;  // reflectance x sin(sun elevation) = mult DN + add
  double haze = 0;           // reflectance subtracted (path radiance)
};

struct SceneCalibration {
  std::array<BandCalibration, 3> bands;  // red, green, blue
  double sun_elevation_deg = 90;         // (0, 90]
  double white = 0.3;                    // reflectance above the haze shown as 255; > 0

  // Top-of-atmosphere reflectance of digital number `dn` of band `band` (0..2), haze included.
  double reflectance(int band, double dn) const;
  // Sets band `band`'s haze from its dark object's digital number: the dark object's reflectance
  // less `dark_reflectance` (what a dark object reflects without the atmosphere).
  void set_haze_from_dark_object(int band, double dark_dn, double dark_reflectance);
  // The sRGB value of `dn` in band `band`, in [1, 255] (0 is the imagery's nodata); NaN stays NaN.
  float display(int band, float dn) const;
};

}  // namespace maquette::texture
