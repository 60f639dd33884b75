#include "synthesis.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <limits>
#include <utility>

#include "core/error.h"
#include "least_cost.h"
#include "patch_pass.h"
#include "pixel_hash.h"
#include "synthesis_plan.h"
#include "vote.h"

namespace maquette::synthesis {
namespace {

// Exemplar pixel indices over a rectangle of global pixels of one level.
struct State {
  PixelRect rect;
  std::vector<int32_t> src;

  explicit State(const PixelRect& r) : rect(r), src(size_t(r.width) * size_t(r.height)) {}
  int32_t& at(int64_t col, int64_t row) { return src[offset(col, row)]; }
  int32_t at(int64_t col, int64_t row) const { return src[offset(col, row)]; }

 private:
  size_t offset(int64_t col, int64_t row) const {
    assert(col >= rect.col0 && col < rect.col0 + rect.width && row >= rect.row0 &&
           row < rect.row0 + rect.height);
    return size_t(row - rect.row0) * size_t(rect.width) + size_t(col - rect.col0);
  }
};

// The guides sampled at one level's pixels: each level-l pixel reads the output pixel at the
// centre of its 2^l x 2^l block.
struct LevelGuides {
  PixelRect rect;
  std::vector<uint8_t> labels;
  std::vector<float> altitude, distance, depth, light;  // empty: none

  size_t index(int64_t col, int64_t row) const {
    return size_t(row - rect.row0) * size_t(rect.width) + size_t(col - rect.col0);
  }
};

LevelGuides level_guides(const TargetGuides& g, int level, const PixelRect& rect) {
  LevelGuides out{rect, std::vector<uint8_t>(size_t(rect.width) * size_t(rect.height)), {}, {}, {},
                  {}};
  // The guides given, each sampled as the labels are.
  std::vector<std::pair<const std::vector<float>*, std::vector<float>*>> scalars;
  for (const auto& [from, to] :
       {std::pair{&g.altitude, &out.altitude}, std::pair{&g.distance, &out.distance},
        std::pair{&g.depth, &out.depth}, std::pair{&g.light, &out.light}})
    if (!from->empty()) {
      to->resize(out.labels.size());
      scalars.emplace_back(from, to);
    }
  const int64_t centre = level > 0 ? int64_t(1) << (level - 1) : 0;
  for (int64_t row = rect.row0; row < rect.row0 + rect.height; ++row)
    for (int64_t col = rect.col0; col < rect.col0 + rect.width; ++col) {
      const int64_t gc = (((col << level) + centre) >> g.shift) - g.rect.col0;
      const int64_t gr = (((row << level) + centre) >> g.shift) - g.rect.row0;
      if (gc < 0 || gr < 0 || gc >= g.rect.width || gr >= g.rect.height)
        throw Error("synthesis: the guides (" + std::to_string(g.rect.width) + " x " +
                    std::to_string(g.rect.height) + " at " + std::to_string(g.rect.col0) + ", " +
                    std::to_string(g.rect.row0) + ") do not cover the window and its halo");
      const size_t gi = size_t(gr) * size_t(g.rect.width) + size_t(gc), i = out.index(col, row);
      out.labels[i] = g.labels[gi];
      for (const auto& [from, to] : scalars) (*to)[i] = (*from)[gi];
    }
  return out;
}

// The allowed exemplar pixels a pixel of target label `label` may start from.
const std::vector<int32_t>& start_pool(const ExemplarLevel& e, uint8_t label) {
  if (label != kUnknownLabel && !e.by_label[label].empty()) return e.by_label[label];
  return e.allowed;
}

// Whether target pixels `a` and `b` of a level lie on either side of a depth break.
bool breaks_between(const LevelGuides& g, const SynthesisParams& p, size_t a, size_t b) {
  return !g.depth.empty() && across_depth_break(g.depth[a], g.depth[b], p.depth_break);
}

// The reuse penalty's window: offsets at Chebyshev distance 2 .. kRepetitionRadius.
constexpr auto kRepetitionOffsets = [] {
  constexpr int side = 2 * kRepetitionRadius + 1;
  std::array<std::array<int, 2>, side * side - 9> offsets{};
  size_t n = 0;
  for (int dy = -kRepetitionRadius; dy <= kRepetitionRadius; ++dy)
    for (int dx = -kRepetitionRadius; dx <= kRepetitionRadius; ++dx)
      if (std::max(dx < 0 ? -dx : dx, dy < 0 ? -dy : dy) >= 2) offsets[n++] = {dx, dy};
  return offsets;
}();

// D_spread's hash purpose (the jitter's is 1, the random candidates' 16 and up).
constexpr uint64_t kSpreadSalt = 7;

// What the cost reads around a pixel, gathered once for all its candidates: the target labels
// of its neighbourhood, and the snapshot's exemplar coordinates at kRepetitionOffsets.
struct Around {
  std::array<uint8_t, kPatchSide * kPatchSide> labels{};
  std::array<int32_t, kRepetitionOffsets.size()> x{}, y{};
};

class Corrector {
 public:
  Corrector(const ExemplarLevel& e, const LevelGuides& g, const SynthesisParams& p, int level,
            int k, int64_t col_period)
      : e_(e),
        g_(g),
        p_(p),
        level_(level),
        k_(k),
        col_period_(col_period),
        floorable_(p.w_label >= 0 && p.w_altitude >= 0 && p.w_distance >= 0 && p.w_light >= 0 &&
                   p.w_repetition >= 0 && p.w_spread >= 0 && p.w_usage >= 0 && p.coherence > -1) {}

  // Issues the first loads best() makes for pixel (col, row), its neighbours' sources' colours
  // and similar patches, so that they are under way while the pixel before it is corrected.
  void prefetch(const State& state, int64_t col, int64_t row) const {
    for (int dy = -kPatchRadius; dy <= kPatchRadius; ++dy)
      for (int dx = -kPatchRadius; dx <= kPatchRadius; ++dx) {
        const size_t s = size_t(state.at(col + dx, row + dy));
        __builtin_prefetch(&e_.rgb[3 * s]);
        __builtin_prefetch(&e_.similar[s * size_t(k_)]);
        __builtin_prefetch(&e_.excluded[s]);
      }
  }

  // The best candidate for pixel (col, row) given the current state and the pass's snapshot
  // (packed coordinates, see corrected()).
  int32_t best(const State& state, const State& snapshot, int64_t col, int64_t row,
               uint64_t salt) const {
    // The two random candidates of the pixel's label: their loads issued first (a cache miss
    // each, in pools as large as the level).
    const uint8_t label = g_.labels[g_.index(col, row)];
    const std::vector<int32_t>& pool = start_pool(e_, label);
    const int64_t hashed_col = wrapped_col(col, col_period_);
    std::array<const int32_t*, 2> drawn{};
    for (uint64_t j = 0; j < drawn.size(); ++j) {
      drawn[j] = &pool[pixel_hash(hashed_col, row, level_, p_.seed, salt + j) % pool.size()];
      __builtin_prefetch(drawn[j]);
    }
    std::array<float, kPatchValues> patch{};
    size_t o = 0;
    for (int dy = -kPatchRadius; dy <= kPatchRadius; ++dy)
      for (int dx = -kPatchRadius; dx <= kPatchRadius; ++dx) {
        const size_t s = size_t(state.at(col + dx, row + dy));
        for (int c = 0; c < 3; ++c) patch[o++] = e_.rgb[3 * s + size_t(c)];
      }
    const auto feature = e_.basis.project(patch);
    Around around;
    for (size_t i = 0; i < kRepetitionOffsets.size(); ++i) {
      const int32_t s = snapshot.at(col + kRepetitionOffsets[i][0], row + kRepetitionOffsets[i][1]);
      around.x[i] = s & 0xffff;
      around.y[i] = s >> 16;
    }
    // The neighbours' sources shifted; those of neighbours across a depth break are forbidden:
    // they would continue a patch across a silhouette. Nor are such neighbours matched: their
    // target labels count as unknown and their colours as the candidate's own (below), so that a
    // pixel beside a silhouette (the sky above a skyline) is not drawn to the painting's pixels
    // beside another class.
    std::array<int32_t, kPatchSide * kPatchSide> shifted{}, forbidden{};
    std::array<bool, kPatchSide * kPatchSide> across{};
    size_t m = 0, f = 0;
    for (int dy = -kPatchRadius; dy <= kPatchRadius; ++dy)
      for (int dx = -kPatchRadius; dx <= kPatchRadius; ++dx) {
        const int32_t s = state.at(col + dx, row + dy);
        shifted[m] = e_.index(std::clamp(s % e_.width - dx, 0, e_.width - 1),
                              std::clamp(s / e_.width - dy, 0, e_.height - 1));
        __builtin_prefetch(&e_.similar[size_t(shifted[m]) * size_t(k_)]);
        across[m] = breaks_between(g_, p_, g_.index(col, row), g_.index(col + dx, row + dy));
        if (across[m]) forbidden[f++] = shifted[m];
        around.labels[m] = across[m] ? kUnknownLabel : g_.labels[g_.index(col + dx, row + dy)];
        ++m;
      }
    const bool beside_break = f > 0;
    // The neighbourhood's feature compared with candidate c's: beside a break, the neighbours
    // across it take c's own colours there (equal on both sides: not matched).
    const auto feature_for = [&](int32_t c) {
      if (!beside_break) return feature;
      std::array<float, kPatchValues> mixed = patch;
      const auto own = e_.patch(c % e_.width, c / e_.width);
      for (size_t j = 0; j < across.size(); ++j)
        if (across[j])
          std::copy_n(own.begin() + ptrdiff_t(3 * j), 3, mixed.begin() + ptrdiff_t(3 * j));
      return e_.basis.project(mixed);
    };
    std::array<int32_t, kPatchSide * kPatchSide * 8 + 2> candidates{};
    size_t n = 0;
    // Similar patches and the pools hold allowed pixels only (exemplar_pyramid.h), or -1.
    const auto add_allowed = [&](int32_t c) {
      assert(c < 0 || !e_.excluded[size_t(c)]);
      if (c < 0 || n == candidates.size()) return;
      const auto in = [c](const auto& list, size_t count) {
        int found = 0;  // no early exit: vectorized
        for (size_t i = 0; i < count; ++i) found |= int(list[i] == c);
        return found != 0;
      };
      if (!in(candidates, n) && !in(forbidden, f)) candidates[n++] = c;
    };
    // Coherent candidates first (the neighbours' sources, shifted), then their similar patches.
    for (const int32_t c : shifted)
      if (!e_.excluded[size_t(c)]) add_allowed(c);
    const size_t coherent = n;
    for (const int32_t c : shifted)
      for (int j = 0; j < k_; ++j) add_allowed(e_.similar[size_t(c) * size_t(k_) + size_t(j)]);
    for (const int32_t* c : drawn) add_allowed(*c);

    // The candidates' features lie scattered over the level (a cache miss each): their loads
    // issued together before the costs read them (-27 % of the transfer's CPU).
    for (size_t i = 0; i < n; ++i) {
      const size_t c = size_t(candidates[i]);
      __builtin_prefetch(&e_.features[c * kFeatureDims]);
      if (!e_.altitude.empty()) __builtin_prefetch(&e_.altitude[c]);
      const size_t w = size_t(e_.width);
      if (c >= w) __builtin_prefetch(&e_.labels[c - w]);
      __builtin_prefetch(&e_.labels[c]);
      if (c + w < e_.labels.size()) __builtin_prefetch(&e_.labels[c + w]);
      if (level_ > 0 && !e_.usage.empty()) __builtin_prefetch(&e_.usage[c]);
      if (p_.spread_typical < 1 && !e_.region_quantile.empty())
        __builtin_prefetch(&e_.region_quantile[c]);
    }
    // A candidate of the pixel's own label beats any other (the pool's random candidates offer
    // one whenever the exemplar has that label); among equals the least cost wins (least_cost.h),
    // most dismissed on their floor().
    const auto scale = [&](size_t i) { return i < coherent ? 1.0 : 1.0 + p_.coherence; };
    Floor low{};
    const int chosen = least_cost(
        n,
        [&](size_t i) {
          return label == kUnknownLabel || e_.labels[size_t(candidates[i])] == label;
        },
        [&](size_t i) {
          low = floor(candidates[i], feature_for(candidates[i]), row, hashed_col);
          return floorable_ ? (low.colour + low.spread) * scale(i)
                            : -std::numeric_limits<double>::infinity();
        },
        [&](size_t i) {
          const double base = cost(candidates[i], low, around, col, row);
          return i < coherent ? base : base * scale(i) + p_.w_usage * usage(candidates[i]);
        });
    return chosen >= 0 ? candidates[size_t(chosen)]
                       : state.at(col, row);  // every candidate forbidden: kept
  }

 private:
  // A candidate's D_color and its weighted D_spread, the first and last terms of its cost: with
  // every weight >= 0 the terms between are >= 0 and rounding is monotone, so the cost is no less
  // than their sum (nor, times 1 + coherence, than it times that): computed first, they dismiss
  // most candidates before the rest of their cost is. hashed_col: the column as the hashes read
  // it (wrapped_col).
  struct Floor {
    double colour, spread;
    int cx, cy;  // the candidate's exemplar coordinates, for the rest of its cost
  };
  Floor floor(int32_t c, const std::array<float, kFeatureDims>& feature, int64_t row,
              int64_t hashed_col) const {
    double colour = 0;
    for (int i = 0; i < kFeatureDims; ++i) {
      const double d =
          double(feature[size_t(i)]) - double(e_.features[size_t(c) * kFeatureDims + size_t(i)]);
      colour += d * d;
    }
    const int cx = c % e_.width, cy = c / e_.width;
    const uint64_t h =
        pixel_hash(hashed_col >> kSpreadBlockShift, row >> kSpreadBlockShift, level_, p_.seed,
                   kSpreadSalt ^ uint64_t(cx >> kSpreadRegionShift) << 40 ^
                       uint64_t(cy >> kSpreadRegionShift) << 20);
    const bool preferable = p_.spread_typical >= 1 || e_.region_quantile.empty() ||
                            typical_region(e_.region_quantile[size_t(c)], p_.spread_typical);
    const double spread = preferable ? double(h >> 11) * 0x1.0p-53 : 1.0;  // [0, 1), or 1
    return {colour, p_.w_spread * spread, cx, cy};
  }

  double cost(int32_t c, const Floor& floor, const Around& around, int64_t col, int64_t row) const {
    const int cx = floor.cx, cy = floor.cy;
    int mismatched = 0;
    size_t t = 0;
    for (int dy = -kPatchRadius; dy <= kPatchRadius; ++dy)
      for (int dx = -kPatchRadius; dx <= kPatchRadius; ++dx) {
        const uint8_t target = around.labels[t++];
        const uint8_t source = e_.labels[size_t(
            e_.index(std::clamp(cx + dx, 0, e_.width - 1), std::clamp(cy + dy, 0, e_.height - 1)))];
        mismatched += target != kUnknownLabel && target != source;
      }
    const size_t i = g_.index(col, row);
    const double altitude = guide_mismatch(g_.altitude, i, e_.altitude, c);
    const double distance = p_.w_distance > 0 ? guide_mismatch(g_.distance, i, e_.distance, c) : 0;
    const double light = p_.w_light > 0 ? guide_mismatch(g_.light, i, e_.light, c) : 0;
    int reused = 0;  // branch-free over contiguous arrays: vectorized
    for (size_t i = 0; i < kRepetitionOffsets.size(); ++i)
      reused +=
          int(unsigned(around.x[i] - cx + 1) <= 2u) & int(unsigned(around.y[i] - cy + 1) <= 2u);
    return floor.colour + p_.w_label * mismatched / double(kPatchSide * kPatchSide) +
           p_.w_altitude * altitude + p_.w_distance * distance + p_.w_light * light +
           p_.w_repetition * reused / double(kRepetitionOffsets.size()) + floor.spread;
  }

  // D_usage (synthesis.h): the exemplar's measured over-use, at the coarser levels.
  double usage(int32_t c) const {
    return level_ > 0 && !e_.usage.empty() ? double(e_.usage[size_t(c)]) : 0.0;
  }

  const ExemplarLevel& e_;
  const LevelGuides& g_;
  const SynthesisParams& p_;
  int level_, k_;
  int64_t col_period_;  // at this level
  bool floorable_;      // every weight >= 0: a candidate's floor bounds its cost (floor())
};

State initial_state(const ExemplarLevel& e, const LevelGuides& g, const SynthesisParams& p,
                    int level, int64_t col_period, const PixelRect& rect) {
  State s(rect);
  for (int64_t row = rect.row0; row < rect.row0 + rect.height; ++row)
    for (int64_t col = rect.col0; col < rect.col0 + rect.width; ++col) {
      const std::vector<int32_t>& pool = start_pool(e, g.labels[g.index(col, row)]);
      s.at(col, row) =
          pool[pixel_hash(wrapped_col(col, col_period), row, level, p.seed, 0) % pool.size()];
    }
  return s;
}

// Each pixel: its parent's exemplar pixel doubled, offset by the child's place, jittered.
State upsampled(const State& coarse, const ExemplarLevel& coarse_e, const ExemplarLevel& e,
                const SynthesisParams& p, int level, int64_t col_period, const PixelRect& rect) {
  State s(rect);
  const uint64_t span = uint64_t(2 * p.jitter + 1);
  for (int64_t row = rect.row0; row < rect.row0 + rect.height; ++row)
    for (int64_t col = rect.col0; col < rect.col0 + rect.width; ++col) {
      const int32_t parent = coarse.at(col >> 1, row >> 1);
      const uint64_t h = pixel_hash(wrapped_col(col, col_period), row, level, p.seed, 1);
      const int jx = int((h & 0xffffffffu) % span) - p.jitter,
                jy = int((h >> 32) % span) - p.jitter;
      const int x = 2 * (parent % coarse_e.width) + int(col & 1) + jx;
      const int y = 2 * (parent / coarse_e.width) + int(row & 1) + jy;
      s.at(col, row) = e.index(std::clamp(x, 0, e.width - 1), std::clamp(y, 0, e.height - 1));
    }
  return s;
}

// Sub-pass order of Lefebvre & Hoppe: parities (0,0) (1,1) (0,1) (1,0) of (column, row).
constexpr std::array<std::array<int, 2>, kSubPasses> kParities = {{{0, 0}, {1, 1}, {0, 1}, {1, 0}}};

State corrected(State state, const ExemplarLevel& e, const LevelGuides& g, const SynthesisParams& p,
                int level, int k, int64_t col_period, const PassPlan& plan, int pass) {
  const Corrector corrector(e, g, p, level, k, col_period);
  // The state at the start of the pass as packed coordinates x | y << 16 (the reuse penalty
  // compares coordinates many times per pixel: no divisions there).
  State snapshot = state;
  for (int32_t& s : snapshot.src) s = s % e.width | (s / e.width) << 16;
  for (int sub = 0; sub < kSubPasses; ++sub) {
    const PixelMask& needed = plan.outs[size_t(sub)];
    const PixelRect& r = needed.rect;
    State next(r);
    const auto [px, py] = kParities[size_t(sub)];
    const uint64_t salt = 16 + uint64_t(pass * kSubPasses + sub) * 2;
    for (int64_t row = r.row0; row < r.row0 + r.height; ++row)
      for (int64_t col = r.col0; col < r.col0 + r.width; ++col) {
        const bool corrects = (col & 1) == px && (row & 1) == py && needed.has(col, row);
        if (corrects && col + 2 < r.col0 + r.width) corrector.prefetch(state, col + 2, row);
        next.at(col, row) =
            corrects ? corrector.best(state, snapshot, col, row, salt) : state.at(col, row);
      }
    state = std::move(next);
  }
  return state;
}

// The finest level's patch passes (patch_pass.h); their draws' salts follow the correction's.
State patch_passed(State state, const ExemplarLevel& e, const LevelGuides& g,
                   const SynthesisParams& p, int64_t col_period,
                   const std::array<PassPlan, kMaxPatchPasses>& plans) {
  const PatchPassInputs in{g.rect,        g.labels,        g.depth,        g.altitude,
                           p.depth_break, p.patch_balance, p.patch_search, p.patch_edges,
                           p.w_altitude,  p.seed,          col_period,     p.line_classes};
  for (int pass = 0; pass < p.patch_passes; ++pass)
    for (int sub = 0; sub < kSubPasses; ++sub) {
      const PixelMask& needed = plans[size_t(pass)].outs[size_t(sub)];
      State next(needed.rect);
      const auto [px, py] = kParities[size_t(sub)];
      const uint64_t salt = 64 + uint64_t(pass * kSubPasses + sub) * kMaxPatchSearch;
      next.src =
          patch_sub_pass(e, in, state.rect, state.src, needed.rect, px, py, salt, needed.bits);
      state = std::move(next);
    }
  return state;
}

}  // namespace

int synthesis_halo() {
  // The widest margin over the alignments of a window to the coarsest level's pixels.
  int64_t halo = 0;
  const int64_t period = int64_t(1) << kLevels;
  for (int64_t offset = 0; offset < period; ++offset) {
    const PixelRect out{offset, offset, 1, 1};
    const Plan plan = plan_levels(out, kMaxPatchPasses);
    for (int l = 0; l < kLevels; ++l) {
      const PixelRect& s = plan.levels[size_t(l)].start;
      halo = std::max({halo, out.col0 - (s.col0 << l), ((s.col0 + s.width) << l) - (out.col0 + 1)});
    }
  }
  return int(halo);
}

PixelRect guide_rect(const PixelRect& out, int shift) {
  const int64_t halo = synthesis_halo();
  const int64_t col0 = (out.col0 - halo) >> shift, row0 = (out.row0 - halo) >> shift;
  return {col0, row0, ((out.col0 + out.width + halo - 1) >> shift) - col0 + 1,
          ((out.row0 + out.height + halo - 1) >> shift) - row0 + 1};
}

std::vector<int32_t> synthesize(const ExemplarPyramid& pyramid, const TargetGuides& guides,
                                const SynthesisParams& params, const PixelRect& out,
                                std::span<const uint8_t> wanted) {
  if (int(pyramid.levels.size()) != kLevels)
    throw Error("synthesis: the exemplar pyramid has " + std::to_string(pyramid.levels.size()) +
                " levels, not " + std::to_string(kLevels));
  if (params.vote_radius < 0 || params.vote_radius > kVoteRadius)
    throw Error("synthesis: vote_radius " + std::to_string(params.vote_radius) + ": must be 0 .. " +
                std::to_string(kVoteRadius));
  if (guides.col_period < 0 || guides.col_period % (int64_t(1) << kLevels) != 0)
    throw Error("synthesis: col_period " + std::to_string(guides.col_period) +
                ": must be a multiple of " + std::to_string(1 << kLevels));
  if (params.patch_passes < 0 || params.patch_passes > kMaxPatchPasses)
    throw Error("synthesis: patch_passes " + std::to_string(params.patch_passes) +
                ": must be 0 .. " + std::to_string(kMaxPatchPasses));
  if (params.patch_search < 0 || params.patch_search > kMaxPatchSearch)
    throw Error("synthesis: patch_search " + std::to_string(params.patch_search) +
                ": must be 0 .. " + std::to_string(kMaxPatchSearch));
  if (params.patch_edges < 0 || params.patch_edges > kMaxPatchEdges)
    throw Error("synthesis: patch_edges " + std::to_string(params.patch_edges) + ": must be 0 .. " +
                std::to_string(kMaxPatchEdges));
  if (!wanted.empty() && wanted.size() != size_t(out.width) * size_t(out.height))
    throw Error("synthesis: " + std::to_string(wanted.size()) + " wanted flags for a window of " +
                std::to_string(out.width) + " x " + std::to_string(out.height));
  const Plan plans = plan_levels(out, params.patch_passes, wanted);
  State state({});
  for (int l = kLevels - 1; l >= 0; --l) {
    const LevelPlan& plan = plans.levels[size_t(l)];
    const ExemplarLevel& e = pyramid.levels[size_t(l)];
    const LevelGuides g = level_guides(guides, l, plan.start);
    const int64_t period = guides.col_period >> l;
    state = l == kLevels - 1
                ? initial_state(e, g, params, l, period, plan.start)
                : upsampled(state, pyramid.levels[size_t(l) + 1], e, params, l, period, plan.start);
    for (int pass = 0; pass < kPasses; ++pass)
      state = corrected(std::move(state), e, g, params, l, pyramid.k, period,
                        plan.passes[size_t(pass)], pass);
    if (l == 0) {
      state = patch_passed(std::move(state), e, g, params, period, plans.patch_passes);
      State voted(out);
      voted.src = vote(e,
                       {state.rect, state.src, g.rect, g.labels, g.depth, params.depth_break,
                        params.vote_balance},
                       params.vote_radius, out);
      state = std::move(voted);
    }
  }
  return std::move(state.src);
}

}  // namespace maquette::synthesis
