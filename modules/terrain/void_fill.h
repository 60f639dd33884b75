// Void filling by a discrete PDE solved per void, with the samples around the void as boundary
// conditions (see README.md): Laplace (membrane, harmonic) or biharmonic (thin plate).
#pragma once

#include "core/tile.h"

namespace maquette::terrain {

enum class FillMethod { Laplace, Biharmonic };

struct FillOptions {
  FillMethod method = FillMethod::Biharmonic;
  int max_void_px = 63;  // larger voids, and voids reaching the window's edge, stay NaN
};

// `dem` (one channel, halo included) with the voids that reach the tile's interior filled;
// every other sample is copied unchanged. Each void is solved from `dem` alone (never from
// another void's fill), in an order of unknowns fixed by the samples' relative positions, so a
// void gives the same bits in every window that holds it with the same orientation.
Tile<float> fill_voids(const Tile<float>& dem, const FillOptions& options);

}  // namespace maquette::terrain
