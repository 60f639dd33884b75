#include "harmonize.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>

#include "../texture/colour.h"
#include "core/error.h"

namespace maquette::synthesis {
namespace {

using Lab = std::array<double, 3>;

// The CIELAB colour of sRGB (0..255 a component) and back (clamped to 0..255).
Lab lab_of(const float* rgb) { return texture::srgb_to_lab(rgb[0], rgb[1], rgb[2]); }

void rgb_of(const Lab& lab, float* rgb) {
  const Lab srgb = texture::lab_to_srgb(lab);
  for (size_t c = 0; c < 3; ++c) rgb[c] = float(srgb[c]);
}

// The CIELAB colours of each label's allowed pixels of `e`, with the pixels' indices.
struct LabelColours {
  std::vector<size_t> pixels;
  std::vector<Lab> lab;
};

std::map<uint8_t, LabelColours> colours_by_label(const Exemplar& e) {
  std::map<uint8_t, LabelColours> out;
  for (size_t i = 0; i < e.labels.size(); ++i)
    if (!e.excluded[i]) {
      LabelColours& l = out[e.labels[i]];
      l.pixels.push_back(i);
      l.lab.push_back(lab_of(&e.rgb[3 * i]));
    }
  return out;
}

std::array<double, 2> mean_sd(const std::vector<Lab>& lab, int channel) {
  double sum = 0, sum2 = 0;
  for (const Lab& v : lab) sum += v[size_t(channel)];
  const double mean = sum / double(lab.size());
  for (const Lab& v : lab) sum2 += (v[size_t(channel)] - mean) * (v[size_t(channel)] - mean);
  return {mean, std::sqrt(sum2 / double(lab.size()))};
}

// `moved`'s channel values matched to `reference`'s (harmonize's contract).
void match_channel(std::vector<Lab>& moved, const std::vector<Lab>& reference, int channel,
                   Harmonization how) {
  const size_t k = size_t(channel);
  if (how == Harmonization::Reinhard) {
    const auto [m0, s0] = mean_sd(reference, channel);
    const auto [m, s] = mean_sd(moved, channel);
    for (Lab& v : moved) v[k] = (s > 0 ? (v[k] - m) * s0 / s : 0.0) + m0;
    return;
  }
  std::vector<double> sorted(reference.size());
  for (size_t i = 0; i < reference.size(); ++i) sorted[i] = reference[i][k];
  std::sort(sorted.begin(), sorted.end());
  std::vector<size_t> order(moved.size());
  std::iota(order.begin(), order.end(), size_t(0));
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return moved[a][k] < moved[b][k]; });
  const double n = double(moved.size()), n0 = double(sorted.size());
  for (size_t r = 0; r < order.size(); ++r)
    moved[order[r]][k] = sorted[size_t(std::floor((double(r) + 0.5) * n0 / n))];
}

}  // namespace

Harmonization parse_harmonization(const std::string& name, const std::string& where) {
  if (name == "none") return Harmonization::None;
  if (name == "reinhard") return Harmonization::Reinhard;
  if (name == "histogram") return Harmonization::Histogram;
  throw Error(where + ": '" + name + "' is not one of none, reinhard, histogram");
}

void harmonize(std::vector<Exemplar>& parts, Harmonization how) {
  if (how == Harmonization::None || parts.size() < 2) return;
  const auto reference = colours_by_label(parts[0]);
  for (size_t p = 1; p < parts.size(); ++p) {
    Exemplar& e = parts[p];
    for (auto& [label, colours] : colours_by_label(e)) {
      const auto ref = reference.find(label);
      if (ref == reference.end()) continue;
      for (int c = 0; c < 3; ++c) match_channel(colours.lab, ref->second.lab, c, how);
      for (size_t j = 0; j < colours.pixels.size(); ++j)
        rgb_of(colours.lab[j], &e.rgb[3 * colours.pixels[j]]);
    }
  }
}

}  // namespace maquette::synthesis
