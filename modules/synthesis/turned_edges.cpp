#include "turned_edges.h"

#include <algorithm>
#include <cstddef>
#include <cstdlib>
#include <string>
#include <utility>

#include "chart_guides.h"
#include "core/error.h"
#include "core/tile.h"
#include "core/unfolded_faces.h"
#include "seam_cut.h"

namespace maquette::synthesis {
namespace {

using Pixel = std::array<int64_t, 2>;

// B: the band of `e` over the cell (positions s0 .. s0 + n - 1, depths 0 .. kTurnedEdgeBand - 1)
// synthesized in G's chart, indexed [t * n + s - s0]. The chart's guides are found among the
// cell's (laid in the cell's own chart, chart_guides.h: `held`, at pixel level `level`) by the
// face pixel G's chart lays.
std::vector<int32_t> chart_band(const Grid& grid, const FacePlane& plane,
                                const ExemplarPyramid& pyramid, const SynthesisParams& sp,
                                const TargetGuides& guides, const HaloPixels& held, int level,
                                int halo, const TurnedEdge& e, int64_t s0, int n) {
  constexpr int64_t kBand = kTurnedEdgeBand;
  const Pixel a = e.at(s0, 0), b = e.at(s0 + n - 1, kBand - 1);
  const Pixel lo = {std::min(a[0], b[0]), std::min(a[1], b[1])};
  const PixelRect window{e.plane[0] + lo[0], e.plane[1] + lo[1], std::abs(a[0] - b[0]) + 1,
                         std::abs(a[1] - b[1]) + 1};
  const int shift = guides.shift;
  TargetGuides chart;
  chart.shift = shift;
  chart.col_period = guides.col_period;
  chart.rect = guide_rect(window, shift);
  const bool altitude = !guides.altitude.empty();
  const Pixel origin = {e.plane[0] >> shift, e.plane[1] >> shift};  // G's first guide pixel
  for (int64_t y = chart.rect.row0; y < chart.rect.row0 + chart.rect.height; ++y)
    for (int64_t x = chart.rect.col0; x < chart.rect.col0 + chart.rect.width; ++x) {
      const auto p = plane.chart_pixel(grid, e.face, level, x - origin[0], y - origin[1]);
      const int64_t i = p ? held.find(*p) : -1;
      if (i < 0)
        throw Error("synthesis.transfer: " + e.cell.ToText() + "'s band along face " +
                    std::to_string(e.face) + " needs guides beyond its halo of " +
                    std::to_string(halo));
      chart.labels.push_back(guides.labels[size_t(i)]);
      if (altitude) chart.altitude.push_back(guides.altitude[size_t(i)]);
    }
  const std::vector<int32_t> src = synthesize(pyramid, chart, sp, window);
  std::vector<int32_t> band(size_t(n) * size_t(kBand));
  for (int64_t t = 0; t < kBand; ++t)
    for (int64_t s = 0; s < n; ++s) {
      const Pixel q = e.at(s0 + s, t);
      band[size_t(t * n + s)] = src[size_t((q[1] - lo[1]) * window.width + q[0] - lo[0])];
    }
  return band;
}

}  // namespace

int64_t TurnedEdge::depth(const Pixel& q) const {
  switch (side) {
    case 0:
      return -1 - q[1];
    case 1:
      return q[0] - face_pixels;
    case 2:
      return q[1] - face_pixels;
    default:
      return -1 - q[0];
  }
}

int64_t TurnedEdge::along(const Pixel& q) const { return side % 2 == 0 ? q[0] : q[1]; }

int64_t TurnedEdge::unturned_depth(int64_t row) const {
  const int64_t face_row = int64_t(cell.row()) * (face_pixels >> cell.level()) + row;
  return polar_row < 0 ? face_pixels - 1 - face_row : face_row;
}

Pixel TurnedEdge::at(int64_t s, int64_t t) const {
  switch (side) {
    case 0:
      return {s, -1 - t};
    case 1:
      return {face_pixels + t, s};
    case 2:
      return {s, face_pixels + t};
    default:
      return {-1 - t, s};
  }
}

std::vector<TurnedEdge> turned_edges(const Grid& grid, const FacePlane& plane, CellId cell,
                                     int tile_size, int refine) {
  const int face = cell.face();
  const auto& here = plane.place(face);
  if (here[1] == 0) return {};
  const int guide_level = cell.level() + log2_tile_size(tile_size);
  const int n = tile_size << refine;
  if (n % kTurnedEdgePin != 0)
    throw Error("synthesis.transfer: output tiles of " + std::to_string(n) +
                " pixels on a polar face, not a multiple of " + std::to_string(kTurnedEdgePin));
  std::vector<TurnedEdge> edges;
  for (int g = 0; g < CellId::kNumFaces; ++g) {
    const auto& there = plane.place(g);
    const bool laid_against = there[0] == here[0] && std::abs(there[1] - here[1]) == 1;
    if (there[1] != 0 || laid_against || !UnfoldedFaces::adjacent(grid, face, g)) continue;
    const auto out = UnfoldedFaces(grid, g, guide_level + refine).place_tile(cell, n);
    if (!out) throw Error("synthesis.transfer: face " + std::to_string(g) + " has no place");
    TurnedEdge e;
    e.cell = cell;
    e.face = g;
    e.face_pixels = int64_t(n) << cell.level();
    e.place = *out;
    e.plane = {there[0] * e.face_pixels, there[1] * e.face_pixels};
    e.polar_row = int(here[1]);
    const Pixel centre = e.place.at(n / 2, n / 2);
    e.side = centre[1] < 0                ? 0
             : centre[0] >= e.face_pixels ? 1
             : centre[1] >= e.face_pixels ? 2
                                          : 3;
    int64_t nearest = e.depth(e.place.first);
    for (const auto& [c, r] : {std::pair{n - 1, 0}, std::pair{0, n - 1}, std::pair{n - 1, n - 1}})
      nearest = std::min(nearest, e.depth(e.place.at(c, r)));
    if (nearest < kTurnedEdgeBand) edges.push_back(e);
  }
  return edges;
}

std::vector<int32_t> join_turned_edges(const Grid& grid, const FacePlane& plane,
                                       const ExemplarPyramid& pyramid, const SynthesisParams& sp,
                                       const TargetGuides& guides, int halo,
                                       const std::vector<TurnedEdge>& edges,
                                       std::vector<int32_t> own) {
  if (edges.empty()) return own;
  if (!guides.distance.empty() || !guides.depth.empty() || !guides.light.empty())
    throw Error("synthesis.transfer: " + edges[0].cell.ToText() +
                "'s band along a turned edge lays no distance, depth or light guides");
  const int n = (int(guides.rect.width) - 2 * halo) << guides.shift;
  const ExemplarLevel& finest = pyramid.levels[0];
  const auto colour_error = [&](int32_t x, int32_t y) {
    float d = 0;
    for (size_t k = 0; k < 3; ++k) {
      const float v = finest.rgb[3 * size_t(x) + k] - finest.rgb[3 * size_t(y) + k];
      d += v * v;
    }
    return d;
  };
  // A pixel joins the band of its nearest turned edge (ties: the lower face), unless the edge
  // with the face the polar face is laid against is as near (turned_edges.h).
  const auto owner = [&](int64_t c, int64_t r) {
    size_t best = 0;
    for (size_t k = 1; k < edges.size(); ++k)
      if (edges[k].depth(edges[k].place.at(c, r)) < edges[best].depth(edges[best].place.at(c, r)))
        best = k;
    return edges[best].depth(edges[best].place.at(c, r)) < edges[best].unturned_depth(r)
               ? best
               : edges.size();
  };
  // The guides' face pixels, as the cell's chart lays them (as synthesis.transfer does).
  const int tile = n >> guides.shift;
  const CellId cell = edges[0].cell;
  const int level = cell.level() + log2_tile_size(tile);
  const HaloPixels held(cell, tile, halo, [&](int c, int r) {
    return plane.chart_pixel(grid, cell.face(), level, int64_t(cell.col()) * tile + c,
                             int64_t(cell.row()) * tile + r);
  });
  std::vector<int32_t> out = own;
  for (size_t k = 0; k < edges.size(); ++k) {
    const TurnedEdge& e = edges[k];
    int64_t s0 = e.along(e.place.first);
    for (const int64_t c : {0, n - 1})
      for (const int64_t r : {0, n - 1}) s0 = std::min(s0, e.along(e.place.at(c, r)));
    const std::vector<int32_t> band =
        chart_band(grid, plane, pyramid, sp, guides, held, level, halo, e, s0, n);
    std::vector<float> error(band.size());
    std::vector<size_t> at(band.size());  // each band pixel's index in the output
    for (int64_t t = 0; t < kTurnedEdgeBand; ++t)
      for (int64_t s = 0; s < n; ++s) {
        const Pixel p = e.place.tile_pixel(e.at(s0 + s, t));
        const size_t i = size_t(t * n + s);
        at[i] = size_t(p[1] * n + p[0]);
        error[i] = colour_error(band[i], own[at[i]]);
      }
    const std::vector<int> cut = seam_cut(error, s0, n, kTurnedEdgeBand, kTurnedEdgePin);
    for (int64_t s = 0; s < n; ++s)
      for (int64_t t = 0; t < cut[size_t(s)]; ++t) {
        const size_t i = size_t(t * n + s);
        if (owner(int64_t(at[i]) % n, int64_t(at[i]) / n) == k) out[at[i]] = band[i];
      }
  }
  return out;
}

}  // namespace maquette::synthesis
