// Shared helpers of the grid tests.
#pragma once

#include <GeographicLib/Geodesic.hpp>
#include <cmath>
#include <random>
#include <vector>

#include "core/grid.h"

namespace maquette::test {

// Points uniform on the sphere, from a fixed seed.
inline std::vector<LonLat> random_points(size_t count, uint32_t seed = 42) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> lon(-180, 180), z(-1, 1);
  std::vector<LonLat> out(count);
  for (auto& p : out) p = {lon(rng), std::asin(z(rng)) * 180 / M_PI};
  return out;
}

inline double distance_m(LonLat a, LonLat b) {
  double s12 = 0;
  GeographicLib::Geodesic::WGS84().Inverse(a.lat, a.lon, b.lat, b.lon, s12);
  return s12;
}

// All cells of a level, in id order.
inline std::vector<CellId> all_cells(int level) {
  std::vector<CellId> out;
  for (int face = 0; face < CellId::kNumFaces; ++face) {
    const CellId f = CellId::FromFace(face);
    const CellId end = f.range_max().parent(level).next();
    for (CellId c = f.range_min().parent(level); c != end; c = c.next()) out.push_back(c);
  }
  return out;
}

}  // namespace maquette::test
