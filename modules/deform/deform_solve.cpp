#include "deform_solve.h"

#include <Eigen/Sparse>
#include <cmath>
#include <span>

#include "core/error.h"

namespace maquette::deform {
namespace {

// A term of a least-squares row: coefficient * h[vertex].
using Term = std::pair<size_t, double>;

// The weighted rows of one least squares, kept as the sparse matrix A (compressed rows, built in
// row order: no triplets to sort) and b, solved by the normal equations A^T A h = A^T b.
class System {
 public:
  System(HeightField& field, std::vector<size_t> unknowns)
      : field_(field), unknowns_(std::move(unknowns)), column_(field.z.size(), -1) {
    for (size_t i = 0; i < unknowns_.size(); ++i) column_[unknowns_[i]] = int(i);
    starts_.push_back(0);
  }

  const std::vector<size_t>& unknowns() const { return unknowns_; }
  bool unknown(size_t vertex) const { return column_[vertex] >= 0; }

  // Adds the row weight * (sum terms = rhs); terms on vertices that are no unknowns go to the
  // right-hand side at their current height. A row without unknowns is dropped.
  void add(std::span<const Term> terms, double rhs, double weight) {
    const size_t first = columns_.size();
    for (const auto& [vertex, coefficient] : terms) {
      const int u = column_[vertex];
      if (u < 0) {
        rhs -= coefficient * field_.z[vertex];
      } else {
        columns_.push_back(u);
        values_.push_back(weight * coefficient);
      }
    }
    if (columns_.size() == first) return;
    starts_.push_back(int(columns_.size()));
    rhs_.push_back(weight * rhs);
  }

  void solve() {
    const Eigen::Map<const Eigen::SparseMatrix<double, Eigen::RowMajor>> a(
        Eigen::Index(rhs_.size()), Eigen::Index(unknowns_.size()), Eigen::Index(values_.size()),
        starts_.data(), columns_.data(), values_.data());
    const Eigen::SparseMatrix<double> at = a.transpose();
    const Eigen::SparseMatrix<double> ata = at * a;
    const Eigen::VectorXd atb = at * Eigen::Map<const Eigen::VectorXd>(rhs_.data(), a.rows());
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(ata);
    if (ldlt.info() != Eigen::Success) throw Error("the deformation's least squares is singular");
    const Eigen::VectorXd h = ldlt.solve(atb);
    for (size_t i = 0; i < unknowns_.size(); ++i) {
      if (!std::isfinite(h[Eigen::Index(i)]))
        throw Error("the deformation's least squares has no finite solution");
      field_.z[unknowns_[i]] = h[Eigen::Index(i)];
    }
  }

 private:
  HeightField& field_;
  std::vector<size_t> unknowns_;  // sorted vertex indices
  std::vector<int> column_;       // by vertex: its unknown's column, -1 for none
  std::vector<int> starts_, columns_;
  std::vector<double> values_, rhs_;
};

// The vertices of the constraints' triangles, sorted, without those of `fixed`: marked on the
// field's vertices and read back in index order (no sort of the many repeats).
std::vector<size_t> touched(const std::vector<HeightConstraint>& constraints,
                            const std::vector<size_t>& fixed, size_t vertices) {
  std::vector<char> mark(vertices, 0);
  for (const HeightConstraint& c : constraints)
    for (const size_t v : c.at.vertex) mark[v] = 1;
  for (const size_t v : fixed) mark[v] = 0;
  std::vector<size_t> out;
  for (size_t v = 0; v < vertices; ++v)
    if (mark[v]) out.push_back(v);
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
  System system(field, touched(constraints, fixed, field.z.size()));
  if (system.unknowns().empty()) return {};
  for (const HeightConstraint& c : constraints) {
    const std::array<Term, 3> terms{{{c.at.vertex[0], c.at.weight[0]},
                                     {c.at.vertex[1], c.at.weight[1]},
                                     {c.at.vertex[2], c.at.weight[2]}}};
    system.add(terms, c.z, 1.0);
  }
  std::array<Term, 7> terms;
  for (const size_t v : system.unknowns()) {
    const int col = int(v % size_t(field.width)), r = int(v / size_t(field.width));
    const std::array<double, 6> w = cotangent_weights(field, col, r);
    terms[0] = {v, 1.0};
    size_t count = 1;
    double sum = 0;
    for (size_t k = 0; k < 6; ++k) {
      const size_t n = field.index(col + kNeighbours[k][0], r + kNeighbours[k][1]);
      if (neighbours == Neighbours::All || system.unknown(n)) {
        terms[count++] = {n, -w[k]};
        sum += w[k];
      }
    }
    if (sum == 0) continue;  // an isolated unknown: its constraints alone decide it
    for (size_t k = 1; k < count; ++k) terms[k].second /= sum;
    system.add(std::span(terms.data(), count), 0.0, energy_weight);
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
