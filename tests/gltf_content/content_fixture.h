// Mesh content for the tests: a textured box, a UV sphere with smooth normals, images encoded by
// GDAL, and an order-free comparison of meshes (Draco reorders triangles and vertices).
#pragma once

#include <string>

#include "content/content.h"

namespace maquette::test {

// An image of w x h pixels, a colour gradient, encoded by GDAL's `driver` ("PNG", "JPEG").
std::string encoded_image(const std::string& driver, int w, int h);

// A box of size `size` (x, y, z) with its minimum corner at `corner` (ENU metres), 4 vertices
// per face with the face's normal and uvs in 0.13..0.87 (off Draco's grid), triangles
// counter-clockwise seen from outside.
MeshObject box(std::array<float, 3> corner, std::array<float, 3> size);
// A UV sphere of `radius` around `centre`: normals the directions from the centre, no uvs.
MeshObject sphere(std::array<float, 3> centre, float radius, int slices, int stacks);

// The largest differences between the triangles of `a` and of `b`, matched corner by corner
// (each triangle of `b` with the triangle of `a` whose corners are nearest, in any rotation of
// its corners, within 10 cm); triangle counts and unmatched triangles are GoogleTest failures.
struct MeshDifference {
  double position = 0;  // metres
  double normal = 0;    // radians
  double uv = 0;
};
MeshDifference compare_meshes(const MeshObject& a, const MeshObject& b);

}  // namespace maquette::test
