#include "content/closed_solid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <tuple>

namespace maquette {
namespace {

// Each vertex's point: the rank of its position among the distinct positions.
std::vector<uint32_t> point_ids(const std::vector<float>& positions) {
  const size_t n = positions.size() / 3;
  const auto at = [&](uint32_t v) {
    return std::array<float, 3>{positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]};
  };
  std::vector<uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return at(a) < at(b); });
  std::vector<uint32_t> id(n);
  uint32_t next = 0;
  for (size_t i = 0; i < n; ++i) {
    if (i > 0 && at(order[i]) != at(order[i - 1])) ++next;
    id[order[i]] = next;
  }
  return id;
}

using Point = std::array<double, 3>;

// Six times the signed volume of the tetrahedron abcd.
double orient(const Point& a, const Point& b, const Point& c, const Point& d) {
  const double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
  const double vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
  const double wx = d[0] - a[0], wy = d[1] - a[1], wz = d[2] - a[2];
  return ux * (vy * wz - vz * wy) - uy * (vx * wz - vz * wx) + uz * (vx * wy - vy * wx);
}

int sign(double v) { return (v > 0) - (v < 0); }

// Whether segment pq passes strictly through the interior of triangle abc.
bool segment_crosses(const Point& p, const Point& q, const Point& a, const Point& b,
                     const Point& c) {
  const int sp = sign(orient(a, b, c, p)), sq = sign(orient(a, b, c, q));
  if (sp == 0 || sq == 0 || sp == sq) return false;
  const int s1 = sign(orient(p, q, a, b)), s2 = sign(orient(p, q, b, c)),
            s3 = sign(orient(p, q, c, a));
  return s1 != 0 && s1 == s2 && s2 == s3;
}

}  // namespace

std::vector<uint32_t> without_fins(const MeshObject& object) {
  const std::vector<uint32_t>& indices = object.indices;
  const std::vector<uint32_t> point = point_ids(object.positions);
  // Each triangle's points sorted, whether sorting them reversed its turn, and its number.
  std::vector<std::tuple<std::array<uint32_t, 3>, bool, size_t>> keys;
  for (size_t t = 0; t + 2 < indices.size(); t += 3) {
    std::array<uint32_t, 3> p{point[indices[t]], point[indices[t + 1]], point[indices[t + 2]]};
    // (a, b, c) is an even permutation of its sorted order iff the smallest is followed by
    // the next in turn.
    const size_t first = size_t(std::min_element(p.begin(), p.end()) - p.begin());
    const bool reversed = p[(first + 1) % 3] > p[(first + 2) % 3];
    std::sort(p.begin(), p.end());
    keys.emplace_back(p, reversed, t / 3);
  }
  std::sort(keys.begin(), keys.end());
  std::vector<bool> dropped(keys.size(), false);
  // Within a run of one point set: the reversed ones after the others, paired off in order.
  for (size_t i = 0; i < keys.size();) {
    size_t end = i;
    while (end < keys.size() && std::get<0>(keys[end]) == std::get<0>(keys[i])) ++end;
    size_t turned = i;
    while (turned < end && !std::get<1>(keys[turned])) ++turned;
    for (size_t a = i, b = turned; a < turned && b < end; ++a, ++b)
      dropped[std::get<2>(keys[a])] = dropped[std::get<2>(keys[b])] = true;
    i = end;
  }
  std::vector<uint32_t> kept;
  for (size_t t = 0; t + 2 < indices.size(); t += 3)
    if (!dropped[t / 3]) kept.insert(kept.end(), &indices[t], &indices[t + 3]);
  return kept;
}

bool has_crossing_triangles(const MeshObject& object) {
  const std::vector<float>& p = object.positions;
  const std::vector<uint32_t> point = point_ids(p);
  const size_t n = object.indices.size() / 3;
  std::vector<std::array<uint32_t, 3>> corner(n);  // point ids
  std::vector<std::array<Point, 3>> at(n);
  std::vector<std::array<double, 6>> box(n);  // min x, y, z, max x, y, z
  for (size_t t = 0; t < n; ++t) {
    box[t] = {INFINITY, INFINITY, INFINITY, -INFINITY, -INFINITY, -INFINITY};
    for (int k = 0; k < 3; ++k) {
      const uint32_t v = object.indices[3 * t + size_t(k)];
      corner[t][size_t(k)] = point[v];
      for (int d = 0; d < 3; ++d) {
        const double x = p[3 * v + size_t(d)];
        at[t][size_t(k)][size_t(d)] = x;
        box[t][size_t(d)] = std::min(box[t][size_t(d)], x);
        box[t][3 + size_t(d)] = std::max(box[t][3 + size_t(d)], x);
      }
    }
  }
  const auto edge_crosses = [&](size_t s, int k, size_t t) {
    return segment_crosses(at[s][size_t(k)], at[s][size_t(k + 1) % 3], at[t][0], at[t][1],
                           at[t][2]);
  };
  // Sweep along x: pairs whose x ranges overlap only (a lake's closed mesh has 10^5 triangles).
  std::vector<size_t> by_x(n);
  std::iota(by_x.begin(), by_x.end(), size_t(0));
  std::sort(by_x.begin(), by_x.end(), [&](size_t a, size_t b) { return box[a][0] < box[b][0]; });
  for (size_t i = 0; i < n; ++i)
    for (size_t j = i + 1; j < n && box[by_x[j]][0] <= box[by_x[i]][3]; ++j) {
      const size_t s = by_x[i], t = by_x[j];
      if (box[s][1] > box[t][4] || box[t][1] > box[s][4] || box[s][2] > box[t][5] ||
          box[t][2] > box[s][5])
        continue;
      int shared = 0, shared_s = -1, shared_t = -1;
      for (int ks = 0; ks < 3; ++ks)
        for (int kt = 0; kt < 3; ++kt)
          if (corner[s][size_t(ks)] == corner[t][size_t(kt)])
            ++shared, shared_s = ks, shared_t = kt;
      if (shared >= 2) continue;
      if (shared == 1) {
        // The edges opposite the shared point: (i + 1, i + 2).
        if (edge_crosses(s, (shared_s + 1) % 3, t) || edge_crosses(t, (shared_t + 1) % 3, s))
          return true;
        continue;
      }
      for (int k = 0; k < 3; ++k)
        if (edge_crosses(s, k, t) || edge_crosses(t, k, s)) return true;
    }
  return false;
}

bool is_closed_outward(const MeshObject& object) {
  const std::vector<float>& p = object.positions;
  const std::vector<uint32_t>& indices = object.indices;
  if (indices.empty()) return false;
  const std::vector<uint32_t> point = point_ids(p);
  std::vector<std::pair<uint32_t, uint32_t>> edges;
  edges.reserve(indices.size());
  double volume = 0;  // six times the signed volume: the triple products of the triangles
  for (size_t t = 0; t + 2 < indices.size(); t += 3) {
    const uint32_t a = indices[t], b = indices[t + 1], c = indices[t + 2];
    if (point[a] == point[b] || point[b] == point[c] || point[c] == point[a]) return false;
    edges.insert(edges.end(), {{point[a], point[b]}, {point[b], point[c]}, {point[c], point[a]}});
    const double ax = p[3 * a], ay = p[3 * a + 1], az = p[3 * a + 2];
    const double bx = p[3 * b], by = p[3 * b + 1], bz = p[3 * b + 2];
    const double cx = p[3 * c], cy = p[3 * c + 1], cz = p[3 * c + 2];
    volume += ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx);
  }
  std::sort(edges.begin(), edges.end());
  for (size_t i = 0; i < edges.size(); ++i) {
    if (i + 1 < edges.size() && edges[i + 1] == edges[i]) return false;
    const auto [a, b] = edges[i];
    if (!std::binary_search(edges.begin(), edges.end(), std::make_pair(b, a))) return false;
  }
  return volume > 0;
}

}  // namespace maquette
