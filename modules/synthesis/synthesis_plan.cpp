#include "synthesis_plan.h"

#include <algorithm>

namespace maquette::synthesis {
namespace {

// `m` grown by `reach` on every side, its bits dilated by the square of that radius.
PixelMask grown(const PixelMask& m, int64_t reach) {
  PixelMask g{{m.rect.col0 - reach, m.rect.row0 - reach, m.rect.width + 2 * reach,
               m.rect.height + 2 * reach},
              {}};
  if (m.bits.empty()) return g;
  const size_t w = size_t(g.rect.width), mw = size_t(m.rect.width);
  const size_t side = size_t(2 * reach + 1);
  // Along the rows first (m's rows, g's columns: m's column x is g's x + reach), then the columns.
  std::vector<uint8_t> across(size_t(m.rect.height) * w, 0);
  for (size_t y = 0; y < size_t(m.rect.height); ++y)
    for (size_t x = 0; x < mw; ++x)
      if (m.bits[y * mw + x]) std::fill_n(across.begin() + ptrdiff_t(y * w + x), side, 1);
  g.bits.assign(w * size_t(g.rect.height), 0);
  for (size_t y = 0; y < size_t(m.rect.height); ++y)
    for (size_t x = 0; x < w; ++x)
      if (across[y * w + x])
        for (size_t d = 0; d < side; ++d) g.bits[(y + d) * w + x] = 1;
  return g;
}

// The pixels of the next coarser level covering `m`'s rectangle, each read when a child is.
PixelMask parents(const PixelMask& m) {
  const PixelRect& r = m.rect;
  const int64_t c0 = r.col0 >> 1, r0 = r.row0 >> 1;
  PixelMask p{
      {c0, r0, ((r.col0 + r.width - 1) >> 1) - c0 + 1, ((r.row0 + r.height - 1) >> 1) - r0 + 1},
      {}};
  if (m.bits.empty()) return p;
  p.bits.assign(size_t(p.rect.width) * size_t(p.rect.height), 0);
  for (int64_t row = r.row0; row < r.row0 + r.height; ++row)
    for (int64_t col = r.col0; col < r.col0 + r.width; ++col)
      if (m.has(col, row))
        p.bits[size_t((row >> 1) - r0) * size_t(p.rect.width) + size_t((col >> 1) - c0)] = 1;
  return p;
}

// Fills `pass` backwards from `need` (what its last sub-pass outputs), each sub-pass reading its
// state within `reach` and the pass its start within `start_reach`; returns the start's mask.
PixelMask plan_pass(PassPlan& pass, PixelMask need, int reach, int start_reach) {
  pass.outs[kSubPasses - 1] = std::move(need);
  for (int s = kSubPasses - 2; s >= 0; --s)
    pass.outs[size_t(s)] = grown(pass.outs[size_t(s) + 1], reach);
  PixelMask start = grown(pass.outs[0], start_reach);
  pass.start = start.rect;
  return start;
}

}  // namespace

Plan plan_levels(const PixelRect& out, int patch_passes, std::span<const uint8_t> wanted) {
  Plan plan;
  PixelMask need{out, {}};
  if (std::any_of(wanted.begin(), wanted.end(), [](uint8_t w) { return w == 0; }))
    need.bits.assign(wanted.begin(), wanted.end());
  need = grown(need, kVoteRadius);  // the finest level's vote reads it
  for (int pass = patch_passes - 1; pass >= 0; --pass)
    need = plan_pass(plan.patch_passes[size_t(pass)], std::move(need), kPatchPassRadius,
                     kPatchPassRadius);
  for (int l = 0; l < kLevels; ++l) {
    for (int pass = kPasses - 1; pass >= 0; --pass)
      need = plan_pass(plan.levels[size_t(l)].passes[size_t(pass)], std::move(need), kPatchRadius,
                       std::max(kPatchRadius, kRepetitionRadius));
    plan.levels[size_t(l)].start = need.rect;
    need = parents(need);
  }
  return plan;
}

}  // namespace maquette::synthesis
