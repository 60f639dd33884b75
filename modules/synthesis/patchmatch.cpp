#include "patchmatch.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <utility>

#include "core/error.h"
#include "pixel_hash.h"

namespace maquette::synthesis {
namespace {

constexpr int kTileSide = 64;
// Salts of the hashed draws: the initial match, then each pass's random search.
constexpr uint64_t kInitialSalt = 1;
constexpr uint64_t kSearchSalt = 2;

// The reference centres in row-major order: the random initial matches' pool.
std::vector<int32_t> reference_pool(const PatchCentres& references) {
  std::vector<int32_t> pool;
  for (size_t i = 0; i < references.member.size(); ++i) {
    if (references.member[i] != 0) pool.push_back(int32_t(i));
  }
  return pool;
}

// The tile holding pixel (x, y) (images are narrower than 2^16 tiles).
int64_t tile_key(int x, int y) { return int64_t(y / kTileSide) << 16 | (x / kTileSide); }

// The entries of `field` by tile of the query image, each tile's entries in row-major order.
std::vector<std::vector<int32_t>> entries_by_tile(const NearestField& field) {
  std::map<int64_t, std::vector<int32_t>> by_key;
  for (size_t e = 0; e < field.size(); ++e) {
    by_key[tile_key(field.query_x[e], field.query_y[e])].push_back(int32_t(e));
  }
  std::vector<std::vector<int32_t>> tiles;
  for (auto& [key, entries] : by_key) tiles.push_back(std::move(entries));
  return tiles;
}

// A uniform draw in [-1, 1) from 32 bits of a hash.
double signed_unit(uint64_t bits) { return double(uint32_t(bits)) / 2147483648.0 - 1.0; }

// `v` rounded half away from zero, as std::lround, inline (std::lround is a call into libm: 4 % of
// a clone stroke's time in the random search).
int rounded(double v) { return int(v < 0 ? v - 0.5 : v + 0.5); }

struct Match {
  int32_t x, y;
  float cost;
};

class Pass {
 public:
  Pass(const PatchImage& query, const PatchImage& reference, const PatchCentres& references,
       const FieldSearchParams& params, const NearestField& before, NearestField& field, int pass)
      : query_(query),
        reference_(reference),
        references_(references),
        params_(params),
        before_(before),
        field_(field),
        pass_(pass) {}

  void run_tile(const std::vector<int32_t>& entries) const {
    const bool forward = pass_ % 2 == 0;
    const int step = forward ? 1 : -1;
    for (size_t i = 0; i < entries.size(); ++i) {
      const int32_t e = entries[forward ? i : entries.size() - 1 - i];
      const int qx = field_.query_x[e], qy = field_.query_y[e];
      Match best{field_.match_x[e], field_.match_y[e], field_.cost[e]};
      // Propagation: the neighbour already visited on this pass's scan, its match shifted back.
      propagate(qx, qy, qx - step, qy, best);
      propagate(qx, qy, qx, qy - step, best);
      random_search(qx, qy, best);
      field_.match_x[e] = best.x;
      field_.match_y[e] = best.y;
      field_.cost[e] = best.cost;
    }
  }

 private:
  void try_candidate(int qx, int qy, int rx, int ry, Match& best) const {
    if (rx < 0 || ry < 0 || rx >= references_.width || ry >= references_.height) return;
    if (!references_.has(rx, ry) || (rx == best.x && ry == best.y)) return;
    const float d = patch_distance(query_, qx, qy, reference_, rx, ry, params_.patch, best.cost);
    if (d < best.cost) best = {rx, ry, d};
  }

  void propagate(int qx, int qy, int nx, int ny, Match& best) const {
    if (nx < 0 || ny < 0 || nx >= query_.width || ny >= query_.height) return;
    const int32_t n = field_.index[size_t(ny) * query_.width + nx];
    if (n < 0) return;
    // The neighbour's match as this pass left it in the same tile, as the last pass did elsewhere.
    const NearestField& source = tile_key(nx, ny) == tile_key(qx, qy) ? field_ : before_;
    try_candidate(qx, qy, source.match_x[n] + (qx - nx), source.match_y[n] + (qy - ny), best);
  }

  // The draws' offsets from the best match do not depend on it: all drawn first, and the
  // candidates they give around the best match so far prefetched (the wide windows' candidates
  // lie anywhere in the image: their reads miss the cache, and most draws leave the best as it
  // is); then tried in order, each around the best match as the draws before left it.
  void random_search(int qx, int qy, Match& best) const {
    constexpr int kMaxDraws = 32;  // windows halving from a side below 2^31
    int dx[kMaxDraws], dy[kMaxDraws], draws = 0;
    for (int radius = std::max(references_.width, references_.height); radius >= 1; radius /= 2) {
      const uint64_t h =
          pixel_hash(qx, qy, params_.round, params_.seed,
                     (kSearchSalt << 56) ^ (uint64_t(pass_) << 16) ^ uint64_t(draws));
      dx[draws] = rounded(signed_unit(h) * radius);
      dy[draws++] = rounded(signed_unit(h >> 32) * radius);
    }
    const auto candidate = [&](int d) {
      return std::pair{std::clamp(best.x + dx[d], 0, references_.width - 1),
                       std::clamp(best.y + dy[d], 0, references_.height - 1)};
    };
    const int half = params_.patch / 2;
    for (int d = 0; d < draws; ++d) {
      const auto [rx, ry] = candidate(d);
      __builtin_prefetch(&references_.member[size_t(ry) * references_.width + rx]);
      if (rx >= half && ry >= half) __builtin_prefetch(reference_.pixel(rx - half, ry - half));
    }
    for (int d = 0; d < draws; ++d) {
      const auto [rx, ry] = candidate(d);
      try_candidate(qx, qy, rx, ry, best);
    }
  }

  const PatchImage& query_;
  const PatchImage& reference_;
  const PatchCentres& references_;
  const FieldSearchParams& params_;
  const NearestField& before_;
  NearestField& field_;
  int pass_;
};

}  // namespace

void PatchMatch::improve(const PatchImage& query, const PatchImage& reference,
                         const PatchCentres& references, const FieldSearchParams& params,
                         NearestField& field) const {
  if (params.patch < 3 || params.patch % 2 == 0) {
    throw Error("PatchMatch: patch side " + std::to_string(params.patch) +
                " is not an odd number of at least 3");
  }
  if (query.channels != reference.channels) {
    throw Error("PatchMatch: the query image has " + std::to_string(query.channels) +
                " channels, the reference image " + std::to_string(reference.channels));
  }
  const std::vector<int32_t> pool = reference_pool(references);
  if (pool.empty()) throw Error("PatchMatch: no reference patch to match");
  // Initial matches: kept where still a reference centre (their cost recomputed), else drawn.
  tbb::parallel_for(size_t(0), field.size(), [&](size_t e) {
    const int qx = field.query_x[e], qy = field.query_y[e];
    const bool kept = field.match_x[e] >= 0 && field.match_x[e] < references.width &&
                      field.match_y[e] >= 0 && field.match_y[e] < references.height &&
                      references.has(field.match_x[e], field.match_y[e]);
    if (!kept) {
      const uint64_t h = pixel_hash(qx, qy, params.round, params.seed, kInitialSalt << 56);
      const int32_t r = pool[h % pool.size()];
      field.match_x[e] = r % references.width;
      field.match_y[e] = r / references.width;
    }
    field.cost[e] = patch_distance(query, qx, qy, reference, field.match_x[e], field.match_y[e],
                                   params.patch, std::numeric_limits<float>::infinity());
  });
  const auto tiles = entries_by_tile(field);
  NearestField before;  // the matches as the previous pass left them (the index is not needed)
  for (int pass = 0; pass < params.iterations; ++pass) {
    before.match_x = field.match_x;
    before.match_y = field.match_y;
    const Pass scan(query, reference, references, params, before, field, pass);
    tbb::parallel_for(size_t(0), tiles.size(), [&](size_t t) { scan.run_tile(tiles[t]); });
  }
}

}  // namespace maquette::synthesis
