// Potential direct solar radiation: the sun's path over the sampled days (Spencer 1971
// declination and orbital eccentricity factor), the beam attenuated by the atmosphere (see
// Atmosphere), projected on an inclined surface and blocked by the horizon.
#pragma once

#include <span>
#include <vector>

namespace maquette::climate {

// How the atmosphere attenuates the beam: a transmissivity per vertical sea-level path raised to
// the relative air mass (Kasten & Young 1989), or the ESRA clear-sky beam of GRASS r.sun (Linke
// turbidity factor, Kasten's Rayleigh optical thickness, refraction-corrected solar altitude;
// Rigollier et al. 2000), both with the air mass scaled by the pressure at the ground.
enum class Atmosphere { Transmissivity, Linke };

struct SolarOptions {
  double solar_constant = 1367;  // W/m^2
  Atmosphere atmosphere = Atmosphere::Transmissivity;
  double transmissivity = 0.7;        // of a vertical path through the atmosphere at sea level
  double linke_turbidity = 3;         // Linke turbidity factor (air mass 2)
  int first_day = 1, last_day = 365;  // day of year, inclusive
  int day_step = 1;                   // every day_step-th day, weighted by the days it stands for
  double minutes = 15;                // time step within a day (midpoint rule), <= 60
};

// Sun positions of the sampled days and times, independent of latitude: the sun direction in a
// frame whose rotation by the latitude gives east-north-up (see SolarModel::radiation).
struct SunSample {
  double sin_decl = 0;      // sin(declination)
  double cos_decl_cos = 0;  // cos(declination) * cos(hour angle)
  double east = 0;          // -cos(declination) * sin(hour angle)
  double weight = 0;        // W/m^2 -> Wh/m^2: extraterrestrial normal irradiance * hours * days
};
std::vector<SunSample> sun_samples(const SolarOptions& options);

// Declination (radians) and eccentricity factor of a day of year (Spencer 1971).
double declination(int day);
double eccentricity(int day);

// The horizon of a pixel: its elevation angles (radians) along evenly spaced azimuths clockwise
// from north (the first one north), and the highest of them (a sun above it needs no look-up).
struct Horizon {
  std::span<const float> angles;
  double highest = 0;

  // Towards `azimuth` (radians clockwise from north), linear between directions.
  double towards(double azimuth) const;
};

// The sun's path over the period and the atmosphere's attenuation, made once per cell and shared
// by its pixels: the relative air mass is tabulated in the sine of the solar altitude.
class SolarModel {
 public:
  explicit SolarModel(const SolarOptions& options);

  // Sum over the samples of the direct beam on a surface with the given gradient (rise per
  // metre east and north) at latitude `lat_deg` and `elevation_m`, in Wh/m^2. The sun counts
  // when it is above the surface, above the horizon plane and (if given) above `horizon`.
  double radiation(double lat_deg, double grad_east, double grad_north, double elevation_m,
                   const Horizon* horizon = nullptr) const;

  // Marks in `used` (one flag per evenly spaced azimuth, the first north) the two directions
  // around the sun's azimuth at every sampled position above the horizon plane at `lat_deg`:
  // the horizon angles radiation() may read there.
  void mark_directions(double lat_deg, std::vector<char>& used) const;

  // Fraction of the extraterrestrial beam (normal to it) reaching the ground with the sun at
  // altitude sine `up` > 0, at pressure ratio `pressure` (1 at sea level).
  double beam(double up, double pressure) const;

 private:
  double air_mass(double up) const;  // sea-level relative air mass, from the table

  SolarOptions options_;
  std::vector<SunSample> sun_;
  std::vector<double> air_mass_;  // at up = i / (size - 1)
  double log_transmissivity_;     // once, not per sun position
};

}  // namespace maquette::climate
