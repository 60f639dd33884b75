#include "layer_values.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.h"
#include "masked_pyramid.h"

namespace maquette::synthesis {

ClassChannels class_channels(const PatchImage& labels, const std::vector<uint8_t>& hole) {
  if (labels.channels != 1) {
    throw Error("class_channels: a class raster has 1 channel, not " +
                std::to_string(labels.channels));
  }
  ClassChannels out;
  for (size_t i = 0; i < hole.size(); ++i) {
    if (hole[i] == 0 && !std::isnan(labels.values[i])) out.classes.push_back(labels.values[i]);
  }
  std::sort(out.classes.begin(), out.classes.end());
  out.classes.erase(std::unique(out.classes.begin(), out.classes.end()), out.classes.end());
  if (out.classes.empty()) throw Error("class_channels: no class outside the hole");
  const int k = int(out.classes.size());
  out.one_hot = PatchImage(labels.width, labels.height, k);
  for (size_t i = 0; i < hole.size(); ++i) {
    float* channels = out.one_hot.values.data() + i * k;
    const float label = labels.values[i];
    if (hole[i] != 0) continue;
    if (std::isnan(label)) {
      std::fill_n(channels, k, NAN);
      continue;
    }
    const auto at = std::lower_bound(out.classes.begin(), out.classes.end(), label);
    channels[at - out.classes.begin()] = 1;
  }
  return out;
}

PatchImage class_labels(const PatchImage& one_hot, const std::vector<float>& classes) {
  PatchImage labels(one_hot.width, one_hot.height, 1);
  const int k = one_hot.channels;
  for (size_t i = 0; i < labels.values.size(); ++i) {
    const float* channels = one_hot.values.data() + i * k;
    labels.values[i] = std::isnan(channels[0])
                           ? NAN
                           : classes[std::max_element(channels, channels + k) - channels];
  }
  return labels;
}

void snap_to_mode(float* channels, int count) {
  if (std::isnan(channels[0])) return;
  const auto mode = std::max_element(channels, channels + count) - channels;
  for (int i = 0; i < count; ++i) channels[i] = i == mode ? 1.0f : 0.0f;
}

PatchImage height_trend(const PatchImage& heights, const std::vector<uint8_t>& unknown,
                        int levels) {
  auto pyramid = masked_pyramid(MaskedImage{heights, unknown}, levels);
  PatchImage trend = std::move(pyramid.back().image);
  fill_by_diffusion(trend, pyramid.back().unknown);
  for (int l = levels - 2; l >= 0; --l) {
    const PatchImage& finer = pyramid[size_t(l)].image;
    PatchImage upsampled(finer.width, finer.height, finer.channels);
    upsample_into(trend, std::vector<uint8_t>(size_t(finer.width) * finer.height, 1), upsampled);
    trend = std::move(upsampled);
  }
  return trend;
}

}  // namespace maquette::synthesis
