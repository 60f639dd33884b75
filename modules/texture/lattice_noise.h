// The noise of one layer over the pixels of a tile, cached on a global lattice (the "cached
// procedural textures" of paper 001): each octave is evaluated exactly on every S-th global face
// pixel (the octaves of the same S summed on one lattice) and interpolated by Catmull-Rom splines
// (bicubic, in float) in between, S the largest power of two <= 8 that samples the octave's
// wavelength often enough for its error, weighted by its share of the amplitude, to stay under
// 0.02 (e.g. 5.7, 4 and 2.8 samples per wavelength for 3 octaves of persistence 0.5). The
// lattices of S >= 2 are then summed on the finest of them: the coarser ones interpolated at its
// nodes, so a pixel interpolates one lattice (two if some octave needs S = 1, evaluated at every
// pixel). Within 0.06 of exact evaluation (measured: lattice_noise_test.cpp).
// Since the lattices are aligned to global face pixel coordinates, every tile computes the same
// value for a pixel, and faces join (a face is a multiple of 8 pixels wide). Octaves shorter than
// 2 pixels contribute their mean, 0 (anti-aliasing), but keep their share of the normalisation.
// Lattice nodes are evaluated lazily, once, when a row needs them (the missing ones of a node row
// in batches: NoiseField::octave at several points), so layers that cover little of a tile cost
// little.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "evaluated_spans.h"
#include "field.h"
#include "noise.h"

namespace maquette::texture {

inline constexpr int kNoiseLatticeReach = 24;  // pixels beyond a pixel its lattice nodes lie

// Where the pixels of a tile's planes lie: plane pixel (c, r), -ring <= c, r < size + ring, is
// global face pixel (col0 + c, row0 + r), and its position is position->at(c, r) (which covers
// ring + kNoiseLatticeReach pixels around the planes when pixel_m > 0).
struct NoiseGeometry {
  int size = 0, ring = 0;
  int64_t col0 = 0, row0 = 0;
  double pixel_m = 0;  // 0: every octave evaluated exactly at every pixel
  const PixelPositions* position = nullptr;
};

class LatticeNoise {
 public:
  LatticeNoise(const NoiseField& field, const NoiseGeometry& geometry);

  // The noise of plane pixels c0 .. c1 (inclusive) of plane row r, into out[0 .. c1 - c0].
  void row(int r, int c0, int c1, float* out);

 private:
  // Spacing <= 8 pixels; nodes up to 3 x 8 pixels away (those of a coarser lattice, interpolated
  // at the finest lattice's outermost nodes).
  static constexpr int kMaxNoiseShift = 3;
  static_assert(3 << kMaxNoiseShift == kNoiseLatticeReach);

  // The octaves sharing a spacing, their amplitude-weighted sum cached on one lattice.
  struct Lattice {
    std::vector<int> octaves;
    int shift = 0;                         // spacing 2^shift pixels
    int64_t node_col0 = 0, node_row0 = 0;  // global node coordinates of nodes[0]
    int cols = 0, rows = 0;
    // Allocated uninitialised, evaluated where first needed: the nodes a layer never reaches
    // cost nothing.
    std::unique_ptr<float[]> nodes;
    std::vector<EvaluatedSpans> evaluated;  // per node row
    std::vector<float> weights;             // 4 per offset in 0 .. spacing - 1
  };

  static constexpr int kBatch = 64;  // points whose noise is evaluated together (noise.h)

  // The weighted sum of the lattice's octaves at n <= kBatch positions.
  void sum(const Lattice& l, Coordinates position, int n, float* out) const;
  // Node row j, its nodes i0 .. i1 evaluated (those of the finest lattice with the coarser
  // lattices interpolated at them added).
  const float* node_row(Lattice& l, int j, int i0, int i1);
  // Nodes i0 .. i1 of node row j into row.
  void evaluate_nodes(Lattice& l, int j, int i0, int i1, float* row);
  // Adds the lattice interpolated at plane pixels c0, c0 + step, .. <= c1 of plane row r to
  // out[0], out[1], ..; step is 1 or a spacing finer than the lattice's, c0 a multiple of it.
  void add_interpolated(Lattice& l, int r, int c0, int c1, int step, float* out);

  const NoiseField& field_;
  NoiseGeometry g_;
  // By increasing spacing. Those before `merged_` make the pixels' values: the one of spacing 1
  // (if any, evaluated at every pixel) and the finest of spacing >= 2, interpolated; those from
  // `merged_` on are interpolated at the nodes of the finest instead (node_row).
  std::vector<Lattice> lattices_;
  size_t merged_ = 0;
  std::vector<float> sum_, vertical_, horizontal_, coarser_;
};

}  // namespace maquette::texture
