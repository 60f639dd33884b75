// Parallel controllable texture synthesis (Lefebvre & Hoppe 2005) guided as paper 000 asks: the
// output is a map from output pixels to exemplar pixels, built coarse to fine over the exemplar
// pyramid (exemplar_pyramid.h).
//
// At the coarsest level each pixel starts at a random allowed exemplar pixel of its target label.
// At each finer level the coordinates of the parent are doubled, offset by the child's position
// and jittered by a hash of (global pixel, level, seed); then kPasses correction passes, each in
// 2 x 2 sub-passes (pixels of one parity of global column and row at a time, in the order
// (0,0) (1,1) (0,1) (1,0)), replace every pixel by the candidate of least cost
//   C = D_color + w_label D_label + w_altitude D_altitude + w_distance D_distance
//       + w_light D_light + w_repetition D_repetition + w_spread D_spread
// among its k-coherence candidates (for each 3 x 3 neighbour q = p + d, the exemplar pixel
// S(q) - d and its k most similar patches) and two random pixels of its target label, the
// candidates other than the S(q) - d at a cost (1 + coherence) times theirs plus w_usage D_usage
// (the coherent candidates carry no D_usage: a copy under way is not broken for its source's
// over-use). With a depth guide
// (a panorama's distance from the eye), a neighbour q across a depth break from p (one of the
// two sky, or farther than depth_break times the other: the renderer's silhouettes) makes its
// S(q) - d no candidate at all (paper 000: silhouettes as coherence breaks, so that no patch is
// planted across ridges at different depths; a pixel with every candidate forbidden keeps its
// source), and is not matched either: in D_color it takes each candidate's own colours (no
// difference), in D_label it counts as unknown (so the sky beside a skyline is not drawn to the
// painting's sky beside its land):
//  - D_color: squared distance between the PCA features of the output's neighbourhood (the
//    exemplar colours at S(p + d)) and of the candidate's;
//  - D_label: the fraction of the 3 x 3 neighbourhood whose target label differs from the
//    candidate's exemplar labels (unknown target labels match anything);
//  - D_altitude: the squared difference of target and exemplar altitude (when both have one);
//  - D_distance: the same of the target's and exemplar's distance from the viewer;
//  - D_light: the same of the target's and exemplar's light (StyLit's lighting guide, Fiser et
//    al. 2016: so that the painting's dark strokes go where the target is in shade; each side's
//    light a quantile within its class, so the two compare whatever the palette and the sun:
//    light_guide.h). D_distance and D_light are added only when their weight is positive: with
//    w_distance and w_light 0 the cost is what it was without them, bit for bit;
//  - D_repetition: the fraction of kRepetitionOffsets pixels at Chebyshev distance 2 to
//    kRepetitionRadius whose coordinates at the start of the pass lie within one pixel of the
//    candidate: the same source reused nearby, not coherently (a coherent neighbour at offset o
//    sits at candidate + o). Counting in the previous pass's state, in a fixed window, keeps the
//    penalty a function of global pixel coordinates, independent of the order of pixels, of
//    threads and of the window computed: the usage is local, not a global count.
//  - D_usage: at the levels coarser than the finest, the exemplar's measured over-use of the
//    candidate (ExemplarLevel::usage, exemplar_usage.h: Kaspar et al. 2015's occurrence map,
//    measured once on the exemplar itself, so global without depending on the window); 0 when
//    not measured; at the finest level the copy's coherence decides. Added to the candidates
//    other than the S(q) - d only (above).
//  - D_spread: a preference of each block of 16 x 16 pixels of a level (global pixel
//    coordinates >> kSpreadBlockShift) for each region of 8 x 8 exemplar pixels, uniform in
//    [0, 1) from a hash of both (and the level and seed): blocks prefer different copies among
//    equally good ones, so the most used pixels are used less, at no cost in coherence within a
//    block. A region outside the central spread_typical of its class by lightness
//    (spread_regions.h) is preferred by none: 1.
// A candidate whose exemplar label is the pixel's target label beats any that is not (the cost
// decides among those of one kind): the two random candidates of the label offer one (unless
// forbidden) whenever the level's exemplar has that label, so such an output pixel ends on a
// pixel of its label. Excluded exemplar pixels are never candidates, and every output pixel
// (every kept one, given synthesize()'s `wanted`) ends on an allowed pixel.
//
// Then, with patch_passes > 0, the finest level's patch passes (patch_pass.h): each pixel takes,
// among the copies under way around it (S(p + d) - d, d within 2), the one whose 5 x 5 exemplar
// patch is nearest the output's (the coherence synthesis.assess measures; ebsynth's search
// without its averaging), with patch_search places drawn around its source and patch_edges from
// the exemplar's own edges between the two classes (class_edges.h) where the target's classes
// meet, and patch_balance weighing them by their colour excess as the vote does (a pixel
// of one of line_classes thinner than its window keeps its source); in the same 2 x 2
// sub-passes.
//
// Last, the finest level's vote (vote.h; ebsynth's coherence comes from votes of the overlapping
// patches, here the vote picks a source, it does not average colours): each pixel takes, among
// the sources S(p + d) - d the patches of side 2 vote_radius + 1 around it propose (of its
// target label), the one whose colour is nearest their mean (with vote_balance, weighed by how
// much the synthesis over-shows its colour, measured on the exemplar: vote.h); a pixel with a
// depth break within the window keeps its source. So the output is still a copy: every pixel's
// colour is its source's, and the sources returned are the pixels whose colours the output shows.
//
// So each output pixel is a function of its global pixel coordinates, the guides within
// synthesis_halo() pixels of it, the exemplar and the parameters: a window computed with its halo
// equals the whole image cropped to it, bit for bit. With TargetGuides::col_period P, columns c
// and c + P are one place: every hash reads the column modulo the level's period (P >> level),
// so a window at c + P equals the window at c given the same guides (across the antimeridian).
//
// The coordinates are a plane's: those of one grid face, or the faces laid unturned in one plane
// (core/face_plane.h, as synthesis.transfer does). The output is seamless where the guides the
// caller gives around a window are the plane's own pixels at those coordinates: the store's halo
// (core/halo.h) lays a neighbour face as it meets the cell's face, so across the edges between
// equatorial faces, the antimeridian, and each polar face's edge with the equatorial face it is
// laid against. Across a polar face's other three edges the neighbour is turned in the cell's
// halo: synthesized in this plane the two sides would meet in a straight seam; synthesis.transfer
// joins there the neighbour's chart to the plane's synthesis by a minimum-error cut
// (turned_edges.h), still a function of global pixel coordinates and guides.
#pragma once

#include <bitset>
#include <cstdint>
#include <span>
#include <vector>

#include "exemplar_pyramid.h"
#include "spread_regions.h"

namespace maquette::synthesis {

inline constexpr int kLevels = 4;            // pyramid levels synthesized (the exemplar's)
inline constexpr int kPasses = 2;            // correction passes per level
inline constexpr int kSubPasses = 4;         // 2 x 2
inline constexpr int kRepetitionRadius = 3;  // of the reuse penalty's window, at each level
inline constexpr int kVoteRadius = 2;        // the widest vote (its patches' radius)
inline constexpr int kMaxPatchPasses = 3;    // the finest level's patch passes (patch_pass.h)
inline constexpr int kSpreadBlockShift = 4;  // D_spread's blocks: 16 x 16 pixels of a level

struct SynthesisParams {
  double w_label = 2.0;
  double w_altitude = 1.0;
  double w_distance = 0.0;
  double w_light = 0.0;
  double w_repetition = 0.3;
  double w_usage = 0.05;
  double w_spread = 0.15;
  // The central share of each class's exemplar regions D_spread may prefer (spread_regions.h).
  double spread_typical = 1.0;
  // Ashikhmin's coherence: the cost of a candidate that is not a neighbour's source shifted
  // (a similar patch, a random pixel) is multiplied by 1 + coherence.
  double coherence = 0.5;
  int patch_passes = 0;      // 0 .. kMaxPatchPasses: the finest level's (patch_pass.h)
  double patch_balance = 0;  // their histogram balance (patch_pass.h), an exponent; 0: none
  int patch_search = 0;      // their places drawn per pixel where classes meet (patch_pass.h)
  int patch_edges = 0;       // and drawn there from the exemplar's class edges (patch_pass.h)
  // Target labels of lines (roads, tracks, streams): where one is thinner than the passes'
  // window its pixels keep their source through them (patch_pass.h).
  std::bitset<256> line_classes{};
  int vote_radius = 1;        // 0 .. kVoteRadius; 0: no vote
  double vote_balance = 0;    // the vote's histogram balance (vote.h), an exponent; 0: none
  int jitter = 1;             // amplitude of the upsampling jitter, pixels at each level (0: none)
  double depth_break = 1.05;  // a depth ratio that breaks coherence (with a depth guide)
  uint64_t seed = 0;
};

// A rectangle of global pixel coordinates at some level: [col0, col0 + width) x [row0, ...).
struct PixelRect {
  int64_t col0 = 0, row0 = 0;
  int64_t width = 0, height = 0;

  bool contains(const PixelRect& r) const {
    return r.col0 >= col0 && r.row0 >= row0 && r.col0 + r.width <= col0 + width &&
           r.row0 + r.height <= row0 + height;
  }
};

// The target's guides on a raster of global pixels `1 << shift` times coarser than the output's
// (a step's refine): output pixel (c, r) reads guide sample ((c >> shift) - rect.col0,
// (r >> shift) - rect.row0). Labels are painting classes (kUnknownLabel: any); altitude,
// distance and light in [0, 1], NaN or empty for none; depth in metres from the eye (infinity:
// the sky), empty for no coherence breaks.
struct TargetGuides {
  PixelRect rect;
  int shift = 0;
  std::vector<uint8_t> labels;  // rect.width x rect.height, row-major
  std::vector<float> altitude;  // the same, or empty
  std::vector<float> distance;  // the same, or empty
  std::vector<float> light;     // the same, or empty
  std::vector<float> depth;     // the same, or empty
  // Output columns c and c + col_period are one place (0: none): a multiple of 2^kLevels, where
  // the caller gives the same guides.
  int64_t col_period = 0;
};

// Pixels of halo the guides need around an output window, at the output's resolution.
int synthesis_halo();
// The guide pixels (guides.shift = shift) covering output window `out` grown by synthesis_halo():
// the guides' rect synthesize() needs for `out`.
PixelRect guide_rect(const PixelRect& out, int shift);

// For each pixel of `out` (output resolution), row-major, the index y * width + x of its
// exemplar pixel at the pyramid's finest level. `wanted` (row-major over `out`, or empty: every
// pixel) names the pixels whose result the caller keeps: the corrections and patch passes
// compute only what those read (synthesis_plan.h), so their results are the same bits as without
// it, and the others' are exemplar pixels of no meaning, excluded ones perhaps (where the land
// cover has no data, say). Preconditions:
// guides.rect covers `out` grown by synthesis_halo() pixels (>> guides.shift); the pyramid has
// kLevels levels. Throws maquette::Error when wanted is neither empty nor of out's size, when
// the guides do not cover it, params.vote_radius is outside 0 .. kVoteRadius,
// params.patch_passes outside 0 .. kMaxPatchPasses, params.patch_search outside 0 ..
// kMaxPatchSearch, params.patch_edges outside 0 .. kMaxPatchEdges (patch_pass.h) or
// guides.col_period is not a multiple of 2^kLevels.
std::vector<int32_t> synthesize(const ExemplarPyramid& pyramid, const TargetGuides& guides,
                                const SynthesisParams& params, const PixelRect& out,
                                std::span<const uint8_t> wanted = {});

}  // namespace maquette::synthesis
