#include <cmath>
#include <map>
#include <optional>

#include "core/error.h"
#include "core/unfolded_faces.h"
#include "runtime/step_exec.h"

namespace maquette {
namespace {

// Where a cell's tile lies in the region's mosaic: its pixel (c, r) at mosaic sample
// first + c * col_step + r * row_step (turned when its face is not the mosaic's anchor).
using TilePlace = UnfoldedFaces::TilePlace;

TilePlace mosaic_place(const UnfoldedFaces& plane, const Mosaic& mosaic, CellId cell, int size) {
  TilePlace p = *plane.place_tile(cell, size);  // the planner placed every cell
  p.first = {p.first[0] - mosaic.origin_col, p.first[1] - mosaic.origin_row};
  return p;
}

// Copies `src` (no halo) into `dst` at `at`, or the reverse.
void paste(const Tile<float>& src, Tile<float>& dst, const TilePlace& at) {
  for (int r = 0; r < src.size(); ++r)
    for (int c = 0; c < src.size(); ++c) {
      const auto q = at.at(c, r);
      for (int k = 0; k < src.channels(); ++k) dst.at(int(q[0]), int(q[1]), k) = src.at(c, r, k);
    }
}

void cut(const Tile<float>& src, Tile<float>& dst, const TilePlace& at) {
  for (int r = 0; r < dst.size(); ++r)
    for (int c = 0; c < dst.size(); ++c) {
      const auto q = at.at(c, r);
      for (int k = 0; k < dst.channels(); ++k) dst.at(c, r, k) = src.at(int(q[0]), int(q[1]), k);
    }
}

// The features of the port within its reach of any of `cells`, by id.
FeatureList near_any(const FeaturePort& port, const std::vector<CellId>& cells) {
  std::map<int64_t, const VectorFeature*> by_id;
  for (const CellId c : cells)
    for (const VectorFeature* f : port.index->within(CellOutline(default_grid(), c), port.reach_m))
      by_id.emplace(f->id, f);
  FeatureList out;
  for (const auto& [id, f] : by_id) out.push_back(f);
  return out;
}

// Fills the samples within `halo` of the cells' tiles in `mosaic` (of `layer`, pasted at their
// places) that no cell's tile covers, from the store's tiles there, as a cell step's halo reads
// its neighbours: the ring around the cells' square, and where the cells do not fill it (a
// region that is not a square of cells, or across a seam). NaN where the plane has no face (a
// corner gap) or the layer no tile.
void fill_halo(const UnfoldedFaces& plane, const Mosaic& input, const std::vector<CellId>& cells,
               int halo, const LayerInfo& layer, const StepIO& io, int tile_size,
               Tile<float>& mosaic) {
  const int side = mosaic.size();
  std::vector<char> covered(size_t(side) * size_t(side), 0);
  std::vector<TilePlace> places;
  for (const CellId c : cells) {
    places.push_back(mosaic_place(plane, input, c, tile_size));
    for (int r = 0; r < tile_size; ++r)
      for (int k = 0; k < tile_size; ++k) {
        const auto q = places.back().at(k, r);
        covered[size_t(q[1]) * size_t(side) + size_t(q[0])] = 1;
      }
  }
  const int level = input.level - log2_tile_size(tile_size);
  std::map<CellId, std::optional<Tile<float>>> tiles;
  for (const TilePlace& at : places)
    for (int r = -halo; r < tile_size + halo; ++r)
      for (int c = -halo; c < tile_size + halo; ++c) {
        const auto q = at.at(c, r);
        const int col = int(q[0]), row = int(q[1]);
        char& done = covered[size_t(row) * size_t(side) + size_t(col)];
        if (done) continue;  // a cell's own sample, or filled already
        done = 1;
        const auto pixel = plane.from_anchor(input.origin_col + col, input.origin_row + row);
        if (!pixel) continue;
        const CellId cell = CellId::FromFaceColRow(
            pixel->face, level, uint32_t(pixel->col / tile_size), uint32_t(pixel->row / tile_size));
        auto it = tiles.find(cell);
        if (it == tiles.end()) it = tiles.emplace(cell, io.read(layer, cell)).first;
        if (!it->second) continue;
        for (int k = 0; k < mosaic.channels(); ++k)
          mosaic.at(col, row, k) =
              it->second->at(int(pixel->col % tile_size), int(pixel->row % tile_size), k);
      }
}

// A refined step ("refine": k) writes output mosaics, and so tiles, 2^k times finer: the same
// place at pixel level + k.
void refine_mosaic(Mosaic& m, int refine) {
  m.level += refine;
  m.origin_col <<= refine;
  m.origin_row <<= refine;
}

}  // namespace

void run_region_step(const StepPlan& plan, StepIO& io, Progress& progress) {
  const auto& op = static_cast<const RegionOperator&>(*plan.step->op);
  const std::vector<CellId>& cells = plan.cells.cells();
  if (cells.empty()) return;
  const int n = plan.tile_size;
  const auto [face, col0, row0, extent] = plan.mosaic;
  // The cells' square grown by the operator's halo on every side: at most kMaxMosaicSide
  // (checked by plan_run).
  const int halo = op.spec().halo;
  const int side = int(extent * n) + 2 * halo;

  Mosaic input;
  input.face = face;
  input.level = plan.level + log2_tile_size(n);
  input.origin_col = col0 * n - halo;
  input.origin_row = row0 * n - halo;
  const UnfoldedFaces plane(default_grid(), face, input.level);
  Mosaic output = input;
  for (const auto& [port, layer] : plan.inputs) {
    Tile<float> mosaic(side, layer.channels, 0, NAN);
    for (const CellId c : cells)
      if (const auto tile = io.read(layer, c))
        paste(*tile, mosaic, mosaic_place(plane, input, c, n));
    if (halo > 0) fill_halo(plane, input, cells, halo, layer, io, n, mosaic);
    input.layers.emplace(port, std::move(mosaic));
  }
  for (const FeaturePort& f : plan.features) input.features[f.port] = near_any(f, cells);
  const int refine = plan.step->refine;
  refine_mosaic(output, refine);
  const UnfoldedFaces out_plane(default_grid(), face, output.level);
  output.layers = io.blank_outputs(side << refine);
  for (const CellId c : cells) output.content.emplace(c, io.blank_content(c));
  try {
    op.run({&default_grid(), &plan.params, &io.store(), &plan.inputs}, input, output);
  } catch (const std::exception& e) {
    throw Error(plan.step->label() + " failed on the region's mosaic: " + e.what());
  } catch (...) {
    throw Error(plan.step->label() + " failed on the region's mosaic: unknown exception");
  }
  for (const auto& [port, layer] : plan.outputs) {
    if (layer.kind != LayerKind::Raster) continue;
    const Tile<float>& m = output.layers.at(port);
    if (m.size() != side << refine || m.channels() != layer.channels)
      throw Error(plan.step->label() + ": the operator changed the size of output mosaic '" + port +
                  "'");
  }

  if (output.content.size() != cells.size())  // the runner prepared one entry per cell
    throw Error(plan.step->label() + ": the operator added content for cells not of the step");

  std::vector<TileSet> tiles(cells.size(), io.blank_outputs(n << refine));
  std::vector<CellOutput> outputs;
  for (size_t i = 0; i < cells.size(); ++i) {
    for (auto& [port, tile] : tiles[i])
      cut(output.layers.at(port), tile, mosaic_place(out_plane, output, cells[i], n << refine));
    try {
      outputs.push_back(
          {cells[i], &tiles[i], io.encode_content(cells[i], output.content.at(cells[i]))});
    } catch (const std::exception& e) {
      throw Error(plan.step->label() + " failed on cell " + cells[i].ToText() + ": " + e.what());
    }
  }
  io.write(outputs);
  progress.advance(int64_t(cells.size()));
}

}  // namespace maquette
