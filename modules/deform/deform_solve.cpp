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

  // Room for `rows` constraint rows of `terms` terms in all and the unknowns' energy rows (at
  // most 7 terms each on the height field and regular Loop vertices; more only grows).
  void reserve(size_t rows, size_t terms) {
    const size_t all_rows = rows + unknowns_.size();
    starts_.reserve(all_rows + 1);
    rhs_.reserve(all_rows);
    columns_.reserve(terms + 7 * unknowns_.size());
    values_.reserve(terms + 7 * unknowns_.size());
  }

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
    sort_row(first);
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

  // Sorts the entries of the row begun at `first` by column (insertion sort: rows hold 3 to ~20
  // terms, those through the subdivision matrix already sorted) and adds up repeated columns
  // (none in deform_heights' rows): normal_equations reads each column once per row. The order of
  // a row's terms changes none of its sums.
  void sort_row(size_t first) {
    for (size_t e = first + 1; e < columns_.size(); ++e)
      for (size_t f = e; f > first && columns_[f - 1] > columns_[f]; --f) {
        std::swap(columns_[f - 1], columns_[f]);
        std::swap(values_[f - 1], values_[f]);
      }
    size_t kept = first;
    for (size_t e = first; e < columns_.size(); ++e) {
      if (e > first && columns_[e] == columns_[kept - 1]) {
        values_[kept - 1] += values_[e];
        continue;
      }
      columns_[kept] = columns_[e];
      values_[kept++] = values_[e];
    }
    columns_.resize(kept);
    values_.resize(kept);
  }

  // The lower triangle of A^T A (what SimplicialLDLT reads) or both, and A^T b, by blocks of
  // columns in parallel: entry (k, j), k >= j, sums a_ij a_ik over the rows i of column j in
  // increasing order (the terms of row i from column j on: rows are sorted by column), so the
  // same bits for any thread count; the upper triangle is the lower's mirror (entry (j, k) would
  // sum the same products in the same order).
  Eigen::SparseMatrix<double> normal_equations(Eigen::VectorXd& atb, Triangles triangles) const {
    const size_t n = unknowns_.size();
    // A by columns: rows increasing in each (a counting sort of the entries in row order), with
    // each entry's place in its row.
    std::vector<int> col_starts(n + 1, 0), col_entries(values_.size());
    for (const int c : columns_) ++col_starts[size_t(c) + 1];
    for (size_t c = 0; c < n; ++c) col_starts[c + 1] += col_starts[c];
    std::vector<int> next(col_starts.begin(), col_starts.end() - 1);
    for (size_t e = 0; e < columns_.size(); ++e)
      col_entries[size_t(next[size_t(columns_[e])]++)] = int(e);
    std::vector<int> row_of(values_.size());
    for (size_t i = 0; i + 1 < starts_.size(); ++i)
      std::fill(row_of.begin() + starts_[i], row_of.begin() + starts_[i + 1], int(i));
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
        for (int c = col_starts[j]; c < col_starts[j + 1]; ++c) {
          const int e = col_entries[size_t(c)];
          const size_t i = size_t(row_of[size_t(e)]);
          const double aij = values_[size_t(e)];
          rhs += aij * rhs_[i];
          for (int f = e; f < starts_[i + 1]; ++f) {
            const int k = columns_[size_t(f)];
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
    Eigen::SparseMatrix<double> lower{Eigen::Index(n), Eigen::Index(n)};
    size_t entries = 0;
    for (const Block& block : blocks) entries += block.rows.size();
    lower.resizeNonZeros(Eigen::Index(entries));
    int* outer = lower.outerIndexPtr();
    size_t column = 0, at = 0;
    outer[0] = 0;
    for (const Block& block : blocks) {
      for (const int count : block.counts) {
        outer[column + 1] = outer[column] + count;
        ++column;
      }
      std::copy(block.rows.begin(), block.rows.end(), lower.innerIndexPtr() + at);
      std::copy(block.values.begin(), block.values.end(), lower.valuePtr() + at);
      at += block.rows.size();
    }
    return triangles == Triangles::Lower ? lower : mirrored(lower);
  }

  // Both triangles of the symmetric matrix whose lower triangle (diagonal included) is `lower`:
  // column j holds the entries of row j left of the diagonal (from the columns before j, in
  // order), then column j of `lower`.
  static Eigen::SparseMatrix<double> mirrored(const Eigen::SparseMatrix<double>& lower) {
    const Eigen::Index n = lower.cols();
    const int* outer = lower.outerIndexPtr();
    const int* inner = lower.innerIndexPtr();
    const double* value = lower.valuePtr();
    Eigen::SparseMatrix<double> full{n, n};
    int* out_outer = full.outerIndexPtr();
    std::fill(out_outer, out_outer + n + 1, 0);
    for (Eigen::Index k = 0; k < n; ++k)
      for (int e = outer[k]; e < outer[k + 1]; ++e) out_outer[inner[e] + 1] += inner[e] != k;
    for (Eigen::Index j = 0; j < n; ++j)
      out_outer[j + 1] += out_outer[j] + (outer[j + 1] - outer[j]);
    full.resizeNonZeros(out_outer[n]);
    std::vector<int> next(out_outer, out_outer + n);
    for (Eigen::Index k = 0; k < n; ++k)
      for (int e = outer[k]; e < outer[k + 1]; ++e)
        if (inner[e] != k) {
          const int at = next[size_t(inner[e])]++;
          full.innerIndexPtr()[at] = int(k);
          full.valuePtr()[at] = value[e];
        }
    for (Eigen::Index j = 0; j < n; ++j) {
      std::copy(inner + outer[j], inner + outer[j + 1], full.innerIndexPtr() + next[size_t(j)]);
      std::copy(value + outer[j], value + outer[j + 1], full.valuePtr() + next[size_t(j)]);
    }
    return full;
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
  system.reserve(rows.rhs.size(), rows.terms.size());
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
