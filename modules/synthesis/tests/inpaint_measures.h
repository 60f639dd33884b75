// The inpainting tests' measures of a completed image against its original, the same function for
// every fill compared (ours and OpenCV xphoto's): the bidirectional-similarity energy (Simakov et
// al. 2008) by an exact brute-force patch search (OpenCV's BFMatcher, independent of PatchMatch),
// and the mean gradient magnitude along the hole's edge.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <opencv2/core.hpp>
#include <opencv2/features2d.hpp>
#include <vector>

#include "../masked_pyramid.h"

namespace maquette::synthesis::test {

// 8-bit RGB image as floats.
inline PatchImage to_patch_image(const cv::Mat& rgb) {
  PatchImage image(rgb.cols, rgb.rows, 3);
  for (int y = 0; y < rgb.rows; ++y) {
    for (int x = 0; x < rgb.cols; ++x) {
      const auto& p = rgb.at<cv::Vec3b>(y, x);
      for (int c = 0; c < 3; ++c) image.pixel(x, y)[c] = p[c];
    }
  }
  return image;
}

// Rounded to 8 bits, as the operator stores imagery.
inline cv::Mat to_mat(const PatchImage& image) {
  cv::Mat rgb(image.height, image.width, CV_8UC3);
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      for (int c = 0; c < 3; ++c) {
        rgb.at<cv::Vec3b>(y, x)[c] = cv::saturate_cast<uint8_t>(std::lround(image.pixel(x, y)[c]));
      }
    }
  }
  return rgb;
}

// The patch (side `patch`) centred at each of `centres` (x, y) as one float row.
inline cv::Mat patch_rows(const cv::Mat& rgb, const std::vector<cv::Point>& centres, int patch) {
  const int half = patch / 2;
  cv::Mat rows(int(centres.size()), patch * patch * 3, CV_32F);
  for (int r = 0; r < rows.rows; ++r) {
    float* out = rows.ptr<float>(r);
    for (int dy = -half; dy <= half; ++dy) {
      for (int dx = -half; dx <= half; ++dx) {
        const auto& p = rgb.at<cv::Vec3b>(centres[r].y + dy, centres[r].x + dx);
        for (int c = 0; c < 3; ++c) *out++ = p[c];
      }
    }
  }
  return rows;
}

// Mean SSD per patch (7 x 7 x 3 values, 0..255) of: coherence, each patch of `completed` that
// overlaps the hole grown by `band` to its nearest patch of `original` wholly outside it;
// completeness, each such original patch within one patch of the grown hole to its nearest patch
// of `completed` overlapping it. Their sum is the energy: lower is more similar both ways.
struct Energy {
  double coherence = 0, completeness = 0;
  double total() const { return coherence + completeness; }
};

inline Energy bidirectional_energy(const cv::Mat& original, const cv::Mat& completed,
                                   const std::vector<uint8_t>& hole, int band, int patch = 7) {
  const int w = original.cols, h = original.rows, half = patch / 2;
  const auto distance = chessboard_distance(hole, w, h);
  std::vector<cv::Point> inside, outside, near_outside;
  for (int y = half; y < h - half; ++y) {
    for (int x = half; x < w - half; ++x) {
      const int d = distance[size_t(y) * w + x];
      if (d <= band + half) {
        inside.emplace_back(x, y);
      } else {
        outside.emplace_back(x, y);
        if (d <= band + half + patch) near_outside.emplace_back(x, y);
      }
    }
  }
  const cv::Mat targets = patch_rows(completed, inside, patch);
  const auto mean_nearest = [](const cv::Mat& queries, const cv::Mat& train) {
    std::vector<cv::DMatch> matches;
    cv::BFMatcher(cv::NORM_L2SQR).match(queries, train, matches);
    double sum = 0;
    for (const auto& m : matches) sum += m.distance;
    return sum / double(matches.size());
  };
  return {mean_nearest(targets, patch_rows(original, outside, patch)),
          mean_nearest(patch_rows(original, near_outside, patch), targets)};
}

// The mean gradient magnitude (central differences of the channels' mean) over the pixels on
// either side of the hole's edge (a pixel with a 4-neighbour across it).
inline double edge_gradient(const cv::Mat& rgb, const std::vector<uint8_t>& hole) {
  const int w = rgb.cols, h = rgb.rows;
  const auto grey = [&](int x, int y) {
    const auto& p = rgb.at<cv::Vec3b>(y, x);
    return (double(p[0]) + p[1] + p[2]) / 3;
  };
  double sum = 0;
  size_t count = 0;
  for (int y = 1; y < h - 1; ++y) {
    for (int x = 1; x < w - 1; ++x) {
      const uint8_t m = hole[size_t(y) * w + x];
      const bool edge = hole[size_t(y) * w + x - 1] != m || hole[size_t(y) * w + x + 1] != m ||
                        hole[size_t(y - 1) * w + x] != m || hole[size_t(y + 1) * w + x] != m;
      if (!edge) continue;
      const double gx = (grey(x + 1, y) - grey(x - 1, y)) / 2;
      const double gy = (grey(x, y + 1) - grey(x, y - 1)) / 2;
      sum += std::hypot(gx, gy);
      ++count;
    }
  }
  return sum / double(count);
}

}  // namespace maquette::synthesis::test
