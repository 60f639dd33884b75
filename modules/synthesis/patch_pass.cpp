#include "patch_pass.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

#include "class_edges.h"
#include "pixel_hash.h"
#include "vote.h"

namespace maquette::synthesis {
namespace {

constexpr int kSide = 2 * kPatchPassRadius + 1;
constexpr int kRowValues = 3 * kSide;                // RGB of one row of a patch
constexpr int kMinOwnClass = kSide * kSide / 2 + 1;  // a strict majority of p's window
// The vote's floor (RGB 0..1) for each pixel of a patch but its centre.
constexpr float kPatchBalanceFloor = float(kBalanceFloor * (kSide * kSide - 1));
// The altitude weight's scale: a patch's pixels (but the centre) over a 3 x 3 neighbourhood's.
constexpr double kAltitudeScale = double(kSide * kSide - 1) / double(kPatchSide * kPatchSide);

// The class edges' draws' salts, apart from the search's (salt + j, j < kMaxPatchSearch).
constexpr uint64_t kEdgeSalt = uint64_t(1) << 20;

size_t offset(const PixelRect& r, int64_t col, int64_t row) {
  return size_t(row - r.row0) * size_t(r.width) + size_t(col - r.col0);
}

// The label other than `own` and kUnknownLabel most present among `window`'s, the lower on a
// tie; kUnknownLabel when there is none.
uint8_t most_present_other(const std::array<uint8_t, kSide * kSide>& window, uint8_t own) {
  uint8_t best = kUnknownLabel;
  int best_count = 0;
  for (const uint8_t l : window) {
    if (l == own || l == kUnknownLabel) continue;
    const int count = int(std::count(window.begin(), window.end(), l));
    if (count > best_count || (count == best_count && l < best)) best = l, best_count = count;
  }
  return best;
}

}  // namespace

std::vector<int32_t> patch_sub_pass(const ExemplarLevel& e, const PatchPassInputs& in,
                                    const PixelRect& state_rect, const std::vector<int32_t>& state,
                                    const PixelRect& out, int px, int py, uint64_t salt,
                                    std::span<const uint8_t> needed) {
  constexpr int R = kPatchPassRadius;
  std::vector<int32_t> result(size_t(out.width) * size_t(out.height));
  std::array<float, kSide * kRowValues> patch{};  // the output's colours around p, row by row
  std::array<int32_t, kSide * kSide + kMaxPatchSearch + kMaxPatchEdges> proposals{};
  std::array<uint8_t, kSide * kSide> window_labels{};
  const bool balanced = in.balance > 0 && !e.colour_excess.empty();
  ExcessPower power(in.balance);
  for (int64_t row = out.row0; row < out.row0 + out.height; ++row)
    for (int64_t col = out.col0; col < out.col0 + out.width; ++col) {
      int32_t& winner = result[offset(out, col, row)];
      winner = state[offset(state_rect, col, row)];
      if ((col & 1) != px || (row & 1) != py) continue;
      if (!needed.empty() && !needed[offset(out, col, row)]) continue;
      // The sources the next pixel of this parity adds to the window: their loads under way
      // while this one is weighed.
      if (col + 2 < out.col0 + out.width)
        for (int dy = -R; dy <= R; ++dy)
          for (int dx = R - 1; dx <= R; ++dx) {
            const size_t s = size_t(state[offset(state_rect, col + 2 + dx, row + dy)]);
            __builtin_prefetch(&e.rgb[3 * s]);
            __builtin_prefetch(&e.excluded[s]);
            __builtin_prefetch(&e.labels[s]);
          }
      if (depth_break_within(in.depth, in.guide_rect, col, row, R, in.depth_break)) continue;
      const size_t g = offset(in.guide_rect, col, row);
      const uint8_t label = in.labels[g];
      size_t n = 0;
      // Kept when its patch lies inside the exemplar, it is allowed and of p's label; once.
      const auto offer = [&](int x, int y) {
        if (x < R || y < R || x >= e.width - R || y >= e.height - R) return;
        const int32_t c = e.index(x, y);
        if (e.excluded[size_t(c)] || (label != kUnknownLabel && e.labels[size_t(c)] != label))
          return;
        if (std::find(proposals.begin(), proposals.begin() + std::ptrdiff_t(n), c) ==
            proposals.begin() + std::ptrdiff_t(n))
          proposals[n++] = c;
      };
      float* value = patch.data();
      int own_class = 0;  // window pixels of p's target label
      for (int dy = -R; dy <= R; ++dy)
        for (int dx = -R; dx <= R; ++dx) {
          const int32_t s = state[offset(state_rect, col + dx, row + dy)];
          value = std::copy_n(e.rgb.begin() + 3 * std::ptrdiff_t(s), 3, value);
          offer(s % e.width - dx, s / e.width - dy);
          const uint8_t l = in.labels[offset(in.guide_rect, col + dx, row + dy)];
          window_labels[size_t((dy + R) * kSide + dx + R)] = l;
          own_class += l == label;
        }
      if (own_class < kMinOwnClass && in.line_classes[label])
        continue;  // a line thinner than p's window
      const bool classes_meet = own_class < kSide * kSide;
      // Where the copies under way disagree and the target's classes meet, places drawn around
      // p's own source, and from the exemplar's edges between p's class and the other.
      if (n > 1 && classes_meet) {
        const int64_t hashed_col = wrapped_col(col, in.col_period);
        for (int j = 0; j < in.search; ++j) {
          const int radius = kPatchSearchRadius >> j;
          const uint64_t h = pixel_hash(hashed_col, row, 0, in.seed, salt + uint64_t(j));
          offer(winner % e.width + int(h % uint64_t(2 * radius + 1)) - radius,
                winner / e.width + int((h >> 32) % uint64_t(2 * radius + 1)) - radius);
        }
        const auto edge =
            in.edges > 0 && label != kUnknownLabel
                ? class_edge_run(e.class_edges, label, most_present_other(window_labels, label))
                : std::span<const uint64_t>{};
        for (int j = 0; j < in.edges && !edge.empty(); ++j) {
          const uint64_t h =
              pixel_hash(hashed_col, row, 0, in.seed, salt + kEdgeSalt + uint64_t(j));
          const int32_t c = class_edge_pixel(edge[size_t(h % uint64_t(edge.size()))]);
          offer(c % e.width, c / e.width);
        }
      }
      if (n <= 1) {  // within a copy under way, or no proposal kept
        if (n == 1) winner = proposals[0];
        continue;
      }
      // The proposals' patches, guides and excess lie scattered over the exemplar: their loads
      // issued together before the distances read them.
      for (size_t i = 0; i < n; ++i) {
        const std::ptrdiff_t c = proposals[i];
        for (int oy = -R; oy <= R; ++oy) {
          const float* b = e.rgb.data() + 3 * (c + std::ptrdiff_t(oy) * e.width - R);
          __builtin_prefetch(b);
          __builtin_prefetch(b + kRowValues - 1);
        }
        if (!e.altitude.empty()) __builtin_prefetch(&e.altitude[size_t(c)]);
        if (balanced) __builtin_prefetch(&e.colour_excess[size_t(c)]);
      }
      std::array<float, kSide * kSide + kMaxPatchSearch + kMaxPatchEdges> excess_factor{};
      if (balanced)
        for (size_t i = 0; i < n; ++i)
          excess_factor[i] = float(power(e.colour_excess[size_t(proposals[i])]));
      float* centre = patch.data() + R * kRowValues + 3 * R;
      float least = std::numeric_limits<float>::infinity();
      for (size_t i = 0; i < n; ++i) {
        const int32_t c = proposals[i];
        // p's own pixel left out of the distance: its colour will be the candidate's.
        std::copy_n(e.rgb.begin() + 3 * std::ptrdiff_t(c), 3, centre);
        const float factor = balanced ? excess_factor[i] : 1.0f;
        const float guide = in.w_altitude > 0 ? float(in.w_altitude * kAltitudeScale *
                                                      guide_mismatch(in.altitude, g, e.altitude, c))
                                              : 0.0f;
        float d = balanced ? kPatchBalanceFloor : 0.0f;
        for (int oy = -R; oy <= R && d * factor + guide < least; ++oy) {
          const float* a = patch.data() + (oy + R) * kRowValues;
          const float* b =
              e.rgb.data() + 3 * (std::ptrdiff_t(c) + std::ptrdiff_t(oy) * e.width - R);
          for (int k = 0; k < kRowValues; ++k) d += (a[k] - b[k]) * (a[k] - b[k]);
        }
        if (d * factor + guide < least) least = d * factor + guide, winner = c;
      }
    }
  return result;
}

}  // namespace maquette::synthesis
