#include "deform_solve.h"

#include <Eigen/Sparse>
#include <cmath>

#include "core/error.h"

namespace maquette::deform {

void ConstraintRows::add(std::span<const Term> row, double z) {
  terms.insert(terms.end(), row.begin(), row.end());
  starts.push_back(terms.size());
  rhs.push_back(z);
}

namespace {

// The weighted rows of one least squares, kept as the sparse matrix A (compressed rows, built in
// row order: no triplets to sort) and b, solved by the normal equations A^T A h = A^T b.
class System {
 public:
  System(std::vector<double>& z, std::vector<size_t> unknowns)
      : z_(z), unknowns_(std::move(unknowns)), column_(z.size(), -1) {
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
        rhs -= coefficient * z_[vertex];
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
      z_[unknowns_[i]] = h[Eigen::Index(i)];
    }
  }

 private:
  std::vector<double>& z_;
  std::vector<size_t> unknowns_;  // sorted vertex indices
  std::vector<int> column_;       // by vertex: its unknown's column, -1 for none
  std::vector<int> starts_, columns_;
  std::vector<double> values_, rhs_;
};

// The vertices of the rows' terms that `may_move`, sorted, without those of `fixed`: marked on
// the vertices and read back in index order (no sort of the many repeats).
std::vector<size_t> touched(const ConstraintRows& rows, const std::vector<size_t>& fixed,
                            const std::function<bool(size_t)>& may_move, size_t vertices) {
  std::vector<char> mark(vertices, 0);
  for (const Term& t : rows.terms) mark[t.first] = 1;
  for (const size_t v : fixed) mark[v] = 0;
  std::vector<size_t> out;
  for (size_t v = 0; v < vertices; ++v)
    if (mark[v] && may_move(v)) out.push_back(v);
  return out;
}

// The energy rows: which neighbours of an unknown they read.
enum class Reads {
  All,       // every neighbour, those that are not unknowns at their current height
  Unknowns,  // the unknowns only, their weights renormalized
};

// The rows and an energy row per unknown, solved; returns the unknowns.
std::vector<size_t> solve_stage(std::vector<double>& z, const ConstraintRows& rows,
                                const std::vector<size_t>& fixed,
                                const std::function<bool(size_t)>& may_move,
                                const EnergyNeighbours& neighbours, double energy_weight,
                                Reads reads) {
  System system(z, touched(rows, fixed, may_move, z.size()));
  if (system.unknowns().empty()) return {};
  for (size_t i = 0; i < rows.rhs.size(); ++i)
    system.add(std::span(rows.terms).subspan(rows.starts[i], rows.starts[i + 1] - rows.starts[i]),
               rows.rhs[i], 1.0);
  std::vector<Term> around, terms;
  for (const size_t v : system.unknowns()) {
    neighbours(v, around);
    terms.assign(1, {v, 1.0});
    double sum = 0;
    for (const auto& [n, w] : around)
      if (reads == Reads::All || system.unknown(n)) {
        terms.emplace_back(n, -w);
        sum += w;
      }
    if (sum == 0) continue;  // an isolated unknown: its constraints alone decide it
    for (size_t k = 1; k < terms.size(); ++k) terms[k].second /= sum;
    system.add(terms, 0.0, energy_weight);
  }
  system.solve();
  return system.unknowns();
}

}  // namespace

void deform_heights(std::vector<double>& z, const ConstraintRows& control,
                    const ConstraintRows& section, const EnergyNeighbours& neighbours,
                    const std::function<bool(size_t)>& may_move, double energy_weight) {
  const std::vector<size_t> control_vertices = solve_stage(
      z, control, {}, [](size_t) { return true; }, neighbours, energy_weight, Reads::Unknowns);
  solve_stage(z, section, control_vertices, may_move, neighbours, energy_weight, Reads::All);
}

void deform_heights(HeightField& field, const std::vector<HeightConstraint>& control,
                    const std::vector<HeightConstraint>& section,
                    const std::vector<StrokeBand>& bands, double energy_weight) {
  auto rows = [](const std::vector<HeightConstraint>& constraints) {
    ConstraintRows out;
    for (const HeightConstraint& c : constraints) {
      const std::array<Term, 3> terms{{{c.at.vertex[0], c.at.weight[0]},
                                       {c.at.vertex[1], c.at.weight[1]},
                                       {c.at.vertex[2], c.at.weight[2]}}};
      out.add(terms, c.z);
    }
    return out;
  };
  const EnergyNeighbours neighbours = [&field](size_t v, std::vector<Term>& out) {
    const int col = int(v % size_t(field.width)), r = int(v / size_t(field.width));
    const std::array<double, 6> w = cotangent_weights(field, col, r);
    out.clear();
    for (size_t k = 0; k < 6; ++k)
      out.emplace_back(field.index(col + kNeighbours[k][0], r + kNeighbours[k][1]), w[k]);
  };
  const auto in_band = [&](size_t v) {
    return in_any_band(bands, {field.east[v], field.north[v]});
  };
  deform_heights(field.z, rows(control), rows(section), neighbours, in_band, energy_weight);
}

}  // namespace maquette::deform
