// Nearest-neighbour fields between the square patches of two images (paper 002 §6: the clone
// brush's patch search), behind one interface so that another search (an exact one, a GPU one, one
// free of PatchMatch's patents) can replace PatchMatch without touching the completion.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace maquette::synthesis {

// A float image of `channels` interleaved values per pixel, row-major from the top-left.
struct PatchImage {
  int width = 0, height = 0, channels = 0;
  std::vector<float> values;

  PatchImage() = default;
  PatchImage(int w, int h, int c) : width(w), height(h), channels(c), values(size_t(w) * h * c) {}
  float* pixel(int x, int y) { return values.data() + (size_t(y) * width + x) * channels; }
  const float* pixel(int x, int y) const {
    return values.data() + (size_t(y) * width + x) * channels;
  }
};

// The patches taking part in a search, by their centre pixels: query patches (each gets a match)
// and reference patches (the matches allowed). Every patch lies wholly in its image.
struct PatchCentres {
  int width = 0, height = 0;
  std::vector<uint8_t> member;  // width * height, non-zero: a centre of the set

  PatchCentres() = default;
  PatchCentres(int w, int h) : width(w), height(h), member(size_t(w) * h, 0) {}
  bool has(int x, int y) const { return member[size_t(y) * width + x] != 0; }
};

// For each query centre, in row-major order of the query image, the centre of its match in the
// reference image and the patches' sum of squared differences over every channel.
struct NearestField {
  std::vector<int32_t> query_x, query_y;  // the query centres
  std::vector<int32_t> match_x, match_y;  // their matches' centres (reference centres)
  std::vector<float> cost;
  std::vector<int32_t> index;  // query width * height: the entry of each centre, -1 elsewhere

  size_t size() const { return query_x.size(); }
};

// The field's entries for the query centres of `queries` (row-major), all unmatched (match -1,
// cost +infinity): a search's starting point.
NearestField empty_field(const PatchCentres& queries);

struct FieldSearchParams {
  int patch = 7;       // side of the square patches, odd, >= 3
  int iterations = 4;  // passes over the field (0: only the initial matches and their costs)
  uint64_t seed = 0;   // of every random choice (hashed with the query centre and the pass)
  int round = 0;       // hashed with the seed: each call of a completion draws anew
};

// A search improving a nearest-neighbour field. Contract of improve(): every entry of `field`
// (built by empty_field() on the query centres, possibly matched by an earlier call, e.g. upsampled
// from a coarser level) ends matched to a reference centre whose cost is at most its cost before
// the call (recomputed on these images: an entry whose match is no longer a reference centre is
// re-initialized); the result depends only on the images, the sets, the field and `params`, never
// on the thread count. Preconditions: both images have the same channels, patch centres lie at
// least patch / 2 pixels inside their image, `references` has at least one centre.
class NearestFieldSearch {
 public:
  virtual ~NearestFieldSearch() = default;
  virtual void improve(const PatchImage& query, const PatchImage& reference,
                       const PatchCentres& references, const FieldSearchParams& params,
                       NearestField& field) const = 0;
};

// The sum of squared differences between the patches of side `patch` centred at (qx, qy) in
// `query` and (rx, ry) in `reference`, stopping early (returning a value above `bound`) once
// the sum exceeds `bound`.
float patch_distance(const PatchImage& query, int qx, int qy, const PatchImage& reference, int rx,
                     int ry, int patch, float bound);

}  // namespace maquette::synthesis
