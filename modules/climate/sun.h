// Potential direct solar radiation: the sun's path over the sampled days (Spencer 1971
// declination and orbital eccentricity factor), the beam attenuated by the atmosphere
// (transmissivity ^ relative air mass, Kasten & Young 1989, scaled by the pressure at the
// ground's elevation), projected on an inclined surface and blocked by the horizon.
#pragma once

#include <functional>
#include <vector>

namespace maquette::climate {

struct SolarOptions {
  double solar_constant = 1367;       // W/m^2
  double transmissivity = 0.7;        // of a vertical path through the atmosphere at sea level
  int first_day = 1, last_day = 365;  // day of year, inclusive
  int day_step = 1;                   // every day_step-th day, weighted by the days it stands for
  double minutes = 15;                // time step within a day (midpoint rule), <= 60
};

// Sun positions of the sampled days and times, independent of latitude: the sun direction in a
// frame whose rotation by the latitude gives east-north-up (see potential_radiation).
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

// The horizon of a pixel: its elevation angle (radians) towards an azimuth (radians clockwise
// from north), and the highest of those angles (a sun above it needs no look-up).
struct Horizon {
  std::function<double(double azimuth)> towards;
  double highest = 0;
};

// Sum over the samples of the direct beam on a surface with the given gradient (rise per metre
// east and north) at latitude `lat_deg` and `elevation_m`, in Wh/m^2. The sun counts when it is
// above the surface, above the horizon plane and (if given) above `horizon`.
double potential_radiation(const std::vector<SunSample>& sun, const SolarOptions& options,
                           double lat_deg, double grad_east, double grad_north, double elevation_m,
                           const Horizon* horizon = nullptr);

}  // namespace maquette::climate
