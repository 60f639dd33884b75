// The noise of one layer over the pixels of a tile, cached on a global lattice (the "cached
// procedural textures" of paper 001): each octave is evaluated exactly on every S-th global face
// pixel and interpolated by Catmull-Rom splines (bicubic) in between, S the largest power of two
// <= 8 that samples the octave's wavelength often enough for its error, weighted by its share of
// the amplitude, to stay under 0.02 (e.g. 5.7, 4 and 2.8 samples per wavelength for 3 octaves of
// persistence 0.5): within 0.06 of exact evaluation (measured: 0.02, lattice_noise_test.cpp).
// Since the lattice is aligned to global face pixel coordinates, every tile computes the same
// value for a pixel, and faces join (a face is a multiple of 8 pixels wide). Octaves shorter than
// 2 pixels contribute their mean, 0 (anti-aliasing), but keep their share of the normalisation.
// Lattice nodes are evaluated lazily, once, when a row needs them, so layers that cover little of
// a tile cost little.
#pragma once

#include <cstdint>
#include <vector>

#include "noise.h"

namespace maquette::texture {

inline constexpr int kNoiseLatticeReach = 16;  // pixels beyond a pixel its lattice nodes lie

// Where the pixels of a tile's planes lie: plane pixel (c, r), -ring <= c, r < size + ring, is
// global face pixel (col0 + c, row0 + r), and its position is
// position[(r + position_ring) * (size + 2 position_ring) + c + position_ring].
struct NoiseGeometry {
  int size = 0, ring = 0;
  int64_t col0 = 0, row0 = 0;
  double pixel_m = 0;  // 0: every octave evaluated exactly at every pixel
  const std::vector<Vec3d>* position = nullptr;
  int position_ring = 0;  // >= ring + kNoiseLatticeReach when pixel_m > 0
};

class LatticeNoise {
 public:
  LatticeNoise(const NoiseField& field, const NoiseGeometry& geometry);

  // The noise of plane pixels c0 .. c1 (inclusive) of plane row r, into out[0 .. c1 - c0].
  void row(int r, int c0, int c1, float* out);

 private:
  static constexpr int kMaxNoiseShift = 3;  // spacing <= 8 pixels: nodes up to 2 x 8 away
  static_assert(2 << kMaxNoiseShift == kNoiseLatticeReach);

  struct Octave {
    int index = 0, shift = 0;              // spacing 2^shift pixels
    int64_t node_col0 = 0, node_row0 = 0;  // global node coordinates of nodes[0]
    int cols = 0, rows = 0;
    std::vector<float> nodes;     // NaN until evaluated
    std::vector<double> weights;  // 4 per offset in 0 .. spacing - 1
  };

  const Vec3d& position(int64_t col, int64_t row) const;  // of plane pixel (col, row)
  float node(Octave& o, int i, int j);

  const NoiseField& field_;
  NoiseGeometry g_;
  std::vector<Octave> octaves_;  // evaluated ones
  std::vector<double> sum_, vertical_;
};

}  // namespace maquette::texture
