#include "void_fill.h"

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <vector>

#include "core/error.h"
#include "voids.h"

namespace maquette::terrain {
namespace {

// The energy minimised over a void's samples is a sum of squared stencils, each applied at
// every location where it touches the void: forward differences (the Dirichlet energy, whose
// minimiser satisfies the 5-point Laplace equation) or the 5-point Laplacian (the thin-plate
// energy, giving the 13-point biharmonic equation inside the void).
struct Tap {
  int dcol, drow;
  double weight;
};
using Stencil = std::vector<Tap>;

const std::vector<Stencil>& energy_terms(FillMethod method) {
  static const std::vector<Stencil> laplace = {{{0, 0, -1}, {1, 0, 1}}, {{0, 0, -1}, {0, 1, 1}}};
  static const std::vector<Stencil> biharmonic = {
      {{0, 0, -4}, {-1, 0, 1}, {1, 0, 1}, {0, -1, 1}, {0, 1, 1}}};
  return method == FillMethod::Laplace ? laplace : biharmonic;
}

class VoidSystem {
 public:
  VoidSystem(const Tile<float>& dem, const Void& v) : dem_(dem), void_(v), rhs_(v.samples.size()) {
    rhs_.setZero();
  }

  // Adds the squared stencil at every location where it involves an unknown. A term reaching a
  // sample that is neither known nor an unknown (another void, or beyond the window) is left out.
  void add(const Stencil& stencil) {
    const int stride = dem_.stride();
    std::vector<int> locations;
    for (const int s : void_.samples)
      for (const Tap& t : stencil) {
        const int col = s % stride - t.dcol, row = s / stride - t.drow;
        if (col >= 0 && row >= 0 && col < stride && row < stride)
          locations.push_back(row * stride + col);
      }
    std::sort(locations.begin(), locations.end());
    locations.erase(std::unique(locations.begin(), locations.end()), locations.end());
    for (const int location : locations) add_term(stencil, location);
  }

  std::vector<double> solve() const {
    Eigen::SparseMatrix<double> normal(rhs_.size(), rhs_.size());
    normal.setFromTriplets(entries_.begin(), entries_.end());
    const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(normal);
    if (ldlt.info() != Eigen::Success)
      throw Error("terrain.fill_voids: singular system for a void of " +
                  std::to_string(rhs_.size()) + " samples");
    const Eigen::VectorXd x = ldlt.solve(rhs_);
    return {x.begin(), x.end()};
  }

 private:
  void add_term(const Stencil& stencil, int location) {
    const int stride = dem_.stride();
    const std::span<const float> data = dem_.data();
    term_.clear();
    double known = 0;
    for (const Tap& t : stencil) {
      const int col = location % stride + t.dcol, row = location / stride + t.drow;
      if (col < 0 || row < 0 || col >= stride || row >= stride) return;
      const int s = row * stride + col;
      if (!std::isnan(data[s])) {
        known += t.weight * data[s];
        continue;
      }
      const auto it = std::lower_bound(void_.samples.begin(), void_.samples.end(), s);
      if (it == void_.samples.end() || *it != s) return;
      term_.emplace_back(int(it - void_.samples.begin()), t.weight);
    }
    for (const auto& [i, wi] : term_) {
      rhs_[i] -= wi * known;
      for (const auto& [j, wj] : term_) entries_.emplace_back(i, j, wi * wj);
    }
  }

  const Tile<float>& dem_;
  const Void& void_;
  std::vector<Eigen::Triplet<double>> entries_;  // of the normal matrix, summed on assembly
  Eigen::VectorXd rhs_;
  std::vector<std::pair<int, double>> term_;  // unknowns of the term being added
};

}  // namespace

Tile<float> fill_voids(const Tile<float>& dem, const FillOptions& options) {
  Tile<float> out = dem;
  for (const Void& v : find_voids(dem)) {
    if (v.reaches_edge || v.extent > options.max_void_px) continue;
    VoidSystem system(dem, v);
    for (const Stencil& stencil : energy_terms(options.method)) system.add(stencil);
    const std::vector<double> x = system.solve();
    for (size_t i = 0; i < x.size(); ++i) out.data()[v.samples[i]] = float(x[i]);
  }
  return out;
}

}  // namespace maquette::terrain
