// The nodes of a noise lattice row known evaluated (lattice_noise.h): up to kMax sorted, disjoint
// spans of node indices. A node row is evaluated lazily, in the pieces the layers ask for (a layer
// covers runs of blocks along a row), so a request is answered by evaluating just the nodes it
// lacks, without filling the row with a marker first or looking at its values.
#pragma once

#include <algorithm>
#include <array>

namespace maquette::texture {

class EvaluatedSpans {
 public:
  static constexpr int kMax = 8;

  // Calls evaluate(a, b) for each maximal span a .. b of nodes within first .. last not yet
  // evaluated, in order, then records first .. last as evaluated. Were more than kMax spans to
  // remain, the two closest are joined, evaluate called on the nodes between them too: each node
  // is evaluated at most once.
  template <typename Evaluate>
  void fill(int first, int last, Evaluate evaluate) {
    for (int k = 0; k < n_; ++k)  // most requests: already evaluated
      if (span_[k].first <= first && last <= span_[k].last) return;
    int at = first;
    for (int k = 0; k < n_ && at <= last; ++k) {
      if (span_[k].last < at) continue;
      if (span_[k].first > last) break;
      if (span_[k].first > at) evaluate(at, span_[k].first - 1);
      at = span_[k].last + 1;
    }
    if (at <= last) evaluate(at, last);
    // The spans before, first .. last merged with those it overlaps or touches, those after.
    std::array<Span, kMax + 1> merged;
    int m = 0, k = 0;
    for (; k < n_ && span_[k].last + 1 < first; ++k) merged[m++] = span_[k];
    Span joined{first, last};
    for (; k < n_ && span_[k].first <= last + 1; ++k)
      joined = {std::min(joined.first, span_[k].first), std::max(joined.last, span_[k].last)};
    merged[m++] = joined;
    for (; k < n_; ++k) merged[m++] = span_[k];
    if (m > kMax) {  // join the two closest
      int closest = 0;
      for (int i = 1; i + 1 < m; ++i)
        if (merged[i + 1].first - merged[i].last < merged[closest + 1].first - merged[closest].last)
          closest = i;
      evaluate(merged[closest].last + 1, merged[closest + 1].first - 1);
      merged[closest].last = merged[closest + 1].last;
      std::copy(merged.begin() + closest + 2, merged.begin() + m, merged.begin() + closest + 1);
      --m;
    }
    std::copy_n(merged.begin(), m, span_.begin());
    n_ = m;
  }

 private:
  struct Span {
    int first = 0, last = -1;
  };
  std::array<Span, kMax> span_;
  int n_ = 0;
};

}  // namespace maquette::texture
