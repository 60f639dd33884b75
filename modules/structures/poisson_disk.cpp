#include "poisson_disk.h"

#include <array>
#include <cmath>

#include "core/splitmix64.h"

namespace maquette::structures {
namespace {

constexpr int kPhases = 9;
constexpr int kHaloBuckets = kPhases - 1;
// At most 3 points a bucket of side r with pairs >= r apart (4 would need two corners of the
// half-open square); 4 slots keep the layout simple.
constexpr int kSlots = 4;

// The buckets of the window grown by kHaloBuckets, with their kept points.
class Buckets {
 public:
  Buckets(int64_t i0, int64_t j0, int64_t width, int64_t height)
      : i0_(i0),
        j0_(j0),
        width_(width),
        height_(height),
        count_(size_t(width * height), 0),
        points_(size_t(width * height)) {}

  // Whether no kept point of the 3 x 3 buckets around (i, j) is closer than r to p.
  bool free(int64_t i, int64_t j, PlanePoint p, double r2) const {
    for (int64_t b = std::max(j - 1, j0_); b <= std::min(j + 1, j0_ + height_ - 1); ++b)
      for (int64_t a = std::max(i - 1, i0_); a <= std::min(i + 1, i0_ + width_ - 1); ++a) {
        const size_t k = index(a, b);
        for (int s = 0; s < count_[k]; ++s) {
          const double dx = points_[k][s].x - p.x, dy = points_[k][s].y - p.y;
          if (dx * dx + dy * dy < r2) return false;
        }
      }
    return true;
  }
  void keep(int64_t i, int64_t j, PlanePoint p) {
    const size_t k = index(i, j);
    points_[k][count_[k]++] = p;
  }
  int count(int64_t i, int64_t j) const { return count_[index(i, j)]; }
  PlanePoint point(int64_t i, int64_t j, int s) const { return points_[index(i, j)][s]; }

 private:
  size_t index(int64_t i, int64_t j) const { return size_t((j - j0_) * width_ + (i - i0_)); }
  int64_t i0_, j0_, width_, height_;
  std::vector<uint8_t> count_;
  std::vector<std::array<PlanePoint, kSlots>> points_;
};

}  // namespace

double poisson_min_distance(double spacing) { return spacing * std::sqrt(kPoissonDensity); }

std::vector<PlanePoint> poisson_disk(const PolygonSet& region, double min_distance, uint64_t seed,
                                     const PlaneWindow& window) {
  const double r = min_distance, r2 = r * r;
  const int64_t wi0 = int64_t(std::floor(window.x_min / r));
  const int64_t wj0 = int64_t(std::floor(window.y_min / r));
  const int64_t wi1 = int64_t(std::floor(window.x_max / r));
  const int64_t wj1 = int64_t(std::floor(window.y_max / r));
  const int64_t i0 = wi0 - kHaloBuckets, j0 = wj0 - kHaloBuckets;
  Buckets buckets(i0, j0, wi1 - wi0 + 1 + 2 * kHaloBuckets, wj1 - wj0 + 1 + 2 * kHaloBuckets);
  const uint64_t seed_hash = splitmix64_mix(seed);
  for (int p = 0; p < kPhases; ++p) {
    const int64_t grow = kHaloBuckets - p;
    // Phase p is the buckets with (i mod 3, j mod 3) = (p mod 3, p / 3): the first at or after
    // (wi0 - grow, wj0 - grow), then every third.
    const auto first = [&](int64_t start, int offset) {
      return start + ((offset - start) % 3 + 3) % 3;
    };
    for (int64_t j = first(wj0 - grow, p / 3); j <= wj1 + grow; j += 3)
      for (int64_t i = first(wi0 - grow, p % 3); i <= wi1 + grow; i += 3) {
        uint64_t state = splitmix64_mix(splitmix64_mix(seed_hash ^ uint64_t(i)) ^ uint64_t(j));
        for (int t = 0; t < kPoissonTries; ++t) {
          const PlanePoint q{(double(i) + unit_interval(splitmix64_next(state))) * r,
                             (double(j) + unit_interval(splitmix64_next(state))) * r};
          if (buckets.free(i, j, q, r2)) buckets.keep(i, j, q);
        }
      }
  }
  std::vector<PlanePoint> out;
  for (int64_t j = wj0; j <= wj1; ++j)
    for (int64_t i = wi0; i <= wi1; ++i)
      for (int s = 0; s < buckets.count(i, j); ++s) {
        const PlanePoint q = buckets.point(i, j, s);
        if (q.x >= window.x_min && q.x < window.x_max && q.y >= window.y_min &&
            q.y < window.y_max && region.contains({q.x, q.y}))
          out.push_back(q);
      }
  return out;
}

}  // namespace maquette::structures
