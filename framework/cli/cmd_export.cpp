// maquette export png: quicklooks of store layers.
#include <memory>
#include <string>
#include <vector>

#include <spdlog/spdlog.h>

#include "cli/commands.h"
#include "core/error.h"
#include "core/grid.h"
#include "image/quicklook.h"
#include "store/store.h"

namespace maquette::cli {
namespace {

struct PngOptions {
  std::string store, layer, out, ramp = "grey";
  std::vector<std::string> cells;
  std::vector<double> range;
  int max_size = 2048;
};

void export_png(const PngOptions& o) {
  const auto store = Store::open(o.store, Store::Mode::ReadOnly);
  std::vector<CellId> cells;
  for (const std::string& id : o.cells) cells.push_back(CellId::Parse(id));
  QuicklookStyle style{parse_ramp(o.ramp), std::nullopt};
  if (!o.range.empty()) style.range = std::make_pair(o.range[0], o.range[1]);
  const LonLatRaster mosaic = mosaic_layer(*store, default_grid(), o.layer, cells, o.max_size);
  write_quicklook_png(mosaic, style, o.out);
  spdlog::info("wrote {} ({} x {} px, {:.6f} degrees/px, lon/lat)", o.out, mosaic.width,
               mosaic.height, mosaic.step);
}

}  // namespace

void add_export_command(CLI::App& app) {
  CLI::App* exp = app.add_subcommand("export", "Get layers out of a store");
  exp->require_subcommand(1);
  auto o = std::make_shared<PngOptions>();
  CLI::App* png = exp->add_subcommand("png", "Write a PNG quicklook of a layer (colour ramp, stretch)");
  png->add_option("STORE", o->store, "Store file")->required();
  png->add_option("OUT", o->out, "Output PNG file")->required();
  png->add_option("--layer", o->layer, "Layer to draw")->required();
  png->add_option("--ramp", o->ramp, "Colour ramp for one-channel layers: grey, terrain, slope")
      ->capture_default_str();
  png->add_option("--range", o->range, "Values drawn as the ramp's ends (default: 2-98 % of the data)")
      ->expected(2);
  png->add_option("--cells", o->cells, "Only these cells (default: every tile of the layer)");
  png->add_option("--max-size", o->max_size, "Longest side in pixels (coarser overviews are used above it)")
      ->capture_default_str()
      ->check(CLI::Range(16, 65536));
  png->callback([o] { export_png(*o); });
}

}  // namespace maquette::cli
