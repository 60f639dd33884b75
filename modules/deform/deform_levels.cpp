#include "deform_levels.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "loop_adaptive.h"
#include "loop_grid.h"

namespace maquette::deform {
namespace {

// The vertex of each node of a level's grid, in a dense table over the grid's extent (a
// constraint asks three of them: a hash map's look-ups cost more than the table).
class NodeVertices {
 public:
  explicit NodeVertices(const GridNodes& nodes) {
    for (const auto& n : nodes) {
      across_ = std::max(across_, n[0] + 1);
      down_ = std::max(down_, n[1] + 1);
    }
    vertex_.assign(size_t(across_) * size_t(down_), kNone);
    for (size_t v = 0; v < nodes.size(); ++v)
      vertex_[size_t(nodes[v][1]) * size_t(across_) + size_t(nodes[v][0])] = uint32_t(v);
  }
  size_t at(int col, int row) const {
    const uint32_t v = col >= 0 && row >= 0 && col < across_ && row < down_
                           ? vertex_[size_t(row) * size_t(across_) + size_t(col)]
                           : kNone;
    // Every node of a triangle holding a constraint is refined to the finest level.
    if (v == kNone) throw std::logic_error("refined_heights: a constraint off the zone");
    return v;
  }

 private:
  static constexpr uint32_t kNone = UINT32_MAX;
  int across_ = 0, down_ = 0;
  std::vector<uint32_t> vertex_;
};

// The row of constraint c located on the grid of `nodes` (level t + 1, 2^(t+1) nodes a base
// sample, node (0, 0) at the window's first sample) and written through `subdivision` (its rows:
// the level-(t+1) vertices, columns: the level-t vertices): alpha S_a + beta S_b + gamma S_c (Eq.
// 4), terms by increasing vertex.
void row_through(const HeightConstraint& c, const SampleWindow& window, const NodeVertices& nodes,
                 int scale, const SubdivisionMatrix& subdivision, std::vector<Term>& terms) {
  const double x = (c.at.sample[0] - window.col0) * scale;
  const double y = (c.at.sample[1] - window.row0) * scale;
  const int col = int(std::floor(x)), row = int(std::floor(y));
  const double fx = x - col, fy = y - row;
  // The triangle of the square (col, row)-(col + 1, row + 1) as height_field.h cuts it.
  const bool upper = fx >= fy;
  const std::array<size_t, 3> vertex{nodes.at(col, row),
                                     upper ? nodes.at(col + 1, row) : nodes.at(col, row + 1),
                                     nodes.at(col + 1, row + 1)};
  const std::array<double, 3> weight =
      upper ? std::array{1 - fx, fx - fy, fy} : std::array{1 - fy, fy - fx, fx};
  // The three rows of the subdivision matrix (each sorted by column) merged: a column in several
  // sums its terms from the smallest, as a sort of the (column, term) pairs would.
  std::array<const int*, 3> column, end;
  std::array<const double*, 3> value;
  for (size_t k = 0; k < 3; ++k) {
    const Eigen::Index first = subdivision.outerIndexPtr()[vertex[k]];
    column[k] = subdivision.innerIndexPtr() + first;
    end[k] = subdivision.innerIndexPtr() + subdivision.outerIndexPtr()[vertex[k] + 1];
    value[k] = subdivision.valuePtr() + first;
  }
  terms.clear();
  for (;;) {
    int next = INT_MAX;
    for (size_t k = 0; k < 3; ++k)
      if (column[k] != end[k]) next = std::min(next, *column[k]);
    if (next == INT_MAX) break;
    std::array<double, 3> sum{};
    size_t count = 0;
    for (size_t k = 0; k < 3; ++k)
      if (column[k] != end[k] && *column[k] == next) {
        sum[count++] = weight[k] * *value[k]++;
        ++column[k];
      }
    // At most three: sorted by exchanges.
    if (count == 3 && sum[1] > sum[2]) std::swap(sum[1], sum[2]);
    if (count >= 2 && sum[0] > sum[1]) std::swap(sum[0], sum[1]);
    if (count == 3 && sum[1] > sum[2]) std::swap(sum[1], sum[2]);
    double total = sum[0];
    for (size_t i = 1; i < count; ++i) total += sum[i];
    terms.emplace_back(size_t(next), total);
  }
}

// The constraints' rows (row_through), in their order: built by blocks in parallel, each row on
// its own, so the same for any thread count.
ConstraintRows rows_through(const std::vector<HeightConstraint>& constraints,
                            const SampleWindow& window, const NodeVertices& nodes, int scale,
                            const SubdivisionMatrix& subdivision) {
  constexpr size_t kBlock = 4096;
  std::vector<ConstraintRows> blocks((constraints.size() + kBlock - 1) / kBlock);
  tbb::parallel_for(size_t(0), blocks.size(), [&](size_t b) {
    std::vector<Term> terms;
    for (size_t i = b * kBlock; i < std::min(constraints.size(), (b + 1) * kBlock); ++i) {
      row_through(constraints[i], window, nodes, scale, subdivision, terms);
      blocks[b].add(terms, constraints[i].z, constraints[i].feature);
    }
  });
  ConstraintRows rows;
  size_t terms = 0;
  for (const ConstraintRows& block : blocks) terms += block.terms.size();
  rows.terms.reserve(terms);
  rows.starts.reserve(constraints.size() + 1);
  rows.rhs.reserve(constraints.size());
  rows.features.reserve(constraints.size());
  for (const ConstraintRows& block : blocks) {
    const size_t offset = rows.terms.size();
    rows.terms.insert(rows.terms.end(), block.terms.begin(), block.terms.end());
    for (size_t i = 1; i < block.starts.size(); ++i)
      rows.starts.push_back(offset + block.starts[i]);
    rows.rhs.insert(rows.rhs.end(), block.rhs.begin(), block.rhs.end());
    rows.features.insert(rows.features.end(), block.features.begin(), block.features.end());
  }
  return rows;
}

// The energy neighbours of a mesh's vertices: per edge (cot a + cot b) / 2 of the angles facing
// it in the horizontal positions, negative cotangents taken as 0 (as cotangent_weights). Only
// the unknowns' are asked for, so each is computed from its triangles when asked (the triangles
// of each vertex listed once, by counting: no sort of the mesh's edges).
class MeshNeighbours {
 public:
  explicit MeshNeighbours(const TriangleMesh& mesh)
      : mesh_(mesh), starts_(size_t(mesh.vertices.rows()) + 1, 0) {
    for (const auto& t : mesh.triangles)
      for (const int v : t) ++starts_[size_t(v) + 1];
    for (size_t v = 1; v < starts_.size(); ++v) starts_[v] += starts_[v - 1];
    triangles_.resize(starts_.back());
    std::vector<size_t> next(starts_.begin(), starts_.end() - 1);
    for (size_t t = 0; t < mesh.triangles.size(); ++t)
      for (const int v : mesh.triangles[t]) triangles_[next[size_t(v)]++] = t;
  }

  void operator()(size_t v, std::vector<Term>& out) const {
    out.clear();
    auto add = [&out](size_t n, double w) {
      for (Term& term : out)
        if (term.first == n) {
          term.second += w;
          return;
        }
      out.emplace_back(n, w);
    };
    for (size_t i = starts_[v]; i < starts_[v + 1]; ++i) {
      const auto& t = mesh_.triangles[triangles_[i]];
      const size_t k = t[0] == int(v) ? 0 : t[1] == int(v) ? 1 : 2;
      const int a = t[(k + 1) % 3], b = t[(k + 2) % 3];
      add(size_t(a), 0.5 * std::max(0.0, cot(b, int(v), a)));  // edge v-a faces the corner b
      add(size_t(b), 0.5 * std::max(0.0, cot(a, int(v), b)));
    }
  }

 private:
  // cot of the angle at `apex` between the edges to p and q, in the horizontal positions.
  double cot(int apex, int p, int q) const {
    const auto& x = mesh_.vertices;
    const double ax = x(p, 0) - x(apex, 0), ay = x(p, 1) - x(apex, 1);
    const double bx = x(q, 0) - x(apex, 0), by = x(q, 1) - x(apex, 1);
    return (ax * bx + ay * by) / std::abs(ax * by - ay * bx);
  }

  const TriangleMesh& mesh_;
  std::vector<size_t> starts_, triangles_;
};

}  // namespace

SampleWindow refinement_window(const HeightField& field,
                               const std::vector<StrokeConstraints>& by_level) {
  SampleWindow w{field.width, field.height, -1, -1};
  for (const StrokeConstraints& level : by_level)
    for (const auto* list : {&level.control, &level.section})
      for (const HeightConstraint& c : *list)
        for (const size_t v : c.at.vertex) {
          const int col = int(v % size_t(field.width)), row = int(v / size_t(field.width));
          w = {std::min(w.col0, col), std::min(w.row0, row), std::max(w.col1, col),
               std::max(w.row1, row)};
        }
  const int margin = kRefineMargin + int(by_level.size());
  return {std::max(0, w.col0 - margin), std::max(0, w.row0 - margin),
          std::min(field.width - 1, w.col1 + margin), std::min(field.height - 1, w.row1 + margin)};
}

RefinedPatch refined_heights(const HeightField& field, const SampleWindow& window,
                             const std::vector<StrokeConstraints>& by_level, double energy_weight,
                             Subdivision subdivision) {
  const int levels = int(by_level.size());
  const int columns = window.col1 - window.col0 + 1, rows = window.row1 - window.row0 + 1;
  // The window's triangles in height_field_mesh's order, at the samples' true positions.
  TriangleMesh base =
      height_field_mesh({columns, rows, 1, 1, std::vector<double>(size_t(columns) * rows, 0.0)});
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < columns; ++c) {
      const size_t v = field.index(window.col0 + c, window.row0 + r);
      base.vertices.row(Eigen::Index(r * columns + c)) << field.east[v], field.north[v], field.z[v];
    }
  // The vertices of the triangles holding constraints, grown by kZoneRings samples (a ring of the
  // triangulation is within one sample in col and row); the triangles with one of them refined.
  std::vector<char> near(size_t(base.vertices.rows()), subdivision == Subdivision::Uniform);
  for (const StrokeConstraints& level : by_level)
    for (const auto* list : {&level.control, &level.section})
      for (const HeightConstraint& h : *list) {
        const int c = int(std::floor(h.at.sample[0])) - window.col0;
        const int r = int(std::floor(h.at.sample[1])) - window.row0;
        for (int y = std::max(0, r - kZoneRings); y <= std::min(rows - 1, r + 1 + kZoneRings); ++y)
          for (int x = std::max(0, c - kZoneRings); x <= std::min(columns - 1, c + 1 + kZoneRings);
               ++x)
            near[size_t(y * columns + x)] = 1;
      }
  std::vector<bool> marked(base.triangles.size(), false);
  for (size_t t = 0; t < marked.size(); ++t)
    for (const int v : base.triangles[t]) marked[t] = marked[t] || near[size_t(v)];
  const AdaptiveLoop loop = adaptive_loop_subdivide(base, marked, levels);

  GridNodes nodes = height_field_nodes(columns, rows);
  Eigen::VectorXd z = base.vertices.col(2);
  for (int t = 0; t < levels; ++t) {
    nodes = finer_nodes(nodes, loop.new_vertex_ends[size_t(t)]);
    const NodeVertices finer(nodes);
    const SubdivisionMatrix& s = loop.subdivisions[size_t(t)];
    std::vector<double> heights(z.data(), z.data() + z.size());
    const MeshNeighbours neighbours(loop.meshes[size_t(t)]);
    const StrokeConstraints& level = by_level[size_t(t)];
    const Eigen::MatrixX3d& at = loop.meshes[size_t(t)].vertices;
    const auto in_band = [&](size_t v) {
      return in_any_band(level.bands, {at(Eigen::Index(v), 0), at(Eigen::Index(v), 1)});
    };
    deform_heights(heights, rows_through(level.control, window, finer, 2 << t, s),
                   rows_through(level.section, window, finer, 2 << t, s), neighbours, in_band,
                   energy_weight,
                   t == 0 ? LeastSquaresSolver::Cholesky : LeastSquaresSolver::ConjugateGradients);
    z = s * Eigen::Map<const Eigen::VectorXd>(heights.data(), Eigen::Index(heights.size()));
  }

  // The finest mesh at the pixel centres: node coordinates x = j + 0.5 for patch column j.
  const int scale = 1 << levels;
  RefinedPatch patch{window.col0 * scale + scale / 2,
                     window.row0 * scale + scale / 2,
                     (columns - 1) * scale,
                     (rows - 1) * scale,
                     {}};
  patch.z.assign(size_t(patch.columns) * size_t(patch.rows), NAN);
  std::vector<char> written(patch.z.size(), 0);
  for (const auto& t : loop.meshes.back().triangles) {
    const auto& a = nodes[size_t(t[0])];
    const auto& b = nodes[size_t(t[1])];
    const auto& c = nodes[size_t(t[2])];
    const double det = double(b[0] - a[0]) * (c[1] - a[1]) - double(c[0] - a[0]) * (b[1] - a[1]);
    const double sign = det > 0 ? 1 : -1;
    const int j0 = std::min({a[0], b[0], c[0]}), j1 = std::max({a[0], b[0], c[0]});
    const int i0 = std::min({a[1], b[1], c[1]}), i1 = std::max({a[1], b[1], c[1]});
    for (int i = i0; i < i1; ++i)
      for (int j = j0; j < j1; ++j) {
        const size_t p = size_t(i) * size_t(patch.columns) + size_t(j);
        if (written[p]) continue;
        const double x = j + 0.5 - a[0], y = i + 0.5 - a[1];
        // Barycentric weights of b and c times det: exact (halves and small integers), so a
        // centre on an edge is inside both triangles.
        const double nb = sign * (x * (c[1] - a[1]) - y * (c[0] - a[0]));
        const double nc = sign * (y * (b[0] - a[0]) - x * (b[1] - a[1]));
        if (nb < 0 || nc < 0 || nb + nc > sign * det) continue;
        const double wb = nb / (sign * det), wc = nc / (sign * det);
        patch.z[p] = (1 - wb - wc) * z[t[0]] + wb * z[t[1]] + wc * z[t[2]];
        written[p] = 1;
      }
  }
  return patch;
}

}  // namespace maquette::deform
