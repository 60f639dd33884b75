// Blue noise over a region (Poisson disk sampling: every pair of points at least `min_distance`
// apart) decided by a rule of global position, so that any window (a cell, a tile, a rank) asking
// for a part of the plane gets exactly the points the whole would have there.
//
// The plane is cut into a global lattice of square buckets of side r = min_distance, bucket
// (i, j) covering [i r, (i + 1) r) x [j r, (j + 1) r). Each bucket throws kPoissonTries darts in
// turn at positions hashed from (seed, i, j, dart) (splitmix64); a dart is kept when no point kept
// in the 3 x 3 buckets around it is closer than r. The plane is sampled whole and the region cut
// out of it afterwards: sampled inside the region only, points along its edge would meet no
// competitor beyond it and pack more densely there (random sequential adsorption's wall effect:
// 18-36 % more plants than one per spacing^2 in a garden of a few dozen trees). Buckets go in 9
// phases by (i mod 3, j mod 3): buckets of one phase are 2 r apart and never compete, and a
// bucket at phase p depends only on the buckets of earlier phases next to it (parallel Poisson
// disk sampling by phase groups, Wei 2008). A window is thus sampled exactly by running phase p
// over the window grown by 8 - p buckets.
#pragma once

#include <cstdint>
#include <vector>

#include "core/grid.h"
#include "core/polygon_set.h"

namespace maquette::structures {

// Darts per bucket: more fill the plane more densely, up to saturation (~0.70 / r^2, random
// sequential adsorption).
inline constexpr int kPoissonTries = 6;
// Points per r^2 the sampling leaves on an unbounded region with kPoissonTries darts (measured
// on a 400 r x 400 r square: vegetation_poisson_test checks it), so that a spacing s (one plant
// per s x s) asks for r = s sqrt(kPoissonDensity).
inline constexpr double kPoissonDensity = 0.591;

// Points with x in [x_min, x_max) and y in [y_min, y_max).
struct PlaneWindow {
  double x_min = 0, y_min = 0, x_max = 0, y_max = 0;
};

// The sample's points in `window`, by bucket (rows of increasing j, then i) and dart order.
// `region` is planar: its LonLat are (x, y) in the same metres as the points. Preconditions:
// min_distance > 0, the window spans fewer than 2^31 buckets along each axis.
std::vector<PlanePoint> poisson_disk(const PolygonSet& region, double min_distance, uint64_t seed,
                                     const PlaneWindow& window);

// The minimum distance giving one point per spacing x spacing on average (kPoissonDensity).
double poisson_min_distance(double spacing);

}  // namespace maquette::structures
