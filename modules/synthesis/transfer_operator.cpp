// synthesis.transfer: paper 000's transfer of a painting onto the store's land cover (and
// altitude), cell by cell, seamless: synthesis.h over each output tile's pixels in the plane of
// the grid's faces (core/face_plane.h), and along a polar face's turned edges the equatorial
// face's chart joined by a minimum-error cut (turned_edges.h).
#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "chart_guides.h"
#include "core/error.h"
#include "core/face_plane.h"
#include "exemplar.h"
#include "exemplar_params_check.h"
#include "operators.h"
#include "runtime/input_halo.h"
#include "synthesis.h"
#include "transfer_exemplar.h"
#include "transfer_params.h"
#include "turned_edges.h"

namespace maquette::synthesis {
namespace {

OperatorSpec transfer_spec() {
  OperatorSpec s;
  s.name = "synthesis.transfer";
  s.description =
      "Paints the land cover with pieces of a painting (paper 000; Lefebvre & Hoppe 2005 "
      "parallel synthesis guided by land cover and altitude): colours and source coordinates";
  s.inputs = {single_channel_input("landcover",
                                   "target land-cover classes (ingest them with \"as\": "
                                   "\"landcover\")",
                                   Semantics::Categorical),
              single_channel_input("dem",
                                   "elevation in metres, the altitude guide (with "
                                   "altitude_range)",
                                   Semantics::Continuous, true)};
  s.outputs = {
      {"rgb", "the painting's colours (0 is nodata: a channel at 0 in the painting is written 1)",
       DType::U8, 3, Semantics::Continuous, "", 0.0},
      {"source",
       "painting pixel (column, row) each output pixel was copied from: the top-left pixel of its "
       "exemplar_scale block; and the painting (0: painting, i: exemplars[i - 1])",
       DType::F32, 3, Semantics::Continuous, "px",
       std::nullopt},  // NaN where the land cover has no data
  };
  // In input pixels: the output's synthesis_halo() at refine 0, less at finer outputs.
  s.halo = synthesis_halo();
  s.refinable = true;
  s.writes_all_samples = true;
  s.params_schema = transfer_params_schema();
  s.check_params = [name = s.name](const json& params, const std::set<std::string>& mapped_inputs) {
    check_exemplar_params(params, name, mapped_inputs.count("dem") > 0);
  };
  return s;
}

class Transfer : public CellOperator {
 public:
  const OperatorSpec& spec() const override { return spec_; }

  void run(const CellContext& ctx, CellData& data) const override {
    const json& params = *ctx.params;
    const auto table = class_table(params.at("landcover_classes"), spec_.name);
    check_table_fits(table, ctx.input_layer("landcover"), spec_.name);
    const auto exemplar = transfer_exemplar(params);
    const Tile<float>& landcover = input_with_halo(spec_.name, ctx, data, "landcover", spec_.halo);
    const int halo = landcover.halo(), side = landcover.stride();

    // Global pixels of the faces' plane (core/face_plane.h): the halo's pixels from a neighbour
    // face laid unturned are there that face's own (synthesis.h: where it is seamless), and
    // beyond a face corner the face's chart lays them (chart_guides.h), not the halo's fold.
    const FacePlane plane(*ctx.grid);
    TargetGuides guides;
    const auto corner = plane.tile_pixel(ctx.cell, ctx.tile_size, -halo, -halo);
    guides.rect = {corner[0], corner[1], side, side};
    guides.shift = ctx.refine;
    const std::vector<int64_t> order = chart_order(*ctx.grid, plane, ctx.cell, ctx.tile_size, halo);
    const auto laid = [&](const Tile<float>& t, int c, int r) {
      if (order.empty()) return t.at(c - halo, r - halo);
      const int64_t i = order[size_t(r) * size_t(side) + size_t(c)];
      return t.at(int(i % side) - halo, int(i / side) - halo);
    };
    guides.labels.resize(size_t(side) * size_t(side));
    for (int r = 0; r < side; ++r)
      for (int c = 0; c < side; ++c)
        guides.labels[size_t(r) * size_t(side) + size_t(c)] =
            painting_class(table, laid(landcover, c, r));
    const auto range = altitude_range(params, spec_.name, data.inputs.count("dem") > 0);
    if (range) {
      const Tile<float>& dem = input_with_halo(spec_.name, ctx, data, "dem", spec_.halo);
      guides.altitude.resize(guides.labels.size());
      for (int r = 0; r < side; ++r)
        for (int c = 0; c < side; ++c)
          guides.altitude[size_t(r) * size_t(side) + size_t(c)] =
              altitude_guide(laid(dem, c, r), *range);
    }

    const SynthesisParams sp = synthesis_params(params);
    const int n = ctx.tile_size << ctx.refine;
    guides.col_period = plane.wrap_columns(ctx.cell, n);
    const auto first = plane.tile_pixel(ctx.cell, n, 0, 0);
    const PixelRect out{first[0], first[1], n, n};
    // Where the land cover has no data the output has none either (its nodata): the synthesis
    // computes only what the other pixels read (none: nothing).
    std::vector<uint8_t> land(size_t(n) * size_t(n));
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < n; ++c)
        land[size_t(r) * size_t(n) + size_t(c)] =
            !std::isnan(landcover.at(c >> ctx.refine, r >> ctx.refine));
    const bool any_land = std::find(land.begin(), land.end(), 1) != land.end();
    // Along a polar face's turned edges, the band continued from the equatorial face's chart
    // (its cut reads the band's every pixel: there the whole window is computed).
    const auto edges = turned_edges(*ctx.grid, plane, ctx.cell, ctx.tile_size, ctx.refine);
    const std::vector<int32_t> src =
        any_land ? join_turned_edges(*ctx.grid, plane, exemplar->pyramid, sp, guides, halo, edges,
                                     synthesize(exemplar->pyramid, guides, sp, out,
                                                edges.empty() ? land : std::vector<uint8_t>{}))
                 : std::vector<int32_t>{};

    const ExemplarLevel& e = exemplar->pyramid.levels[0];
    const auto target = [&](const char* port, int channels) -> Tile<float>* {
      if (!data.wants(port)) return nullptr;
      Tile<float>& t = data.output(port);
      if (t.size() != n || t.channels() != channels || t.halo() != 0)
        t = Tile<float>::uninitialized(n, channels);
      return &t;
    };
    Tile<float>* rgb = target("rgb", 3);
    Tile<float>* source = target("source", 3);
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < n; ++c) {
        if (!land[size_t(r) * size_t(n) + size_t(c)]) {
          for (int k = 0; k < 3 && rgb; ++k) rgb->at(c, r, k) = NAN;
          for (int k = 0; k < 3 && source; ++k) source->at(c, r, k) = NAN;
          continue;
        }
        const size_t s = size_t(src[size_t(r) * size_t(n) + size_t(c)]);
        if (rgb)
          for (int k = 0; k < 3; ++k) rgb->at(c, r, k) = colour_byte(e.rgb[3 * s + size_t(k)]);
        if (source) {
          const SourcePixel from = exemplar->source_of(int32_t(s));
          source->at(c, r, 0) = float(from.col);
          source->at(c, r, 1) = float(from.row);
          source->at(c, r, 2) = float(from.exemplar);
        }
      }
  }

 private:
  OperatorSpec spec_ = transfer_spec();
};

}  // namespace

std::unique_ptr<Operator> make_transfer() { return std::make_unique<Transfer>(); }

}  // namespace maquette::synthesis
