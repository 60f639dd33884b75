#include "inpaint.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/error.h"
#include "inpaint_mode.h"
#include "layer_values.h"
#include "masked_pyramid.h"

namespace maquette::synthesis {
namespace {

// The patches' and pixels' roles at one pyramid level (inpaint.h).
struct Roles {
  int width = 0, height = 0;
  std::vector<uint8_t> region;         // resynthesized: the hole and its band, nodata excluded
  std::vector<int32_t> region_pixels;  // the region's pixels (y * width + x), row-major
  std::vector<int32_t> region_slot;    // width * height: each pixel's place there, -1 elsewhere
  PatchCentres targets, references, completeness;
};

Roles roles_at(const MaskedImage& level, const std::vector<uint8_t>& hole,
               const InpaintParams& params) {
  const int w = level.image.width, h = level.image.height, half = params.patch / 2;
  std::vector<uint8_t> nodata(hole.size());
  for (size_t i = 0; i < hole.size(); ++i) nodata[i] = level.unknown[i] != 0 && hole[i] == 0;
  const auto to_hole = chessboard_distance(hole, w, h);
  const auto to_nodata = chessboard_distance(nodata, w, h);
  Roles r{w,
          h,
          std::vector<uint8_t>(hole.size(), 0),
          {},
          std::vector<int32_t>(hole.size(), -1),
          PatchCentres(w, h),
          PatchCentres(w, h),
          PatchCentres(w, h)};
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const size_t i = size_t(y) * w + x;
      r.region[i] = to_hole[i] <= params.band && nodata[i] == 0;
      if (r.region[i] != 0) {
        r.region_slot[i] = int32_t(r.region_pixels.size());
        r.region_pixels.push_back(int32_t(i));
      }
      if (x < half || y < half || x >= w - half || y >= h - half) continue;
      const bool overlaps_region = to_hole[i] <= params.band + half;
      r.targets.member[i] = overlaps_region;
      r.references.member[i] = !overlaps_region && to_nodata[i] > half;
      r.completeness.member[i] =
          r.references.member[i] && to_hole[i] <= params.band + half + params.patch;
    }
  }
  return r;
}

bool any(const std::vector<uint8_t>& v) {
  return std::any_of(v.begin(), v.end(), [](uint8_t m) { return m != 0; });
}

// A field for `queries` starting from the matches of the next level up (doubled, the query's
// offset within its 2 x 2 kept); the search re-draws those that are no reference patch here.
NearestField upsampled_field(const PatchCentres& queries, const NearestField& coarse,
                             int coarse_width, int coarse_height) {
  NearestField field = empty_field(queries);
  for (size_t e = 0; e < field.size(); ++e) {
    const int x = field.query_x[e], y = field.query_y[e];
    const int cx = std::min(x / 2, coarse_width - 1), cy = std::min(y / 2, coarse_height - 1);
    const int32_t c = coarse.index[size_t(cy) * coarse_width + cx];
    if (c < 0) continue;
    field.match_x[e] = 2 * coarse.match_x[c] + (x - 2 * cx);
    field.match_y[e] = 2 * coarse.match_y[c] + (y - 2 * cy);
  }
  return field;
}

// Wexler's similarity weights: exp(-cost / 2 sigma^2), sigma^2 the 75th percentile of the costs.
std::vector<double> vote_weights(const NearestField& field) {
  std::vector<float> sorted = field.cost;
  std::vector<double> weights(field.size(), 1.0);
  if (sorted.empty()) return weights;
  const auto p75 = sorted.begin() + ptrdiff_t(sorted.size() * 3 / 4);
  std::nth_element(sorted.begin(), p75, sorted.end());
  const double sigma2 = std::max(double(*p75), 1e-6);
  for (size_t e = 0; e < field.size(); ++e) weights[e] = std::exp(-field.cost[e] / (2 * sigma2));
  return weights;
}

// A level's first matches: the field's own where they are reference patches, random elsewhere,
// no search (their costs computed).
FieldSearchParams start_params(const InpaintParams& params, int level) {
  return {params.patch, 0, params.seed, level * (params.em_iterations + 1)};
}

// How a maximization step sets a pixel from the votes of the patches covering it: the value the
// lowest-cost target patch proposes, the votes' weighted mean, or their weighted mode
// (inpaint_mode.h).
enum class Pick { Best, Mean, Mode };

// One maximization step: each pixel of the region set from its votes by `pick`; with `classes`
// (one-hot channels) then to its most voted class.
void vote(const Roles& roles, const NearestField& coherence, const NearestField& completeness,
          const InpaintParams& params, PatchImage& image, Pick pick, bool classes) {
  const int w = roles.width, h = roles.height, c = image.channels, half = params.patch / 2;
  const auto coherence_weights = vote_weights(coherence);
  const auto completeness_weights = vote_weights(completeness);
  const double coherence_scale = 1.0 / double(std::max<size_t>(coherence.size(), 1));
  const double completeness_scale =
      params.completeness / double(std::max<size_t>(completeness.size(), 1));
  // Sums and the new values by the region's pixels only (a thin band in a large box).
  const size_t n = roles.region_pixels.size();
  std::vector<double> sum(n * c, 0.0), weight(n, 0.0);
  std::vector<float> next(n * c);
  for (size_t s = 0; s < n; ++s) {
    std::copy_n(image.values.data() + size_t(roles.region_pixels[s]) * c, c, next.data() + s * c);
  }
  // Completeness: each reference patch near the region votes into its nearest target patch
  // (scattered, in the field's order).
  for (size_t e = 0; e < completeness.size(); ++e) {
    const double k = completeness_weights[e] * completeness_scale;
    const int sx = completeness.query_x[e], sy = completeness.query_y[e];
    const int tx = completeness.match_x[e], ty = completeness.match_y[e];
    for (int dy = -half; dy <= half; ++dy) {
      for (int dx = -half; dx <= half; ++dx) {
        const int32_t s = roles.region_slot[size_t(ty + dy) * w + (tx + dx)];
        if (s < 0) continue;
        const float* v = image.pixel(sx + dx, sy + dy);
        for (int i = 0; i < c; ++i) sum[size_t(s) * c + i] += k * v[i];
        weight[s] += k;
      }
    }
  }
  // Coherence: every target patch covering a pixel proposes its match's value there (gathered,
  // pixels in parallel, each pixel's votes in a fixed order). For the mode, the completeness votes
  // count as one vote: their weighted mean with their total weight.
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n), [&](const tbb::blocked_range<size_t>& range) {
    std::vector<const float*> votes;
    std::vector<double> vote_weight;
    std::vector<float> completeness_mean(c);
    std::vector<double> mode(c), shifted(c);
    for (size_t s = range.begin(); s != range.end(); ++s) {
      const int x = roles.region_pixels[s] % w, y = roles.region_pixels[s] / w;
      double* pixel_sum = sum.data() + s * c;
      float* out = next.data() + s * c;
      votes.clear();
      vote_weight.clear();
      if (pick == Pick::Mode && weight[s] > 0) {
        for (int i = 0; i < c; ++i) completeness_mean[i] = float(pixel_sum[i] / weight[s]);
        votes.push_back(completeness_mean.data());
        vote_weight.push_back(weight[s]);
      }
      float best_cost = std::numeric_limits<float>::infinity();
      for (int dy = -half; dy <= half; ++dy) {
        for (int dx = -half; dx <= half; ++dx) {
          const int tx = x - dx, ty = y - dy;
          if (tx < 0 || ty < 0 || tx >= w || ty >= h) continue;
          const int32_t e = coherence.index[size_t(ty) * w + tx];
          if (e < 0) continue;
          const float* v = image.pixel(coherence.match_x[e] + dx, coherence.match_y[e] + dy);
          if (pick == Pick::Best) {
            if (coherence.cost[e] < best_cost) {
              best_cost = coherence.cost[e];
              std::copy_n(v, c, out);
            }
            continue;
          }
          const double k = coherence_weights[e] * coherence_scale;
          for (int i = 0; i < c; ++i) pixel_sum[i] += k * v[i];
          weight[s] += k;
          if (pick == Pick::Mode) {
            votes.push_back(v);
            vote_weight.push_back(k);
          }
        }
      }
      if (pick != Pick::Best && weight[s] > 0) {
        for (int i = 0; i < c; ++i) mode[i] = pixel_sum[i] / weight[s];
        if (pick == Pick::Mode) {
          mean_shift_mode(votes.data(), vote_weight.data(), votes.size(), c, mode.data(),
                          shifted.data());
        }
        for (int i = 0; i < c; ++i) out[i] = float(mode[i]);
      }
      if (classes) snap_to_mode(out, c);
    }
  });
  for (size_t s = 0; s < n; ++s) {
    std::copy_n(next.data() + s * c, c, image.values.data() + size_t(roles.region_pixels[s]) * c);
  }
}

// Levels until the hole is at most half a patch thick, while the image keeps 4 patches a side.
int level_count(const std::vector<uint8_t>& hole, int width, int height, int patch) {
  std::vector<uint8_t> outside(hole.size());
  for (size_t i = 0; i < hole.size(); ++i) outside[i] = hole[i] == 0;
  const auto depth = chessboard_distance(outside, width, height);
  int thickness = 0;
  for (size_t i = 0; i < hole.size(); ++i) {
    if (hole[i] != 0) thickness = std::max(thickness, depth[i]);
  }
  int levels = 1;
  while ((thickness >> (levels - 1)) > patch / 2 &&
         std::min(width, height) >> levels >= 4 * patch) {
    ++levels;
  }
  return levels;
}

void check(const PatchImage& image, const std::vector<uint8_t>& hole, const InpaintParams& p) {
  const auto fail = [](const std::string& what) { throw Error("inpaint: " + what); };
  if (p.patch < 3 || p.patch % 2 == 0) {
    fail("patch " + std::to_string(p.patch) + " is not an odd side of at least 3");
  }
  if (p.band < 0) fail("band " + std::to_string(p.band) + " is negative");
  if (p.em_iterations < 1) fail("em_iterations " + std::to_string(p.em_iterations) + " < 1");
  if (p.search_iterations < 1) {
    fail("search_iterations " + std::to_string(p.search_iterations) + " < 1");
  }
  if (!(p.completeness >= 0)) fail("completeness " + std::to_string(p.completeness) + " < 0");
  if (p.values != LayerValues::Continuous && image.channels != 1) {
    fail("heights and classes take 1 channel, not " + std::to_string(image.channels));
  }
  if (hole.size() != image.values.size() / std::max(image.channels, 1)) {
    fail("the hole mask has " + std::to_string(hole.size()) + " pixels, the image " +
         std::to_string(size_t(image.width) * image.height));
  }
}

// The completed image (every level's EM, as inpaint.h says) and its region at full size.
struct Completion {
  PatchImage image;
  std::vector<uint8_t> region;
};

Completion complete(const PatchImage& image, const std::vector<uint8_t>& hole, int levels,
                    const InpaintParams& params, const NearestFieldSearch& search) {
  const int c = image.channels;
  MaskedImage base{image, std::vector<uint8_t>(hole.size(), 0)};
  for (size_t i = 0; i < hole.size(); ++i) {
    const float* pixel = image.values.data() + i * c;
    base.unknown[i] =
        hole[i] != 0 || std::any_of(pixel, pixel + c, [](float v) { return std::isnan(v); });
  }
  const auto pyramid = masked_pyramid(std::move(base), levels);
  std::vector<std::vector<uint8_t>> holes{hole};
  for (int l = 1; l < levels; ++l) {
    const auto& finer = pyramid[l - 1].image;
    holes.push_back(halve_mask(holes.back(), finer.width, finer.height));
  }
  PatchImage work;  // the completed image of the level last processed
  NearestField coherence, completeness;
  int coarse_w = 0, coarse_h = 0;
  for (int l = levels - 1; l >= 0; --l) {
    const Roles roles = roles_at(pyramid[l], holes[l], params);
    if (!any(roles.references.member)) {
      if (l > 0) continue;  // too coarse for a patch outside the hole: start finer
      const auto holed = std::count_if(hole.begin(), hole.end(), [](uint8_t h) { return h != 0; });
      throw Error("inpaint: no " + std::to_string(params.patch) + " x " +
                  std::to_string(params.patch) + " patch lies wholly outside the hole, its band (" +
                  std::to_string(params.band) +
                  " pixels) and the nodata: nothing is left to fill "
                  "it from (the hole covers " +
                  std::to_string(int(std::lround(100.0 * double(holed) / double(hole.size())))) +
                  " % of the image with its context; give a smaller hole or a larger region)");
    }
    PatchImage level = pyramid[l].image;
    const bool coarsest = work.width == 0;
    if (coarsest) {
      fill_by_diffusion(level, pyramid[l].unknown);
      coherence = empty_field(roles.targets);
      completeness = empty_field(roles.completeness);
    } else {
      upsample_into(work, holes[l], level);
      std::vector<uint8_t> nodata(holes[l].size());
      for (size_t i = 0; i < nodata.size(); ++i) {
        nodata[i] = pyramid[l].unknown[i] != 0 && holes[l][i] == 0;
      }
      fill_by_diffusion(level, nodata);
      coherence = upsampled_field(roles.targets, coherence, coarse_w, coarse_h);
      completeness = upsampled_field(roles.completeness, completeness, coarse_w, coarse_h);
    }
    // The level's first values from its first matches: on the coarsest level random ones, each
    // pixel given the value of the best covering it (a start with the image's contrast: searching
    // from the smooth diffusion fill finds smooth ground); on the others the coarser level's
    // matches upsampled, with their own detail (searching from the bilinear start finds blur).
    search.improve(level, level, roles.references, start_params(params, l), coherence);
    search.improve(level, level, roles.targets, start_params(params, l), completeness);
    const bool classes = params.values == LayerValues::Classes && l == 0;
    vote(roles, coherence, completeness, params, level, coarsest ? Pick::Best : Pick::Mean,
         classes);
    for (int it = 0; it < params.em_iterations; ++it) {
      const FieldSearchParams fp{params.patch, params.search_iterations, params.seed,
                                 l * (params.em_iterations + 1) + it + 1};
      search.improve(level, level, roles.references, fp, coherence);
      if (params.completeness > 0 && completeness.size() > 0) {
        search.improve(level, level, roles.targets, fp, completeness);
      }
      // The finest level's last step takes the votes' mode (sharp where the mean blurs); classes
      // take their most voted class instead.
      const bool last = l == 0 && it == params.em_iterations - 1 && !classes;
      vote(roles, coherence, completeness, params, level, last ? Pick::Mode : Pick::Mean, classes);
    }
    work = std::move(level);
    coarse_w = roles.width;
    coarse_h = roles.height;
  }
  return {std::move(work), roles_at(pyramid[0], hole, params).region};
}

// `image` with the region's pixels taken from `filled` (the same channels).
PatchImage with_region(PatchImage image, const Completion& filled) {
  const int c = image.channels;
  for (size_t i = 0; i < filled.region.size(); ++i) {
    if (filled.region[i] != 0) {
      std::copy_n(filled.image.values.begin() + i * c, c, image.values.begin() + i * c);
    }
  }
  return image;
}

// Heights: the trend under the hole and the nodata (layer_values.h) plus the detail completed.
PatchImage inpaint_heights(const PatchImage& heights, const std::vector<uint8_t>& hole, int levels,
                           const InpaintParams& params, const NearestFieldSearch& search) {
  std::vector<uint8_t> unknown(hole.size());
  for (size_t i = 0; i < hole.size(); ++i) {
    unknown[i] = hole[i] != 0 || std::isnan(heights.values[i]);
  }
  const PatchImage trend = height_trend(heights, unknown, std::max(levels, 2));
  PatchImage detail = heights;
  for (size_t i = 0; i < hole.size(); ++i) {
    detail.values[i] = hole[i] != 0 ? 0.0f : heights.values[i] - trend.values[i];
  }
  Completion filled = complete(detail, hole, levels, params, search);
  for (size_t i = 0; i < hole.size(); ++i) filled.image.values[i] += trend.values[i];
  return with_region(heights, filled);
}

}  // namespace

PatchImage inpaint(const PatchImage& image, const std::vector<uint8_t>& hole,
                   const InpaintParams& params, const NearestFieldSearch& search) {
  check(image, hole, params);
  if (std::none_of(hole.begin(), hole.end(), [](uint8_t v) { return v != 0; })) return image;
  const int levels = level_count(hole, image.width, image.height, params.patch);
  switch (params.values) {
    case LayerValues::Continuous:
      return with_region(image, complete(image, hole, levels, params, search));
    case LayerValues::Heights:
      return inpaint_heights(image, hole, levels, params, search);
    case LayerValues::Classes: {
      const ClassChannels channels = class_channels(image, hole);
      const Completion filled = complete(channels.one_hot, hole, levels, params, search);
      return with_region(image, {class_labels(filled.image, channels.classes), filled.region});
    }
  }
  return image;
}

}  // namespace maquette::synthesis
