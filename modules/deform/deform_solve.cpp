#include "deform_solve.h"

#include <Eigen/Sparse>
#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace maquette::deform {
namespace {

// One least-squares row: sum coefficient * h[vertex] = rhs.
struct Row {
  std::vector<std::pair<size_t, double>> terms;
  double rhs = 0;
};

class System {
 public:
  System(HeightField& field, std::vector<size_t> unknowns)
      : field_(field),
        unknowns_(std::move(unknowns)),
        atb_(Eigen::VectorXd::Zero(Eigen::Index(unknowns_.size()))) {}

  const std::vector<size_t>& unknowns() const { return unknowns_; }
  bool unknown(size_t vertex) const { return column(vertex) >= 0; }

  // Adds weight * (row) to the normal equations; terms on vertices that are no unknowns go to
  // the right-hand side at their current height.
  void add(const Row& row, double weight) {
    std::vector<std::pair<Eigen::Index, double>> free;
    double rhs = row.rhs;
    for (const auto& [vertex, coefficient] : row.terms) {
      const Eigen::Index u = column(vertex);
      if (u < 0)
        rhs -= coefficient * field_.z[vertex];
      else
        free.emplace_back(u, coefficient);
    }
    const double w2 = weight * weight;
    for (const auto& [i, a] : free) {
      atb_[i] += w2 * a * rhs;
      for (const auto& [j, b] : free) triplets_.emplace_back(i, j, w2 * a * b);
    }
  }

  void solve() {
    Eigen::SparseMatrix<double> ata(atb_.size(), atb_.size());
    ata.setFromTriplets(triplets_.begin(), triplets_.end());
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(ata);
    if (ldlt.info() != Eigen::Success) throw Error("the deformation's least squares is singular");
    const Eigen::VectorXd h = ldlt.solve(atb_);
    for (size_t i = 0; i < unknowns_.size(); ++i) {
      if (!std::isfinite(h[Eigen::Index(i)]))
        throw Error("the deformation's least squares has no finite solution");
      field_.z[unknowns_[i]] = h[Eigen::Index(i)];
    }
  }

 private:
  Eigen::Index column(size_t vertex) const {
    const auto it = std::lower_bound(unknowns_.begin(), unknowns_.end(), vertex);
    return it != unknowns_.end() && *it == vertex ? Eigen::Index(it - unknowns_.begin()) : -1;
  }

  HeightField& field_;
  std::vector<size_t> unknowns_;  // sorted vertex indices
  std::vector<Eigen::Triplet<double>> triplets_;
  Eigen::VectorXd atb_;
};

// The vertices of the constraints' triangles, sorted, without those of `fixed` (sorted).
std::vector<size_t> touched(const std::vector<HeightConstraint>& constraints,
                            const std::vector<size_t>& fixed) {
  std::vector<size_t> all;
  for (const HeightConstraint& c : constraints)
    all.insert(all.end(), c.at.vertex.begin(), c.at.vertex.end());
  std::sort(all.begin(), all.end());
  all.erase(std::unique(all.begin(), all.end()), all.end());
  std::vector<size_t> out;
  std::set_difference(all.begin(), all.end(), fixed.begin(), fixed.end(), std::back_inserter(out));
  return out;
}

// The energy rows: which neighbours of an unknown they read.
enum class Neighbours {
  All,       // every neighbour, those that are not unknowns at their current height
  Unknowns,  // the unknowns only, their weights renormalized
};

// The constraints' rows and an energy row per unknown, solved; returns the unknowns.
std::vector<size_t> solve_stage(HeightField& field,
                                const std::vector<HeightConstraint>& constraints,
                                const std::vector<size_t>& fixed, double energy_weight,
                                Neighbours neighbours) {
  System system(field, touched(constraints, fixed));
  if (system.unknowns().empty()) return {};
  for (const HeightConstraint& c : constraints) {
    Row row{{}, c.z};
    for (size_t k = 0; k < 3; ++k) row.terms.emplace_back(c.at.vertex[k], c.at.weight[k]);
    system.add(row, 1.0);
  }
  for (const size_t v : system.unknowns()) {
    const int col = int(v % size_t(field.width)), r = int(v / size_t(field.width));
    const std::array<double, 6> w = cotangent_weights(field, col, r);
    Row row{{{v, 1.0}}, 0.0};
    double sum = 0;
    for (size_t k = 0; k < 6; ++k) {
      const size_t n = field.index(col + kNeighbours[k][0], r + kNeighbours[k][1]);
      if (neighbours == Neighbours::All || system.unknown(n)) {
        row.terms.emplace_back(n, -w[k]);
        sum += w[k];
      }
    }
    if (sum == 0) continue;  // an isolated unknown: its constraints alone decide it
    for (size_t k = 1; k < row.terms.size(); ++k) row.terms[k].second /= sum;
    system.add(row, energy_weight);
  }
  system.solve();
  return system.unknowns();
}

}  // namespace

void deform_heights(HeightField& field, const std::vector<HeightConstraint>& control,
                    const std::vector<HeightConstraint>& section, double energy_weight) {
  const std::vector<size_t> control_vertices =
      solve_stage(field, control, {}, energy_weight, Neighbours::Unknowns);
  solve_stage(field, section, control_vertices, energy_weight, Neighbours::All);
}

}  // namespace maquette::deform
