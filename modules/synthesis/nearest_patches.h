// The k nearest neighbours among feature vectors (a k-d tree), exact or (1 + eps)-approximate, for
// the k-coherence candidates: each exemplar patch's k most similar patches, computed once per
// exemplar level.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

namespace maquette::synthesis {

// For each point q of `queries` (indices into `points`), the indices of the `k` points nearest to
// it in squared Euclidean distance among `candidates` for which accept(q, candidate) holds,
// nearest first; ties go to the lower index, so the result is defined whatever the tree's shape.
// Fewer than k (the rest -1) when fewer candidates are accepted. `points` holds `dims` floats per
// point. The result has k entries per query, in the queries' order. The tree's halves are built
// and the queries run in parallel (TBB): `accept` must be safe to call from several threads.
// eps > 0 makes the search approximate (Arya, Mount et al. 1998): a subtree is skipped when all of
// it is farther than the k-th found divided by 1 + eps, so each j-th found is within (1 + eps)^2
// of the true j-th's squared distance; eps 0 is exact. Either way the result depends on the
// inputs alone, not on the threads.
std::vector<int32_t> nearest_patches(const std::vector<float>& points, int dims,
                                     const std::vector<int32_t>& candidates,
                                     const std::vector<int32_t>& queries, int k, float eps,
                                     const std::function<bool(int32_t, int32_t)>& accept);

}  // namespace maquette::synthesis
