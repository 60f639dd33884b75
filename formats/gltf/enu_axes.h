// Content's east-north-up axes and glTF's y-up axes: glTF (x, y, z) = (east, up, -north), as the
// exports write (gltf/local_frame.h). A rotation: triangles keep their winding; exact in float.
#pragma once

#include <vector>

namespace maquette {

// Appends the glTF axes of the ENU vector (x, y, z) at `enu`.
inline void append_gltf_axes(const float* enu, std::vector<float>& out) {
  out.insert(out.end(), {enu[0], enu[2], -enu[1]});
}

// Appends the ENU axes of the glTF vector (x, y, z) at `gltf`.
inline void append_enu_axes(const float* gltf, std::vector<float>& out) {
  out.insert(out.end(), {gltf[0], -gltf[2], gltf[1]});
}

}  // namespace maquette
