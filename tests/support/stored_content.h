// Reading a test store's content layers back as the tests check them: each cell's meshes decoded
// from their GLB (buildings, bridge decks, water), each instance on the globe (placed models,
// plants). Failures to decode throw maquette::Error.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "content/content.h"
#include "store/store.h"

namespace maquette::test {

// One cell's mesh content of a layer, in the content's east-north-up frame at `origin`.
struct StoredMeshes {
  EnuOrigin origin;
  MeshContent mesh;
};
std::vector<StoredMeshes> stored_meshes(const Store& store, const std::string& layer);

// A point of `origin`'s east-north-up frame (metres) on the globe: lon, lat (degrees), height
// above the ellipsoid (metres), by GeographicLib.
std::array<double, 3> enu_to_geodetic(const EnuOrigin& origin, double east, double north,
                                      double up);

// An instance of an instances layer: its position (the model's base) on the globe, its model's
// +x axis turned by its rotation and seen in the position's own east-north-up frame (a unit
// vector), its scale, prototype name and provenance.
struct StoredInstance {
  double lon = 0, lat = 0, height = 0;
  std::array<double, 3> x_axis{};
  std::array<float, 3> scale{};
  std::string prototype;
  ObjectProvenance provenance;
};
std::vector<StoredInstance> stored_instances(const Store& store, const std::string& layer);

}  // namespace maquette::test
