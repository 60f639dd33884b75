// Our transfer and ebsynth (jamriska/ebsynth's CPU backend, compiled in by compare.sh) on the
// same exemplar, guides and output size (zion_fixture.h): the exemplar's colours as ebsynth's
// style, the painting classes one-hot as its guide channels (one more channel marks the excluded
// pixels, which no target pixel has), the target's classes the same way; ebsynth's command-line
// defaults otherwise (5 x 5 patches, uniformity 3500, plain votes, 6 search-vote and 4
// PatchMatch iterations per level). Prints CPU and wall times, s per output megapixel and both
// outputs' measures (assess_metrics.h; ebsynth's sources from its nearest-neighbour field), the
// coherence at every `step`-th column and row (the exact 5 x 5 search at every 2nd pixel takes
// minutes of CPU per image; 8 is what benchmarks/README.md's later rows use). Ours is measured
// with its vote of radius `vote` (synthesis.h), and its copy with ebsynth's plain vote applied
// (each pixel the mean colour of the 5 x 5 overlapping patches' proposals), so that the
// smoothing of a mean vote is measured apart from the copy's coherence. `params`, a JSON object
// of synthesis.transfer's weights (synthesis_params_schema(): "w_spread", "w_usage", ...),
// overrides the defaults for ours; "ours" as the last argument skips ebsynth (a variant's run,
// measured against an earlier run's ebsynth).
// Usage: synthesis_ebsynth_compare [side (512)] [threads (2)] [coherence step (2)] [vote (1)]
//                                  [params ({})] [ours]
#include <omp.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <string>

#include "ebsynth.h"
#include "transfer_params.h"
#include "zion_fixture.h"

namespace maquette::synthesis::bench {
namespace {

struct Timed {
  double cpu = 0, wall = 0;  // seconds (CPU: every thread of the process)
};

template <typename F>
Timed timed(F&& f) {
  const std::clock_t c0 = std::clock();
  const auto w0 = std::chrono::steady_clock::now();
  f();
  return {double(std::clock() - c0) / CLOCKS_PER_SEC,
          std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count()};
}

// One-hot guide channels: class c -> channel c at 255; `excluded` -> the last channel.
std::vector<uint8_t> one_hot(const std::vector<uint8_t>& labels,
                             const std::vector<uint8_t>* excluded, int channels) {
  std::vector<uint8_t> g(labels.size() * size_t(channels), 0);
  for (size_t i = 0; i < labels.size(); ++i) {
    if (labels[i] < channels - 1) g[i * size_t(channels) + labels[i]] = 255;
    if (excluded && (*excluded)[i]) g[i * size_t(channels) + size_t(channels - 1)] = 255;
  }
  return g;
}

// ebsynth's plain vote of a copy `source` over `out` (row-major): each pixel the mean colour of
// the exemplar pixels S(q) - (q - p) proposed by the 5 x 5 patches around it that lie in `out`
// and propose an allowed pixel inside the exemplar.
std::vector<float> plain_vote(const Exemplar& e, const PixelRect& out,
                              const std::vector<int32_t>& source) {
  constexpr int kRadius = 2;
  std::vector<float> rgb(source.size() * 3);
  for (int64_t row = 0; row < out.height; ++row)
    for (int64_t col = 0; col < out.width; ++col) {
      std::array<double, 3> sum{};
      int n = 0;
      for (int64_t dy = -kRadius; dy <= kRadius; ++dy)
        for (int64_t dx = -kRadius; dx <= kRadius; ++dx) {
          const int64_t qc = col + dx, qr = row + dy;
          if (qc < 0 || qr < 0 || qc >= out.width || qr >= out.height) continue;
          const int32_t s = source[size_t(qr * out.width + qc)];
          const int64_t x = s % e.width - dx, y = s / e.width - dy;
          if (x < 0 || y < 0 || x >= e.width || y >= e.height) continue;
          const size_t c = size_t(y * e.width + x);
          if (e.excluded[c]) continue;
          for (size_t k = 0; k < 3; ++k) sum[k] += e.rgb[3 * c + k];
          ++n;
        }
      for (size_t k = 0; k < 3; ++k)
        rgb[3 * size_t(row * out.width + col) + k] = float(std::round(sum[k] / n));
    }
  return rgb;
}

void print(const char* name, const Metrics& m) {
  std::printf(
      "%-9s label %.4f  excluded %llu  coherence %.0f  distinct %.4f  max share %.5f  "
      "worst histogram %.3f",
      name, m.label_consistency, (unsigned long long)m.excluded_pixels, m.coherence,
      m.distinct_source_fraction, m.max_source_share, m.worst_histogram_distance);
  for (const auto& [label, d] : m.histogram_distance) std::printf("  [%d] %.3f", label, d);
  std::printf("\n");
}

struct EbsynthRun {
  Timed time;
  std::vector<int32_t> source;  // exemplar pixel per output pixel (its nearest-neighbour field)
  std::vector<float> rgb;       // its votes' colours
};

// ebsynth on the fixture's side x side window, on `threads` OpenMP threads.
EbsynthRun run_ebsynth(const Exemplar& e, int side, int threads) {
  EbsynthRun r;
  const int channels = zion_params().at("classes").get<int>() + 1;
  std::vector<uint8_t> style(e.rgb.size());
  for (size_t i = 0; i < style.size(); ++i) style[i] = uint8_t(e.rgb[i]);
  std::vector<uint8_t> source_guide = one_hot(e.labels, &e.excluded, channels);
  std::vector<uint8_t> target_guide = one_hot(zion_labels({0, 0, side, side}), nullptr, channels);
  std::vector<float> style_weights(3, 1.0f / 3), guide_weights(size_t(channels), 1.0f / channels);
  constexpr int kPatch = 5;
  int levels = 0;  // as ebsynth's command line: while the smaller image is >= 2 patches + 1
  while (std::min({e.width, e.height, side}) >> levels >= 2 * kPatch + 1) ++levels;
  std::vector<int> search_vote(size_t(levels), 6), patch_match(size_t(levels), 4),
      stop(size_t(levels), 5);
  std::vector<int> nnf(size_t(side) * size_t(side) * 2);
  std::vector<uint8_t> image(size_t(side) * size_t(side) * 3);
  omp_set_num_threads(threads);
  r.time = timed([&] {
    ebsynthRun(EBSYNTH_BACKEND_CPU, 3, channels, e.width, e.height, style.data(),
               source_guide.data(), side, side, target_guide.data(), nullptr, style_weights.data(),
               guide_weights.data(), 3500.0f, kPatch, EBSYNTH_VOTEMODE_PLAIN, levels,
               search_vote.data(), patch_match.data(), stop.data(), 0, nnf.data(), image.data());
  });
  r.source.resize(nnf.size() / 2);
  for (size_t i = 0; i < r.source.size(); ++i) r.source[i] = nnf[2 * i + 1] * e.width + nnf[2 * i];
  r.rgb.assign(image.begin(), image.end());
  return r;
}

int run(int side, int threads, int step, const SynthesisParams& params, bool with_ebsynth) {
  const PixelRect out{0, 0, side, side};
  const double mp = double(side) * side / 1e6;
  std::shared_ptr<const TransferExemplar> t;
  const Timed analysis = timed([&] { t = zion_exemplar(); });
  const Exemplar e = copied_exemplar(t->pyramid.levels[0]);

  std::vector<int32_t> ours;
  const Timed ours_time = timed([&] { ours = synthesize_tiles(*t, out, 256, threads, params); });
  std::vector<float> ours_rgb(ours.size() * 3);
  for (size_t i = 0; i < ours.size(); ++i)
    for (size_t k = 0; k < 3; ++k) ours_rgb[3 * i + k] = e.rgb[3 * size_t(ours[i]) + k];

  std::printf("output %d x %d (%.3f MP), exemplar %d x %d, %d threads\n", side, side, mp, e.width,
              e.height, threads);
  std::printf("exemplar analysis (ours, once): CPU %.1f s, wall %.1f s\n", analysis.cpu,
              analysis.wall);
  std::printf("ours:    CPU %.1f s (%.2f s/MP), wall %.1f s (%.2f s/MP)\n", ours_time.cpu,
              ours_time.cpu / mp, ours_time.wall, ours_time.wall / mp);
  const Metrics ours_m = metrics(e, tally(e, assessed(out, ours, ours_rgb), out, step));
  const Metrics averaged_m =
      metrics(e, tally(e, assessed(out, ours, plain_vote(e, out, ours)), out, step));
  std::printf("ours with vote radius %d; ours+mean: its colours replaced by ebsynth's plain vote\n",
              params.vote_radius);
  print("ours", ours_m);
  print("ours+mean", averaged_m);
  if (!with_ebsynth) return 0;
  const EbsynthRun ebsynth = run_ebsynth(e, side, threads);
  std::printf("ebsynth: CPU %.1f s (%.2f s/MP), wall %.1f s (%.2f s/MP)\n", ebsynth.time.cpu,
              ebsynth.time.cpu / mp, ebsynth.time.wall, ebsynth.time.wall / mp);
  std::printf("ebsynth / ours: CPU %.2fx, wall %.2fx\n", ebsynth.time.cpu / ours_time.cpu,
              ebsynth.time.wall / ours_time.wall);
  const Metrics ebsynth_m =
      metrics(e, tally(e, assessed(out, ebsynth.source, ebsynth.rgb), out, step));
  print("ebsynth", ebsynth_m);
  std::printf("coherence ours / ebsynth: %.2f, ours+mean / ebsynth: %.2f\n",
              ours_m.coherence / ebsynth_m.coherence, averaged_m.coherence / ebsynth_m.coherence);
  return 0;
}

}  // namespace
}  // namespace maquette::synthesis::bench

int main(int argc, char** argv) {
  const int side = argc > 1 ? std::stoi(argv[1]) : 512;
  const int threads = argc > 2 ? std::stoi(argv[2]) : 2;
  const int step = argc > 3 ? std::stoi(argv[3]) : 2;
  if (step < 1) {
    std::fprintf(stderr, "synthesis_ebsynth_compare: coherence step %d: must be >= 1\n", step);
    return 1;
  }
  // The weights: the schema's defaults, overridden by argument 5.
  const nlohmann::json schema = maquette::synthesis::synthesis_params_schema();
  const nlohmann::json given = argc > 5 ? nlohmann::json::parse(argv[5]) : nlohmann::json::object();
  nlohmann::json weights;
  for (const auto& [key, value] : schema.items()) weights[key] = given.value(key, value["default"]);
  for (const auto& [key, value] : given.items())
    if (!schema.contains(key)) {
      std::fprintf(stderr, "synthesis_ebsynth_compare: params: no weight \"%s\"\n", key.c_str());
      return 1;
    }
  maquette::synthesis::SynthesisParams params = maquette::synthesis::synthesis_params(weights);
  if (argc > 4) params.vote_radius = std::stoi(argv[4]);
  if (params.vote_radius < 0 || params.vote_radius > maquette::synthesis::kVoteRadius) {
    std::fprintf(stderr, "synthesis_ebsynth_compare: vote %d: must be 0 .. %d\n",
                 params.vote_radius, maquette::synthesis::kVoteRadius);
    return 1;
  }
  const bool with_ebsynth = !(argc > 6 && std::string(argv[6]) == "ours");
  return maquette::synthesis::bench::run(side, threads, step, params, with_ebsynth);
}
