// Cast shadows of a height field under a sun at infinity: from each point, a march towards the
// sun (as GRASS r.sunmask's) in steps of one node spacing, the ray climbing tan(altitude) metres
// per metre; the point is in shadow when the terrain at a step is above the ray (by more than
// 1 cm, so that a plane the sun lights is not shadowed by rounding). The march ends at the grid's
// edge (nothing blocks the sun outside it) or once the ray is above the grid's highest node.
// Nodes lie on a regular square grid of a plane (x east, y north, metres; row 0 at the top, the
// north) with heights z up; the sun comes from `azimuth` (degrees clockwise from the grid's
// north) at `altitude` degrees above the plane. The terrain at a step is read bilinearly between
// the four nodes around it (nodes without data left out), or, as r.sunmask does, at the node
// nearest it: that reading shadows too much where a ray grazes a slope (any one node above the
// ray shadows), ~16 % more than the exact shadow of a cone (tests/render), and serves to compare
// with r.sunmask. No earth curvature: the caller gives heights in a frame where the rays are
// straight (e.g. an east-north-up frame). Each point is marched on its own: the same bits for any
// threads.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace maquette {

struct HeightGrid {
  int width = 0, height = 0;  // nodes
  double x0 = 0, y0 = 0;      // the position of node (0, 0): metres east, north
  double spacing = 1;         // metres between neighbouring nodes, > 0
  std::vector<float> z;       // row-major from the north, NaN for no data
};

enum class ShadowSampling { Bilinear, Nearest };

class CastShadow {
 public:
  // Keeps a reference to `grid`. Preconditions: grid.z.size() == width * height, spacing > 0,
  // altitude in (0, 90).
  CastShadow(const HeightGrid& grid, double azimuth_deg, double altitude_deg,
             ShadowSampling sampling = ShadowSampling::Bilinear);

  // Whether the point (x, y, z) (metres, the grid's frame) lies in the terrain's shadow.
  bool shadowed(double x, double y, double z) const;

  // 1 on the grid's nodes in shadow, 0 elsewhere (0 on nodes without data), row-major.
  std::vector<uint8_t> node_mask() const;

 private:
  // The terrain at fractional (col, row) as `sampling_` reads it; NaN for none.
  double height(double col, double row) const;

  const HeightGrid& grid_;
  ShadowSampling sampling_;
  double dcol_, drow_;  // one step (a node spacing) towards the sun, in columns and rows
  double rise_;         // metres the ray climbs per step
  double highest_;      // the grid's highest node: no ray above it is blocked
};

}  // namespace maquette
