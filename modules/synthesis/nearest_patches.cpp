#include "nearest_patches.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <array>
#include <limits>
#include <utility>

namespace maquette::synthesis {
namespace {

struct Node {
  int32_t begin = 0, end = 0;  // the node's points: order[begin, end)
  int32_t left = -1, right = -1;
  int dim = 0;
  float split = 0;
};

using Entry = std::pair<float, int32_t>;  // (squared distance, point): the result's order

class KdTree {
 public:
  static constexpr int32_t kLeafSize = 12;
  // Points from which a node's two halves are built in parallel (the tests' 2000 points too).
  static constexpr int32_t kParallelBuild = 1024;

  KdTree(const std::vector<float>& points, int dims, std::vector<int32_t> order)
      : points_(points), dims_(dims), order_(std::move(order)) {
    if (order_.empty()) return;
    nodes_.resize(size_t(node_count(int32_t(order_.size()))));
    build(0, 0, int32_t(order_.size()));
    // Each leaf's coordinates again, dimension by dimension (its n points' first coordinates,
    // then their second...): a leaf's distances are computed side by side.
    leaf_coords_.resize(order_.size() * size_t(dims_));
    tbb::parallel_for(size_t(0), nodes_.size(), [this](size_t id) {
      const Node& node = nodes_[id];
      if (node.left >= 0) return;
      const int32_t n = node.end - node.begin;
      float* at = &leaf_coords_[size_t(node.begin) * size_t(dims_)];
      for (int32_t j = 0; j < n; ++j)
        for (int d = 0; d < dims_; ++d)
          at[size_t(d) * size_t(n) + size_t(j)] = coord(order_[size_t(node.begin + j)], d);
    });
  }

  // The k best entries, sorted, of the accepted points; `prune` scales a subtree's bound before
  // it is compared with the k-th found ((1 + eps)^2 times the rounding's margin).
  void search(int32_t query, int k, float prune,
              const std::function<bool(int32_t, int32_t)>& accept, std::vector<Entry>& best) const {
    best.clear();
    std::vector<float> offsets(size_t(dims_), 0.0f);
    if (!nodes_.empty()) visit(0, query, k, prune, accept, best, offsets, 0.0f);
  }

 private:
  float coord(int32_t point, int dim) const {
    return points_[size_t(point) * size_t(dims_) + size_t(dim)];
  }

  // The nodes of a subtree over n points: a node splits its points in halves down to leaves of
  // at most kLeafSize.
  static int32_t node_count(int32_t n) {
    return n <= kLeafSize ? 1 : 1 + node_count(n / 2) + node_count(n - n / 2);
  }

  // Node `id` over order_[begin, end) and its subtree in the ids after it, depth first, left
  // first: the same tree for any threads (the two halves are disjoint, built in parallel when
  // large).
  void build(int32_t id, int32_t begin, int32_t end) {
    nodes_[size_t(id)] = {begin, end};
    if (end - begin <= kLeafSize) return;
    int dim = 0;
    float widest = -1;
    for (int d = 0; d < dims_; ++d) {
      float lo = std::numeric_limits<float>::max(), hi = std::numeric_limits<float>::lowest();
      for (int32_t i = begin; i < end; ++i) {
        lo = std::min(lo, coord(order_[size_t(i)], d));
        hi = std::max(hi, coord(order_[size_t(i)], d));
      }
      if (hi - lo > widest) widest = hi - lo, dim = d;
    }
    const int32_t mid = begin + (end - begin) / 2;
    std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                     [&](int32_t a, int32_t b) {
                       const float ca = coord(a, dim), cb = coord(b, dim);
                       return ca < cb || (ca == cb && a < b);
                     });
    Node& node = nodes_[size_t(id)];
    node.dim = dim;
    node.split = coord(order_[size_t(mid)], dim);
    node.left = id + 1;
    node.right = id + 1 + node_count(mid - begin);
    const auto left = [&] { build(node.left, begin, mid); };
    const auto right = [&] { build(node.right, mid, end); };
    if (end - begin >= kParallelBuild) {
      tbb::parallel_invoke(left, right);
    } else {
      left();
      right();
    }
  }

  // The squared distances from the query to each of a leaf's points, each summed over the
  // dimensions in order (the points side by side, each point's sum as a scalar loop's).
  void leaf_distances(const Node& node, int32_t query, std::array<float, kLeafSize>& out) const {
    const int32_t n = node.end - node.begin;
    const float* at = &leaf_coords_[size_t(node.begin) * size_t(dims_)];
    const float* q = &points_[size_t(query) * size_t(dims_)];
    std::fill_n(out.begin(), n, 0.0f);
    for (int d = 0; d < dims_; ++d, at += n)
      for (int32_t j = 0; j < n; ++j) {
        const float x = q[d] - at[j];
        out[size_t(j)] += x * x;
      }
  }

  // `bound`: a lower bound of the squared distance from the query to the node's box, the sum of
  // the squared `offsets` to the splits crossed so far, one per dimension (Arya & Mount's
  // incremental distance).
  void visit(int32_t id, int32_t query, int k, float prune,
             const std::function<bool(int32_t, int32_t)>& accept, std::vector<Entry>& best,
             std::vector<float>& offsets, float bound) const {
    const Node& node = nodes_[size_t(id)];
    if (node.left < 0) {
      std::array<float, kLeafSize> distances;
      leaf_distances(node, query, distances);
      for (int32_t i = node.begin; i < node.end; ++i) {
        const Entry entry{distances[size_t(i - node.begin)], order_[size_t(i)]};
        if (int(best.size()) == k && !(entry < best.back())) continue;
        if (!accept(query, entry.second)) continue;
        best.insert(std::upper_bound(best.begin(), best.end(), entry), entry);
        if (int(best.size()) > k) best.pop_back();
      }
      return;
    }
    const float gap = coord(query, node.dim) - node.split;
    const int32_t near = gap < 0 ? node.left : node.right, far = gap < 0 ? node.right : node.left;
    visit(near, query, k, prune, accept, best, offsets, bound);
    // Points equal to the split lie on either side: visit the far side unless strictly beyond
    // (`prune` holds the bound shrunk by more than its rounding, so that no tie is lost).
    float& offset = offsets[size_t(node.dim)];
    const float saved = offset, far_bound = bound - saved * saved + gap * gap;
    if (int(best.size()) < k || far_bound * prune <= best.back().first) {
      offset = gap;
      visit(far, query, k, prune, accept, best, offsets, far_bound);
      offset = saved;
    }
  }

  const std::vector<float>& points_;
  int dims_;
  std::vector<int32_t> order_;
  std::vector<float> leaf_coords_;  // each leaf's points, by dimension, at its begin * dims_
  std::vector<Node> nodes_;
};

}  // namespace

std::vector<int32_t> nearest_patches(const std::vector<float>& points, int dims,
                                     const std::vector<int32_t>& candidates,
                                     const std::vector<int32_t>& queries, int k, float eps,
                                     const std::function<bool(int32_t, int32_t)>& accept) {
  const KdTree tree(points, dims, candidates);
  // At eps 0 the factor is exactly the rounding's margin alone: the exact search's bits.
  const float prune = (1 + eps) * (1 + eps) * (1 - 1e-5f);
  std::vector<int32_t> out(queries.size() * size_t(k), -1);
  // Queries are independent: each block writes its own entries, so any split gives the same.
  tbb::parallel_for(tbb::blocked_range<size_t>(0, queries.size(), 1024),
                    [&](const tbb::blocked_range<size_t>& range) {
                      std::vector<Entry> best;
                      for (size_t q = range.begin(); q != range.end(); ++q) {
                        tree.search(queries[q], k, prune, accept, best);
                        for (size_t j = 0; j < best.size(); ++j)
                          out[q * size_t(k) + j] = best[j].second;
                      }
                    });
  return out;
}

}  // namespace maquette::synthesis
