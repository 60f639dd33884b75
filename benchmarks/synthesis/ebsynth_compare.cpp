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
// smoothing of a mean vote is measured apart from the copy's coherence. Given several seeds,
// ours is run with each (ebsynth once: its randomness has no seed) and each measure's minimum,
// median and maximum printed, with each class's histogram distance beside the distance a random
// draw of as many of the class's exemplar pixels shows, single, in 5 x 5 squares, or as the
// class's own connected pieces in the window each copied whole (the noise of the measure itself
// at that class's size and shape). The arguments: kUsage below (printed with every
// argument error and by --help).
#include <omp.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <map>
#include <optional>
#include <random>
#include <set>
#include <string>

#include "core/error.h"
#include "core/whole_int.h"
#include "ebsynth.h"
#include "gdal/image_file.h"
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

// Label -> its target pixels in `labels` (row-major) and its usable exemplar pixels.
using ClassPixels = std::map<uint8_t, std::array<int64_t, 2>>;

ClassPixels class_pixels(const Exemplar& e, const std::vector<uint8_t>& labels) {
  ClassPixels count;
  for (const uint8_t l : labels)
    if (l != kUnknownLabel) ++count[l][0];
  for (size_t i = 0; i < e.labels.size(); ++i)
    if (!e.excluded[i]) ++count[e.labels[i]][1];
  return count;
}

// The most distinct sources a copy can have with every pixel copied from a usable exemplar pixel
// of its label: the sum over labels of min(target pixels, usable exemplar pixels), as a fraction
// of the target pixels with a label.
double distinct_bound(const Exemplar& e, const ClassPixels& count) {
  std::map<uint8_t, uint64_t> targets;
  uint64_t target = 0;
  for (const auto& [label, n] : count) {
    if (n[0] > 0) targets[label] = uint64_t(n[0]);
    target += uint64_t(n[0]);
    std::printf("  class %d: %lld target pixels, %lld usable exemplar pixels\n", int(label),
                (long long)n[0], (long long)n[1]);
  }
  if (target == 0) throw maquette::Error("the window holds no pixel of a land-cover class");
  return double(label_keeping_sources(e, targets, 0)) / double(target);
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

// Minimum, median (the mean of the middle two for an even count) and maximum; `v` not empty.
std::array<double, 3> spread(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return {v.front(), (v[(n - 1) / 2] + v[n / 2]) / 2, v.back()};
}

void print_spread(const char* name, const std::vector<double>& v, const char* format) {
  const auto [low, median, high] = spread(v);
  std::printf("  %-16s min ", name);
  std::printf(format, low);
  std::printf("  median ");
  std::printf(format, median);
  std::printf("  max ");
  std::printf(format, high);
  std::printf("\n");
}

// A set of pixels copied whole: offsets from its bounding box's top-left corner.
using Shape = std::vector<std::array<int, 2>>;

Shape square(int side) {
  Shape s;
  for (int dy = 0; dy < side; ++dy)
    for (int dx = 0; dx < side; ++dx) s.push_back({dx, dy});
  return s;
}

// The target's pixels of `label` in the side x side window `labels` as 8-connected pieces.
std::vector<Shape> pieces(const std::vector<uint8_t>& labels, int side, uint8_t label) {
  std::vector<Shape> out;
  std::vector<uint8_t> seen(labels.size(), 0);
  for (size_t start = 0; start < labels.size(); ++start) {
    if (labels[start] != label || seen[start]) continue;
    std::vector<std::array<int, 2>> piece, stack{{int(start) % side, int(start) / side}};
    seen[start] = 1;
    while (!stack.empty()) {
      const auto [x, y] = stack.back();
      stack.pop_back();
      piece.push_back({x, y});
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int nx = x + dx, ny = y + dy;
          const size_t i = size_t(ny) * size_t(side) + size_t(nx);
          if (nx < 0 || ny < 0 || nx >= side || ny >= side || labels[i] != label || seen[i])
            continue;
          seen[i] = 1;
          stack.push_back({nx, ny});
        }
    }
    int x0 = side, y0 = side;
    for (const auto& [x, y] : piece) x0 = std::min(x0, x), y0 = std::min(y0, y);
    for (auto& [x, y] : piece) x -= x0, y -= y0;
    out.push_back(std::move(piece));
  }
  return out;
}

// The total variation between the histogram of `label`'s usable exemplar pixels and that of
// `shapes`, each copied whole from a place of the exemplar drawn uniformly among those where
// every pixel of it is a usable pixel of the label (with replacement; a shape that fits nowhere
// is copied as 5 x 5 squares of as many pixels), over kDraws draws: the median and largest. The
// sampling noise of the measure for a copy made of such pieces: single pixels (independent
// draws), 5 x 5 squares (the measure's patches), or the class's own connected pieces in the
// target (a copy coherent over each piece, as a field copied from one place of the painting).
constexpr int kDraws = 200;

std::array<double, 2> shape_draw_distance(const Exemplar& e, uint8_t label,
                                          const std::vector<Shape>& shapes) {
  const auto usable = [&](int x, int y) {
    const size_t i = size_t(y) * size_t(e.width) + size_t(x);
    return e.labels[i] == label && !e.excluded[i];
  };
  const auto places_of = [&](const Shape& shape) {
    int w = 0, h = 0;
    for (const auto& [x, y] : shape) w = std::max(w, x + 1), h = std::max(h, y + 1);
    std::vector<std::array<int, 2>> places;  // top-left corners
    for (int y = 0; y + h <= e.height; ++y)
      for (int x = 0; x + w <= e.width; ++x)
        if (std::all_of(shape.begin(), shape.end(),
                        [&](const auto& p) { return usable(x + p[0], y + p[1]); }))
          places.push_back({x, y});
    return places;
  };
  // Each shape with its places, the shapes that fit nowhere replaced by squares.
  const Shape fallback = square(kCoherenceSide);
  std::vector<std::pair<const Shape*, const std::vector<std::array<int, 2>>*>> drawn_shapes;
  std::map<const Shape*, std::vector<std::array<int, 2>>> places;
  std::map<size_t, std::vector<std::array<int, 2>>> by_size;  // squares: one list per side
  for (const Shape& shape : shapes) {
    auto& p = shape.size() == 1 || shape == fallback ? by_size[shape.size()] : places[&shape];
    if (p.empty()) p = places_of(shape);
    if (!p.empty()) {
      drawn_shapes.emplace_back(&shape, &p);
      continue;
    }
    auto& q = by_size[fallback.size()];
    if (q.empty()) q = places_of(fallback);
    if (q.empty()) return {1, 1};
    for (size_t n = 0; n < (shape.size() + fallback.size() - 1) / fallback.size(); ++n)
      drawn_shapes.emplace_back(&fallback, &q);
  }
  const std::vector<uint64_t> exemplar = exemplar_histogram(e, label);
  std::mt19937_64 random(label);
  std::vector<double> d(kDraws);
  for (double& distance : d) {
    std::vector<uint64_t> drawn(exemplar.size(), 0);
    for (const auto& [shape, at] : drawn_shapes) {
      const auto [x, y] = (*at)[std::uniform_int_distribution<size_t>(0, at->size() - 1)(random)];
      for (const auto& [dx, dy] : *shape) {
        const size_t i = size_t(y + dy) * size_t(e.width) + size_t(x + dx);
        ++drawn[size_t(histogram_bin(e.rgb[3 * i], e.rgb[3 * i + 1], e.rgb[3 * i + 2]))];
      }
    }
    distance = total_variation(drawn, exemplar);
  }
  const auto s = spread(d);  // min, median, max
  return {s[1], s[2]};
}

// As many whole side x side squares as cover `pixels` (at least one).
std::vector<Shape> squares(int64_t pixels, int side) {
  return std::vector<Shape>(
      size_t(std::max<int64_t>(1, (pixels + side * side / 2) / (side * side))), square(side));
}

// Ours' measures over the seeds: each measure's spread, and each class's histogram distance's
// beside random draws' (shape_draw_distance) of its target pixel count, single pixels and 5 x 5
// squares, and of its pieces in the target window (`labels`, side x side).
void print_seeds(const Exemplar& e, const std::vector<Metrics>& runs, const ClassPixels& count,
                 const std::vector<uint8_t>& labels, int side) {
  const auto of = [&](auto measure) {
    std::vector<double> v;
    for (const Metrics& m : runs) v.push_back(double(measure(m)));
    return v;
  };
  std::printf("ours over %zu seeds:\n", runs.size());
  print_spread("label", of([](const Metrics& m) { return m.label_consistency; }), "%.4f");
  print_spread("excluded", of([](const Metrics& m) { return m.excluded_pixels; }), "%.0f");
  print_spread("coherence", of([](const Metrics& m) { return m.coherence; }), "%.0f");
  print_spread("distinct", of([](const Metrics& m) { return m.distinct_source_fraction; }), "%.4f");
  print_spread("max share", of([](const Metrics& m) { return m.max_source_share; }), "%.5f");
  print_spread("worst histogram", of([](const Metrics& m) { return m.worst_histogram_distance; }),
               "%.3f");
  for (const auto& [label, n] : count) {
    if (n[0] == 0) continue;
    const auto [low, median, high] =
        spread(of([label](const Metrics& m) { return m.histogram_distance.at(label); }));
    const auto pixel = shape_draw_distance(e, label, squares(n[0], 1));
    const auto patch = shape_draw_distance(e, label, squares(n[0], kCoherenceSide));
    const std::vector<Shape> own = pieces(labels, side, label);
    const auto piece = shape_draw_distance(e, label, own);
    size_t largest = 0;
    for (const Shape& p : own) largest = std::max(largest, p.size());
    std::printf(
        "  histogram [%d] (%lld target pixels): min %.3f  median %.3f  max %.3f; as many of its "
        "exemplar pixels drawn at random (median, max of %d draws): single %.3f, %.3f; in %d x "
        "%d squares %.3f, %.3f; as its %zu pieces in the window (the largest %zu pixels) %.3f, "
        "%.3f\n",
        int(label), (long long)n[0], low, median, high, kDraws, pixel[0], pixel[1], kCoherenceSide,
        kCoherenceSide, patch[0], patch[1], own.size(), largest, piece[0], piece[1]);
  }
}

// Per class, the distinct sources copied against the class's bound (min of its target pixels and
// its usable exemplar pixels, as `count` has them: distinct_bound), and with several paintings each
// painting's share of the class's usable exemplar pixels and of the output pixels copied, the
// distance of the pixels copied from each painting to that painting's pixels of the class, and the
// output's distance to the paintings' histograms mixed in the output's shares (what the measure
// would be if each painting's share were as copied): so a histogram off because of the paintings'
// shares is told from one off within a painting.
void print_class_sources(const Exemplar& e, const TransferExemplar& t,
                         const std::vector<uint8_t>& labels, const ClassPixels& count,
                         const std::vector<int32_t>& source) {
  const size_t paintings = t.parts.size();
  const auto painting = [&](int32_t s) { return size_t(t.source_of(s).exemplar); };
  const auto bin = [&](int32_t s) {
    return size_t(
        histogram_bin(e.rgb[3 * size_t(s)], e.rgb[3 * size_t(s) + 1], e.rgb[3 * size_t(s) + 2]));
  };
  using Histograms = std::vector<std::vector<uint64_t>>;  // per painting
  std::map<uint8_t, std::array<Histograms, 2>> h;         // label -> exemplar's, output's
  const auto of = [&](uint8_t label) -> std::array<Histograms, 2>& {
    auto [it, fresh] = h.try_emplace(label);
    if (fresh)
      for (Histograms& side : it->second)
        side.assign(paintings, std::vector<uint64_t>(kHistogramBins, 0));
    return it->second;
  };
  for (size_t i = 0; i < e.labels.size(); ++i)
    if (!e.excluded[i]) ++of(e.labels[i])[0][painting(int32_t(i))][bin(int32_t(i))];
  for (size_t i = 0; i < labels.size(); ++i)
    if (labels[i] != kUnknownLabel && source[i] >= 0)
      ++of(labels[i])[1][painting(source[i])][bin(source[i])];
  const auto total = [](const std::vector<uint64_t>& v) {
    uint64_t n = 0;
    for (const uint64_t c : v) n += c;
    return n;
  };
  for (const auto& [label, sides] : h) {
    const auto& [exemplar, output] = sides;
    const auto [targets, usable] = count.at(label);  // n[0], n[1] of distinct_bound
    if (targets == 0) continue;
    std::set<int32_t> distinct;
    for (size_t i = 0; i < labels.size(); ++i)
      if (labels[i] == label && source[i] >= 0) distinct.insert(source[i]);
    std::printf("    class %d: %zu distinct sources of at most %lld", int(label), distinct.size(),
                (long long)std::min(targets, usable));
    if (paintings < 2) {
      std::printf("\n");
      continue;
    }
    std::vector<double> mixed(kHistogramBins, 0), out(kHistogramBins, 0);
    for (size_t p = 0; p < paintings; ++p) {
      const uint64_t ne = total(exemplar[p]), no = total(output[p]);
      std::printf("  painting %zu exemplar %.3f output %.3f", p, double(ne) / double(usable),
                  double(no) / double(targets));
      if (no > 0) std::printf(" (distance %.3f)", total_variation(output[p], exemplar[p]));
      for (size_t b = 0; b < size_t(kHistogramBins); ++b) {
        out[b] += double(output[p][b]) / double(targets);
        if (ne > 0) mixed[b] += double(exemplar[p][b]) / double(ne) * double(no) / double(targets);
      }
    }
    std::printf("; at the output's shares %.3f\n", total_variation(out, mixed));
  }
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

// Ours with `seeds` seeds from params.seed on (and ebsynth once when `with_ebsynth`), each
// written to `picture` + seed + ".png" when `picture` is not empty.
int run(int side, int threads, int step, SynthesisParams params, const nlohmann::json& classes,
        const nlohmann::json& painting_classes, bool with_ebsynth, int seeds,
        const std::string& picture) {
  const PixelRect out{0, 0, side, side};
  const double mp = double(side) * side / 1e6;
  std::shared_ptr<const TransferExemplar> t;
  const Timed analysis = timed([&] { t = zion_exemplar(classes, painting_classes); });
  const Exemplar e = copied_exemplar(t->pyramid.levels[0]);

  std::printf("output %d x %d (%.3f MP), exemplar %d x %d, %d threads\n", side, side, mp, e.width,
              e.height, threads);
  std::printf("exemplar analysis (ours, once): CPU %.1f s, wall %.1f s\n", analysis.cpu,
              analysis.wall);
  std::printf("the window's classes (painting classes through the class table):\n");
  const std::vector<uint8_t> labels = zion_labels(out, classes);
  const ClassPixels count = class_pixels(e, labels);
  std::printf("distinct-source bound with label consistency 1: %.4f\n", distinct_bound(e, count));
  std::printf("ours with vote radius %d; ours+mean: its colours replaced by ebsynth's plain vote\n",
              params.vote_radius);
  std::vector<Metrics> ours_m, averaged_m;
  const uint64_t first_seed = params.seed;
  for (int i = 0; i < seeds; ++i) {
    params.seed = first_seed + uint64_t(i);
    std::vector<int32_t> ours;
    const Timed ours_time =
        timed([&] { ours = synthesize_tiles(*t, out, 256, threads, params, classes); });
    const std::vector<float> ours_rgb = source_colours(e, ours);
    std::printf("ours, seed %llu: CPU %.1f s (%.2f s/MP), wall %.1f s (%.2f s/MP)\n",
                (unsigned long long)params.seed, ours_time.cpu, ours_time.cpu / mp, ours_time.wall,
                ours_time.wall / mp);
    if (!picture.empty()) {
      std::vector<uint8_t> pixels(ours_rgb.size());
      for (size_t i = 0; i < pixels.size(); ++i)
        pixels[i] = uint8_t(std::clamp(std::lround(ours_rgb[i]), 0L, 255L));
      write_image(pixels, side, side, 3, {"PNG", {}},
                  picture + std::to_string(params.seed) + ".png");
    }
    ours_m.push_back(metrics(e, tally(e, assessed(out, ours, ours_rgb, classes), out, step)));
    averaged_m.push_back(
        metrics(e, tally(e, assessed(out, ours, plain_vote(e, out, ours), classes), out, step)));
    print("ours", ours_m.back());
    print("ours+mean", averaged_m.back());
    print_class_sources(e, *t, labels, count, ours);
    std::fflush(stdout);
  }
  if (seeds > 1) print_seeds(e, ours_m, count, labels, side);
  if (!with_ebsynth) {
    // ebsynth's coherence depends on the class table and the paintings (benchmarks/README.md,
    // "Synthesis", session 31): a ratio against a figure from another fixture says nothing.
    std::printf("ebsynth not run: no coherence ratio (run 'both' on the same fixture for it)\n");
    return 0;
  }
  const EbsynthRun ebsynth = run_ebsynth(e, side, threads, classes);
  std::printf("ebsynth: CPU %.1f s (%.2f s/MP), wall %.1f s (%.2f s/MP)\n", ebsynth.time.cpu,
              ebsynth.time.cpu / mp, ebsynth.time.wall, ebsynth.time.wall / mp);
  const Metrics ebsynth_m =
      metrics(e, tally(e, assessed(out, ebsynth.source, ebsynth.rgb, classes), out, step));
  print("ebsynth", ebsynth_m);
  const auto coherence = [](const std::vector<Metrics>& runs) {
    std::vector<double> v;
    for (const Metrics& m : runs) v.push_back(m.coherence);
    return spread(v)[1];
  };
  std::printf("coherence ours / ebsynth: %.2f, ours+mean / ebsynth: %.2f%s\n",
              coherence(ours_m) / ebsynth_m.coherence, coherence(averaged_m) / ebsynth_m.coherence,
              seeds > 1 ? " (ours' medians)" : "");
  return 0;
}

}  // namespace
}  // namespace maquette::synthesis::bench

namespace {

constexpr const char* kProgram = "synthesis_ebsynth_compare";
constexpr const char* kUsage =
    R"(usage: synthesis_ebsynth_compare [side] [threads] [step] [vote] [params] [ours|both] [seeds]
                                  [picture]
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
           classes, with its "exclude_classes" ([] when absent); "exemplars" (further paintings,
           synthesis.transfer's, searched with Bruegel's) with "harmonize" (reinhard)
  ours     skip ebsynth (a variant measured against an earlier run's ebsynth); both: run it
  seeds    run ours with this many seeds, params.seed (0) and on, and print each measure's
           min / median / max and each class's histogram distance beside a random draw's (1)
  picture  write each seed's output of ours to picture + seed + ".png" (none)
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
  return maquette::synthesis::bench::zion_weights(given, kProgram);
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
  const std::string which = argc > 6 ? argv[6] : "both";
  if (which != "ours" && which != "both")
    throw maquette::Error(std::string(kProgram) + ": argument 6 '" + which +
                          "': expected \"ours\" (our transfer alone) or \"both\"");
  const int seeds = int_argument(argc, argv, 7, "seeds", 1, 1);
  const std::string picture = argc > 8 ? argv[8] : "";
  if (argc > 9)
    throw maquette::Error(
        std::string(kProgram) +
        ": too many arguments: side threads step vote params [ours|both] [seeds] [picture]");
  if (weights.contains("exclude_classes") && !weights.contains("labels"))
    throw maquette::Error(std::string(kProgram) +
                          ": params.exclude_classes without params.labels: the 8 colour classes "
                          "exclude their class 0");
  return maquette::synthesis::bench::run(
      side, threads, step, params, weights.at("landcover_classes"),
      maquette::synthesis::bench::painting_classes(weights), which == "both", seeds, picture);
} catch (const std::exception& e) {
  std::fprintf(stderr, "%s\n%s", e.what(), kUsage);
  return 1;
}
