#include "deform_solve.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <Eigen/Sparse>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>

#include "conjugate_gradients.h"
#include "core/error.h"

namespace maquette::deform {

void ConstraintRows::add(std::span<const Term> row, double z, int64_t feature) {
  terms.insert(terms.end(), row.begin(), row.end());
  starts.push_back(terms.size());
  rhs.push_back(z);
  features.push_back(feature);
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

  // Solves; on a singular system or a non-finite result returns the column at fault (the first
  // without a coefficient, or the first non-finite one; SIZE_MAX when none is found) and leaves
  // the heights as they were.
  std::optional<size_t> solve(LeastSquaresSolver solver) {
    Eigen::VectorXd atb, h;
    const bool iterate = solver == LeastSquaresSolver::ConjugateGradients;
    // SimplicialLDLT reads the lower triangle only, so it can take the iterations' matrix.
    const Eigen::SparseMatrix<double> ata =
        normal_equations(atb, iterate ? Triangles::Both : Triangles::Lower);
    if (iterate) {
      h.resize(Eigen::Index(unknowns_.size()));
      for (size_t i = 0; i < unknowns_.size(); ++i) h[Eigen::Index(i)] = z_[unknowns_[i]];
    }
    bool solved = false;
    try {
      solved = iterate && conjugate_gradients(ata, atb, h, kConjugateGradientsTolerance,
                                              kConjugateGradientsIterations);
    } catch (const Error&) {  // a diagonal entry or a direction's curvature not positive
      return empty_column();
    }
    if (!solved) {
      Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower> ldlt(ata);
      if (ldlt.info() != Eigen::Success) return empty_column();
      h = ldlt.solve(atb);
    }
    for (size_t i = 0; i < unknowns_.size(); ++i)
      if (!std::isfinite(h[Eigen::Index(i)])) return i;
    for (size_t i = 0; i < unknowns_.size(); ++i) z_[unknowns_[i]] = h[Eigen::Index(i)];
    return std::nullopt;
  }

 private:
  enum class Triangles { Lower, Both };

  // The lower triangle of A^T A (what SimplicialLDLT reads) or both, and A^T b, by blocks of
  // columns in parallel: entry (k, j) sums a_ij a_ik over the rows i of column j in increasing
  // order, so the same bits for any thread count.
  Eigen::SparseMatrix<double> normal_equations(Eigen::VectorXd& atb, Triangles triangles) const {
    const size_t n = unknowns_.size();
    // A by columns: rows increasing in each (a counting sort of the entries in row order).
    std::vector<int> col_starts(n + 1, 0), col_rows(values_.size());
    std::vector<double> col_values(values_.size());
    for (const int c : columns_) ++col_starts[size_t(c) + 1];
    for (size_t c = 0; c < n; ++c) col_starts[c + 1] += col_starts[c];
    std::vector<int> next(col_starts.begin(), col_starts.end() - 1);
    for (size_t i = 0; i + 1 < starts_.size(); ++i)
      for (int e = starts_[i]; e < starts_[i + 1]; ++e) {
        const int at = next[size_t(columns_[size_t(e)])]++;
        col_rows[size_t(at)] = int(i);
        col_values[size_t(at)] = values_[size_t(e)];
      }
    struct Block {
      std::vector<int> counts, rows;
      std::vector<double> values;
    };
    constexpr size_t kColumns = 2048;
    std::vector<Block> blocks((n + kColumns - 1) / kColumns);
    atb.resize(Eigen::Index(n));
    // Per thread: the sums of a column's rows (back to 0 after each column) and the column that
    // last touched each row; they carry nothing from one column to the next.
    struct Scratch {
      std::vector<double> sum;
      std::vector<size_t> seen;
      std::vector<int> touched;
    };
    tbb::enumerable_thread_specific<Scratch> scratch;
    tbb::parallel_for(size_t(0), blocks.size(), [&](size_t b) {
      Scratch& local = scratch.local();
      if (local.sum.empty()) {
        local.sum.assign(n, 0.0);
        local.seen.assign(n, SIZE_MAX);
      }
      auto& [sum, seen, touched] = local;
      Block& out = blocks[b];
      for (size_t j = b * kColumns; j < std::min(n, (b + 1) * kColumns); ++j) {
        touched.clear();
        double rhs = 0;
        for (int e = col_starts[j]; e < col_starts[j + 1]; ++e) {
          const size_t i = size_t(col_rows[size_t(e)]);
          const double aij = col_values[size_t(e)];
          rhs += aij * rhs_[i];
          for (int f = starts_[i]; f < starts_[i + 1]; ++f) {
            const int k = columns_[size_t(f)];
            if (triangles == Triangles::Lower && size_t(k) < j) continue;
            if (seen[size_t(k)] != j) {
              seen[size_t(k)] = j;
              touched.push_back(k);
            }
            sum[size_t(k)] += aij * values_[size_t(f)];
          }
        }
        atb[Eigen::Index(j)] = rhs;
        std::sort(touched.begin(), touched.end());
        out.counts.push_back(int(touched.size()));
        for (const int k : touched) {
          out.rows.push_back(k);
          out.values.push_back(sum[size_t(k)]);
          sum[size_t(k)] = 0.0;
        }
      }
    });
    Eigen::SparseMatrix<double> ata{Eigen::Index(n), Eigen::Index(n)};
    size_t entries = 0;
    for (const Block& block : blocks) entries += block.rows.size();
    ata.resizeNonZeros(Eigen::Index(entries));
    int* outer = ata.outerIndexPtr();
    size_t column = 0, at = 0;
    outer[0] = 0;
    for (const Block& block : blocks) {
      for (const int count : block.counts) {
        outer[column + 1] = outer[column] + count;
        ++column;
      }
      std::copy(block.rows.begin(), block.rows.end(), ata.innerIndexPtr() + at);
      std::copy(block.values.begin(), block.values.end(), ata.valuePtr() + at);
      at += block.rows.size();
    }
    return ata;
  }

  // The first column without a non-zero coefficient, SIZE_MAX when every column has one.
  size_t empty_column() const {
    std::vector<char> held(unknowns_.size(), 0);
    for (size_t e = 0; e < columns_.size(); ++e) held[size_t(columns_[e])] |= values_[e] != 0;
    const auto empty = std::find(held.begin(), held.end(), 0);
    return empty == held.end() ? SIZE_MAX : size_t(empty - held.begin());
  }

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

// The error of a solve that failed at `column` of `system` (SIZE_MAX: none found): the first of
// `rows` reading that unknown names its feature and its number among that feature's rows, else
// every feature of the rows is named.
Error solve_error(const System& system, size_t column, const ConstraintRows& rows,
                  const std::string& what) {
  const std::string failure = "the least squares of the " + what + " is singular or not finite";
  if (column != SIZE_MAX)
    for (size_t i = 0; i < rows.rhs.size(); ++i)
      for (size_t t = rows.starts[i]; t < rows.starts[i + 1]; ++t)
        if (rows.terms[t].first == system.unknowns()[column]) {
          const int64_t feature = rows.features[i];
          const auto number = std::count(rows.features.begin(), rows.features.begin() + i, feature);
          return Error(
              "feature " + std::to_string(feature) + ": constraint " + std::to_string(number + 1) +
              " of its " + what +
              " (numbered along it from 1) reads a height that nothing else holds: " + failure);
        }
  std::string features;
  for (size_t i = 0; i < rows.features.size(); ++i)
    if (std::find(rows.features.begin(), rows.features.begin() + i, rows.features[i]) ==
        rows.features.begin() + i)
      features += (features.empty() ? "" : ", ") + std::to_string(rows.features[i]);
  return Error("features " + features + ": " + failure);
}

// The rows and an energy row per unknown, solved; returns the unknowns. `what` names the rows
// (their constraints) in errors.
std::vector<size_t> solve_stage(std::vector<double>& z, const ConstraintRows& rows,
                                const std::vector<size_t>& fixed,
                                const std::function<bool(size_t)>& may_move,
                                const EnergyNeighbours& neighbours, double energy_weight,
                                Reads reads, LeastSquaresSolver solver, const std::string& what) {
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
  if (const auto fault = system.solve(solver)) throw solve_error(system, *fault, rows, what);
  return system.unknowns();
}

}  // namespace

void deform_heights(std::vector<double>& z, const ConstraintRows& control,
                    const ConstraintRows& section, const EnergyNeighbours& neighbours,
                    const std::function<bool(size_t)>& may_move, double energy_weight,
                    LeastSquaresSolver solver) {
  const std::vector<size_t> control_vertices = solve_stage(
      z, control, {}, [](size_t) { return true; }, neighbours, energy_weight, Reads::Unknowns,
      LeastSquaresSolver::Cholesky, "control curve");
  solve_stage(z, section, control_vertices, may_move, neighbours, energy_weight, Reads::All, solver,
              "cross sections");
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
      out.add(terms, c.z, c.feature);
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
  deform_heights(field.z, rows(control), rows(section), neighbours, in_band, energy_weight,
                 LeastSquaresSolver::Cholesky);
}

}  // namespace maquette::deform
