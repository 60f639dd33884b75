#include "exemplar_usage.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <vector>

#include "assess_metrics.h"

namespace maquette::synthesis {
namespace {

// The copy's tiles: synthesized in parallel, each with its halo from the same guides.
constexpr int kCopyTile = 256;

// The finest level's pixel each pixel of the level copies, synthesized with `params` from
// `guides` (which cover the level grown by synthesis_halo()) in tiles in parallel: the synthesis
// is a function of global pixel coordinates (synthesize's contract), so the tiles make up the
// copy of the level as one window, bit for bit.
std::vector<int32_t> tiled_copy(const ExemplarPyramid& pyramid, const TargetGuides& guides,
                                const SynthesisParams& params) {
  const int w = pyramid.levels[0].width, h = pyramid.levels[0].height;
  const int across = (w + kCopyTile - 1) / kCopyTile, down = (h + kCopyTile - 1) / kCopyTile;
  std::vector<int32_t> source(size_t(w) * size_t(h));
  tbb::parallel_for(0, across * down, [&](int i) {
    const int x0 = i % across * kCopyTile, y0 = i / across * kCopyTile;
    const PixelRect tile{x0, y0, std::min(kCopyTile, w - x0), std::min(kCopyTile, h - y0)};
    const std::vector<int32_t> part = synthesize(pyramid, guides, params, tile);
    for (int64_t r = 0; r < tile.height; ++r)
      std::copy_n(part.begin() + r * tile.width, tile.width, source.begin() + (y0 + r) * w + x0);
  });
  return source;
}

}  // namespace

std::vector<float> usage_of_copy(const ExemplarLevel& finest, const std::vector<int32_t>& source) {
  const int w = finest.width, h = finest.height;
  std::vector<double> count(source.size(), 0);
  for (size_t i = 0; i < source.size(); ++i)
    if (!finest.excluded[i]) count[size_t(source[i])] += 1;
  std::vector<float> usage(count.size(), 0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double sum = 0;
      int n = 0;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int nx = x + dx, ny = y + dy;
          if (nx < 0 || ny < 0 || nx >= w || ny >= h ||
              finest.excluded[size_t(finest.index(nx, ny))])
            continue;
          sum += count[size_t(finest.index(nx, ny))];
          ++n;
        }
      usage[size_t(finest.index(x, y))] = n > 0 ? float(std::max(0.0, sum / n - 1)) : 0.0f;
    }
  return usage;
}

std::vector<float> colour_excess_of_copy(const ExemplarLevel& finest,
                                         const std::vector<int32_t>& source) {
  const auto bin = [&](size_t i) {
    const float* c = &finest.rgb[3 * i];
    return size_t(histogram_bin(c[0] * 255.0f, c[1] * 255.0f, c[2] * 255.0f));
  };
  struct Counts {
    std::vector<double> copy = std::vector<double>(kHistogramBins, 0),
                        exemplar = std::vector<double>(kHistogramBins, 0);
    double pixels = 0;
  };
  std::map<uint8_t, Counts> by_label;
  for (size_t i = 0; i < source.size(); ++i) {
    if (finest.excluded[i]) continue;
    Counts& n = by_label[finest.labels[i]];
    n.copy[bin(size_t(source[i]))] += 1;
    n.exemplar[bin(i)] += 1;
    n.pixels += 1;
  }
  std::vector<float> excess(source.size(), 1.0f);
  for (size_t i = 0; i < source.size(); ++i) {
    if (finest.excluded[i]) continue;
    const Counts& n = by_label.at(finest.labels[i]);
    const size_t b = bin(i);
    const double ratio =
        (n.copy[b] / n.pixels + kExcessFloor) / (n.exemplar[b] / n.pixels + kExcessFloor);
    excess[i] = float(std::clamp(ratio, 1 / kExcessClamp, kExcessClamp));
  }
  return excess;
}

TargetGuides own_label_guides(const ExemplarLevel& finest) {
  const int w = finest.width, h = finest.height, halo = synthesis_halo();
  TargetGuides own;
  own.rect = {-halo, -halo, w + 2 * halo, h + 2 * halo};
  own.labels.assign(size_t(own.rect.width) * size_t(own.rect.height), kUnknownLabel);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (!finest.excluded[size_t(finest.index(x, y))])
        own.labels[size_t(y + halo) * size_t(own.rect.width) + size_t(x + halo)] =
            finest.labels[size_t(finest.index(x, y))];
  return own;
}

void measure_usage(ExemplarPyramid& pyramid, const SynthesisParams& params) {
  ExemplarLevel& finest = pyramid.levels[0];
  for (ExemplarLevel& level : pyramid.levels) level.usage.clear(), level.colour_excess.clear();
  const TargetGuides own = own_label_guides(finest);
  SynthesisParams unpenalized = params;
  unpenalized.w_usage = 0;
  const std::vector<int32_t> source = tiled_copy(pyramid, own, unpenalized);

  finest.usage = usage_of_copy(finest, source);
  finest.colour_excess = colour_excess_of_copy(finest, source);
  for (size_t l = 1; l < pyramid.levels.size(); ++l) {
    const ExemplarLevel& fine = pyramid.levels[l - 1];
    ExemplarLevel& coarse = pyramid.levels[l];
    coarse.usage.assign(size_t(coarse.width) * size_t(coarse.height), 0);
    for (int y = 0; y < coarse.height; ++y)
      for (int x = 0; x < coarse.width; ++x) {
        double sum = 0;
        for (int dy = 0; dy < 2; ++dy)
          for (int dx = 0; dx < 2; ++dx)
            sum += fine.usage[size_t(fine.index(std::min(2 * x + dx, fine.width - 1),
                                                std::min(2 * y + dy, fine.height - 1)))];
        coarse.usage[size_t(coarse.index(x, y))] = float(sum / 4);
      }
  }
}

}  // namespace maquette::synthesis
