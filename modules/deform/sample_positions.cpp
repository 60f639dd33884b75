#include "sample_positions.h"

#include <cmath>
#include <cstdint>
#include <optional>

#include "core/parallel_chunks.h"
#include "three_point_quadratic.h"

namespace maquette::deform {
namespace {

constexpr int64_t kStretch = 32;  // face pixels

// The quadratic through the positions of a stretch's ends and middle, when it holds there.
class Stretch {
 public:
  // The stretch of face pixel columns [first, first + kStretch] of mosaic row `row`, `origin`
  // the face pixel column of mosaic column 0.
  Stretch(const MosaicFrame& frame, int64_t origin, int64_t first, int row) {
    const auto at = [&](int64_t offset) -> std::optional<EastNorth2> {
      const auto centre = frame.sample_centre(int(first + offset - origin), row);
      if (!centre) return std::nullopt;
      return frame.local(*centre);
    };
    const auto p0 = at(0), p1 = at(kStretch / 2), p2 = at(kStretch);
    if (!p0 || !p1 || !p2) return;
    quadratic_ = {double(kStretch / 2), double(kStretch), *p0, *p1, *p2};
    for (const int64_t offset : {kStretch / 4, kStretch - kStretch / 4}) {
      const auto p = at(offset);
      if (!p) return;
      const EastNorth2 q = quadratic(offset);
      if (!(std::abs(q[0] - (*p)[0]) <= kPositionTolerance &&
            std::abs(q[1] - (*p)[1]) <= kPositionTolerance))
        return;
    }
    smooth_ = true;
  }

  bool smooth() const { return smooth_; }

  // The quadratic at `offset` face pixels from the stretch's first.
  EastNorth2 quadratic(int64_t offset) const { return quadratic_(double(offset)); }

 private:
  ThreePointQuadratic quadratic_{};
  bool smooth_ = false;
};

}  // namespace

void place_samples(const MosaicFrame& frame, const std::vector<char>& wanted, HeightField& field) {
  const int64_t origin = int64_t(frame.origin()[0]);
  // Rows in parallel; a failing row throws the first failing row's error whatever the threads.
  parallel_chunks(size_t(field.height), 1, [&](size_t first_row, size_t last_row) {
    for (int r = int(first_row); r < int(last_row); ++r) {
      std::optional<Stretch> stretch;
      int64_t first = 0;
      for (int c = 0; c < field.width; ++c) {
        const size_t v = field.index(c, r);
        if (!wanted[v] || !std::isnan(field.east[v])) continue;
        const int64_t pixel = origin + c;
        // The stretch holding the pixel: its first column a multiple of kStretch.
        const int64_t start = pixel - ((pixel % kStretch) + kStretch) % kStretch;
        if (!stretch || start != first) {
          first = start;
          stretch.emplace(frame, origin, first, r);
        }
        const EastNorth2 p = stretch->smooth() ? stretch->quadratic(pixel - first)
                                               : frame.local(frame.sample_lonlat(c, r));
        field.east[v] = p[0];
        field.north[v] = p[1];
      }
    }
  });
}

}  // namespace maquette::deform
