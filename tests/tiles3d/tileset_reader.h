// Reads a 3D Tiles export the way a viewer does: tileset.json, the external tilesets and every
// GLB content (Draco decoded, tests/tiles3d/glb_reader.h), checking on the way that every tile's
// bounding region is a valid region inside its parent's and holds its content.
#pragma once

#include <array>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "glb_reader.h"

namespace maquette::test {

using Pos = std::array<double, 3>;  // the export's frame (glTF axes)

struct Export {
  std::string dir;
  nlohmann::json tileset;
  std::map<std::string, Glb> glbs;  // by content uri, relative to dir
};

// Reads OUTDIR/tileset.json and everything it leads to; every check is a GoogleTest failure.
Export read_export(const std::string& dir);

// Lon, lat (degrees) and height above the ellipsoid (m) of a decoded vertex, through the root
// transform (glTF y-up -> ENU -> ECEF), by GeographicLib.
std::array<double, 3> geodetic(const std::vector<double>& transform, const Pos& p);

// The EXT_mesh_gpu_instancing attributes of the GLB's first node, if any.
std::optional<nlohmann::json> instancing(const Glb& glb);

// Whether the Khronos glTF validator (tests/tiles3d/node) finds no error in any GLB under `dir`
// (and at least one GLB); nullopt when it is not installed.
std::optional<bool> gltf_validator_passes(const std::string& dir);

}  // namespace maquette::test
