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
// smoothing of a mean vote is measured apart from the copy's coherence. The arguments: kUsage
// below (printed with every argument error and by --help).
#include <omp.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <map>
#include <optional>
#include <string>

#include "core/error.h"
#include "core/whole_int.h"
#include "ebsynth.h"
#include "runtime/params_schema.h"
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

// The most distinct sources a copy of `labels` (target labels, row-major) can have with every
// pixel copied from a usable exemplar pixel of its label: the sum over labels of min(target
// pixels, usable exemplar pixels), as a fraction of the target pixels with a label.
double distinct_bound(const Exemplar& e, const std::vector<uint8_t>& labels) {
  std::map<uint8_t, std::array<int64_t, 2>> count;  // label -> target pixels, exemplar pixels
  for (const uint8_t l : labels)
    if (l != kUnknownLabel) ++count[l][0];
  for (size_t i = 0; i < e.labels.size(); ++i)
    if (!e.excluded[i]) ++count[e.labels[i]][1];
  int64_t bound = 0, target = 0;
  for (const auto& [label, n] : count) {
    bound += std::min(n[0], n[1]);
    target += n[0];
    std::printf("  class %d: %lld target pixels, %lld usable exemplar pixels\n", int(label),
                (long long)n[0], (long long)n[1]);
  }
  if (target == 0) throw maquette::Error("the window holds no pixel of a land-cover class");
  return double(bound) / double(target);
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
EbsynthRun run_ebsynth(const Exemplar& e, int side, int threads, const nlohmann::json& classes) {
  EbsynthRun r;
  const int channels = *std::max_element(e.labels.begin(), e.labels.end()) + 2;
  std::vector<uint8_t> style(e.rgb.size());
  for (size_t i = 0; i < style.size(); ++i) style[i] = uint8_t(e.rgb[i]);
  std::vector<uint8_t> source_guide = one_hot(e.labels, &e.excluded, channels);
  std::vector<uint8_t> target_guide =
      one_hot(zion_labels({0, 0, side, side}, classes), nullptr, channels);
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

int run(int side, int threads, int step, const SynthesisParams& params,
        const nlohmann::json& classes, const nlohmann::json& painting_classes, bool with_ebsynth) {
  const PixelRect out{0, 0, side, side};
  const double mp = double(side) * side / 1e6;
  std::shared_ptr<const TransferExemplar> t;
  const Timed analysis = timed([&] { t = zion_exemplar(classes, painting_classes); });
  const Exemplar e = copied_exemplar(t->pyramid.levels[0]);

  std::vector<int32_t> ours;
  const Timed ours_time =
      timed([&] { ours = synthesize_tiles(*t, out, 256, threads, params, classes); });
  std::vector<float> ours_rgb(ours.size() * 3);
  for (size_t i = 0; i < ours.size(); ++i)
    for (size_t k = 0; k < 3; ++k) ours_rgb[3 * i + k] = e.rgb[3 * size_t(ours[i]) + k];

  std::printf("output %d x %d (%.3f MP), exemplar %d x %d, %d threads\n", side, side, mp, e.width,
              e.height, threads);
  std::printf("exemplar analysis (ours, once): CPU %.1f s, wall %.1f s\n", analysis.cpu,
              analysis.wall);
  std::printf("ours:    CPU %.1f s (%.2f s/MP), wall %.1f s (%.2f s/MP)\n", ours_time.cpu,
              ours_time.cpu / mp, ours_time.wall, ours_time.wall / mp);
  const Metrics ours_m = metrics(e, tally(e, assessed(out, ours, ours_rgb, classes), out, step));
  const Metrics averaged_m =
      metrics(e, tally(e, assessed(out, ours, plain_vote(e, out, ours), classes), out, step));
  std::printf("ours with vote radius %d; ours+mean: its colours replaced by ebsynth's plain vote\n",
              params.vote_radius);
  std::printf("the window's classes (painting classes through the class table):\n");
  const double bound = distinct_bound(e, zion_labels(out, classes));
  std::printf("distinct-source bound with label consistency 1: %.4f\n", bound);
  print("ours", ours_m);
  print("ours+mean", averaged_m);
  if (!with_ebsynth) return 0;
  const EbsynthRun ebsynth = run_ebsynth(e, side, threads, classes);
  std::printf("ebsynth: CPU %.1f s (%.2f s/MP), wall %.1f s (%.2f s/MP)\n", ebsynth.time.cpu,
              ebsynth.time.cpu / mp, ebsynth.time.wall, ebsynth.time.wall / mp);
  std::printf("ebsynth / ours: CPU %.2fx, wall %.2fx\n", ebsynth.time.cpu / ours_time.cpu,
              ebsynth.time.wall / ours_time.wall);
  const Metrics ebsynth_m =
      metrics(e, tally(e, assessed(out, ebsynth.source, ebsynth.rgb, classes), out, step));
  print("ebsynth", ebsynth_m);
  std::printf("coherence ours / ebsynth: %.2f, ours+mean / ebsynth: %.2f\n",
              ours_m.coherence / ebsynth_m.coherence, averaged_m.coherence / ebsynth_m.coherence);
  return 0;
}

}  // namespace
}  // namespace maquette::synthesis::bench

namespace {

constexpr const char* kProgram = "synthesis_ebsynth_compare";
constexpr const char* kUsage =
    R"(usage: synthesis_ebsynth_compare [side] [threads] [step] [vote] [params] [ours]
  side     the output window's side in pixels (512)
  threads  threads for both syntheses (2)
  step     the coherence measure's sample: every step-th column and row (2; >= 1)
  vote     our vote's radius, synthesis.transfer's "vote_radius" (its default, 1; 0 .. 2)
  params   a JSON object of synthesis.transfer's weights and choices ("w_spread", "w_usage",
           "coherence", "seed", ...: synthesis_params_schema(); the defaults otherwise),
           validated against that schema: an unknown key, or a value of the wrong type or out of
           range, is an error naming it; its "vote_radius" and `vote` are one setting, given
           twice with different values an error; "landcover_classes" replaces the fixture's
           class table (zion_fixture.h) for both syntheses and the measures; "labels" (a
           class image, e.g. examples/bruegel-harvesters-classes.geojson) replaces the 8 colour
           classes, with its "exclude_classes" ([] when absent)
  ours     skip ebsynth (a variant measured against an earlier run's ebsynth)
)";

// Argument `i` as an integer >= `min` (the whole argument: "2x" is refused), `fallback` when
// absent.
int int_argument(int argc, char** argv, int i, const char* name, int fallback, int min) {
  if (argc <= i) return fallback;
  const std::string text = argv[i];
  const std::optional<int> value = maquette::whole_int<int>(text);
  if (!value || *value < min)
    throw maquette::Error(std::string(kProgram) + ": " + name + " '" + text +
                          "': expected an integer >= " + std::to_string(min));
  return *value;
}

// The synthesis's params: argument 5 (a JSON object) with argument 4 as its "vote_radius",
// validated against synthesis_params_schema() and the class table's schema, the defaults filled
// in (the fixture's class table among them).
nlohmann::json synthesis_weights(int argc, char** argv) {
  nlohmann::json given = nlohmann::json::object();
  if (argc > 5) {
    given = nlohmann::json::parse(argv[5], nullptr, false);
    if (!given.is_object())
      throw maquette::Error(std::string(kProgram) + ": params '" + argv[5] +
                            "': expected a JSON object of synthesis.transfer's weights");
  }
  if (argc > 4) {
    const nlohmann::json vote = int_argument(argc, argv, 4, "vote", 0, 0);
    if (given.contains("vote_radius") && given.at("vote_radius") != vote)
      throw maquette::Error(std::string(kProgram) + ": vote " + vote.dump() +
                            " and params.vote_radius " + given.at("vote_radius").dump() +
                            " disagree: give the vote's radius once");
    given["vote_radius"] = vote;
  }
  nlohmann::json properties = maquette::synthesis::synthesis_params_schema();
  properties["landcover_classes"] =
      maquette::synthesis::exemplar_params_schema().at("landcover_classes");
  properties["landcover_classes"]["default"] = maquette::synthesis::bench::zion_classes();
  for (const char* key : {"labels", "exclude_classes"})
    properties[key] = maquette::synthesis::exemplar_params_schema().at(key);
  properties["exclude_classes"].erase("default");
  const nlohmann::json schema = {
      {"type", "object"}, {"properties", properties}, {"additionalProperties", false}};
  return maquette::validate_params(schema, given, kProgram);
}

}  // namespace

int main(int argc, char** argv) try {
  if (argc > 1 && (std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h")) {
    std::fputs(kUsage, stdout);
    return 0;
  }
  const int side = int_argument(argc, argv, 1, "side", 512, 1);
  const int threads = int_argument(argc, argv, 2, "threads", 2, 1);
  const int step = int_argument(argc, argv, 3, "step", 2, 1);
  const nlohmann::json weights = synthesis_weights(argc, argv);
  const auto params = maquette::synthesis::synthesis_params(weights);
  const bool with_ebsynth = !(argc > 6 && std::string(argv[6]) == "ours");
  if (argc > 6 && with_ebsynth)
    throw maquette::Error(std::string(kProgram) + ": argument 6 '" + argv[6] +
                          "': expected \"ours\" (our transfer alone)");
  if (argc > 7)
    throw maquette::Error(std::string(kProgram) +
                          ": too many arguments: side threads step vote params [ours]");
  if (weights.contains("exclude_classes") && !weights.contains("labels"))
    throw maquette::Error(std::string(kProgram) +
                          ": params.exclude_classes without params.labels: the 8 colour classes "
                          "exclude their class 0");
  nlohmann::json painting_classes = nlohmann::json::object();
  for (const char* key : {"labels", "exclude_classes"})
    if (weights.contains(key)) painting_classes[key] = weights.at(key);
  return maquette::synthesis::bench::run(
      side, threads, step, params, weights.at("landcover_classes"), painting_classes, with_ebsynth);
} catch (const std::exception& e) {
  std::fprintf(stderr, "%s\n%s", e.what(), kUsage);
  return 1;
}
