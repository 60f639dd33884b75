#include "image/colour_ramp.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.h"

namespace maquette {
namespace {

struct Stop {
  double t;
  std::array<double, 3> rgb;
};

// Hypsometric tints, lowland green to snow.
constexpr Stop kTerrain[] = {{0.00, {58, 112, 64}},   {0.20, {112, 158, 82}},
                             {0.40, {205, 196, 120}}, {0.60, {170, 120, 72}},
                             {0.80, {140, 110, 100}}, {1.00, {250, 250, 250}}};
// Atlas tints by height in metres; the sea is drawn from 0 m down.
constexpr Stop kHypsometric[] = {
    {-8000, {8, 40, 100}},   {-2000, {30, 90, 160}},  {-200, {90, 150, 205}},
    {0.0, {160, 200, 230}},  {0.001, {60, 130, 80}},  {200, {120, 170, 95}},
    {500, {185, 205, 120}},  {1000, {230, 215, 145}}, {1500, {210, 170, 105}},
    {2000, {180, 130, 80}},  {3000, {145, 100, 80}},  {4000, {165, 155, 150}},
    {5000, {230, 230, 230}}, {6500, {255, 255, 255}}};
// Flat white through yellow and red to dark purple for steep slopes.
constexpr Stop kSlope[] = {{0.00, {255, 255, 255}},
                           {0.25, {255, 230, 110}},
                           {0.50, {240, 130, 50}},
                           {0.75, {190, 40, 50}},
                           {1.00, {70, 10, 80}}};

// Matplotlib's viridis (CC0), every 15th of its 256 entries.
constexpr Stop kViridis[] = {
    {0 / 17.0, {68, 1, 84}},     {1 / 17.0, {72, 23, 105}},   {2 / 17.0, {71, 42, 122}},
    {3 / 17.0, {67, 61, 132}},   {4 / 17.0, {61, 78, 138}},   {5 / 17.0, {53, 94, 141}},
    {6 / 17.0, {46, 109, 142}},  {7 / 17.0, {41, 123, 142}},  {8 / 17.0, {35, 137, 142}},
    {9 / 17.0, {31, 151, 139}},  {10 / 17.0, {33, 165, 133}}, {11 / 17.0, {46, 179, 124}},
    {12 / 17.0, {70, 192, 111}}, {13 / 17.0, {101, 203, 94}}, {14 / 17.0, {137, 213, 72}},
    {15 / 17.0, {176, 221, 47}}, {16 / 17.0, {216, 226, 25}}, {17 / 17.0, {253, 231, 37}}};
// ColorBrewer's RdBu (11 classes) from blue to red, near-white in the middle.
constexpr Stop kDiverging[] = {
    {0.0, {5, 48, 97}},     {0.1, {33, 102, 172}},  {0.2, {67, 147, 195}},  {0.3, {146, 197, 222}},
    {0.4, {209, 229, 240}}, {0.5, {247, 247, 247}}, {0.6, {253, 219, 199}}, {0.7, {244, 165, 130}},
    {0.8, {214, 96, 77}},   {0.9, {178, 24, 43}},   {1.0, {103, 0, 31}}};

template <size_t N>
std::array<uint8_t, 3> interpolate(const Stop (&stops)[N], double t) {
  size_t i = 1;
  while (i < N - 1 && t > stops[i].t) ++i;
  const Stop& a = stops[i - 1];
  const Stop& b = stops[i];
  const double w = std::clamp((t - a.t) / (b.t - a.t), 0.0, 1.0);
  std::array<uint8_t, 3> out{};
  for (int k = 0; k < 3; ++k) out[k] = uint8_t(std::lround(a.rgb[k] + w * (b.rgb[k] - a.rgb[k])));
  return out;
}

}  // namespace

Ramp parse_ramp(std::string_view name) {
  if (name == "grey" || name == "gray") return Ramp::Grey;
  if (name == "viridis") return Ramp::Viridis;
  if (name == "diverging") return Ramp::Diverging;
  if (name == "terrain") return Ramp::Terrain;
  if (name == "slope") return Ramp::Slope;
  if (name == "hypsometric") return Ramp::Hypsometric;
  throw Error("unknown colour ramp '" + std::string(name) +
              "' (expected grey, viridis, diverging, terrain, slope or hypsometric)");
}

std::array<uint8_t, 3> ramp_colour(Ramp ramp, double t) {
  if (ramp == Ramp::Hypsometric) return interpolate(kHypsometric, std::isfinite(t) ? t : 0.0);
  t = std::isfinite(t) ? std::clamp(t, 0.0, 1.0) : 0.0;
  switch (ramp) {
    case Ramp::Viridis:
      return interpolate(kViridis, t);
    case Ramp::Diverging:
      return interpolate(kDiverging, t);
    case Ramp::Terrain:
      return interpolate(kTerrain, t);
    case Ramp::Slope:
      return interpolate(kSlope, t);
    case Ramp::Grey:
    case Ramp::Hypsometric:
      break;
  }
  const auto g = uint8_t(std::lround(255.0 * t));
  return {g, g, g};
}

}  // namespace maquette
