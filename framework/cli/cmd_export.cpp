// maquette export gtiff|png: layers out of a store as GeoTIFF or PNG quicklooks.
#include <spdlog/spdlog.h>

#include <memory>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "core/error.h"
#include "core/geojson.h"
#include "core/grid.h"
#include "geotiff/export_geotiff.h"
#include "image/quicklook.h"
#include "store/store.h"

namespace maquette::cli {
namespace {

struct RegionOptions {
  std::vector<double> bbox;
  std::vector<std::string> cells;
};

RegionSpec region_of(const RegionOptions& o) {
  RegionSpec region;
  if (!o.bbox.empty()) {
    check_bbox(o.bbox, "--bbox");
    region.bbox = {o.bbox[0], o.bbox[1], o.bbox[2], o.bbox[3]};
  }
  for (const std::string& id : o.cells) region.cells.push_back(CellId::Parse(id));
  return region;
}

void add_region_options(CLI::App* cmd, RegionOptions& o) {
  auto* bbox = cmd->add_option("--bbox", o.bbox, "Only tiles overlapping this lon/lat box: W S E N")
                   ->expected(4);
  cmd->add_option("--cells", o.cells, "Only tiles in these cells (text ids, any levels)")
      ->excludes(bbox);
}

struct GtiffOptions {
  std::string store, out;
  RegionOptions region;
  GeoTiffExport spec;
};

void export_gtiff(GtiffOptions& o) {
  const auto store = Store::open(o.store, Store::Mode::ReadOnly);
  o.spec.region = region_of(o.region);
  export_geotiff(*store, default_grid(), o.spec, o.out);
  spdlog::info("wrote {} ({})", o.out, o.spec.crs);
}

struct PngOptions {
  std::string store, layer, out, ramp;
  RegionOptions region;
  std::vector<double> range;
  std::vector<int> bands;
  bool hillshade = false;
  int max_size = 2048;
};

bool metres(const std::string& units) {
  return units == "m" || units == "metre" || units == "metres" || units == "meter" ||
         units == "meters";
}

void export_png(const PngOptions& o) {
  const auto store = Store::open(o.store, Store::Mode::ReadOnly);
  const Grid& grid = default_grid();
  const LayerInfo info = store->require_layer(o.layer);
  QuicklookStyle style;
  style.ramp = !o.ramp.empty()                            ? parse_ramp(o.ramp)
               : metres(info.units) && info.channels == 1 ? Ramp::Terrain
                                                          : Ramp::Grey;
  if (!o.range.empty()) style.range = std::make_pair(o.range[0], o.range[1]);
  style.hillshade = o.hillshade;
  for (int b : o.bands) style.bands.push_back(b - 1);
  if (info.semantics == Semantics::Categorical) style.classes = class_table(info);
  const LonLatRaster mosaic = mosaic_layer(
      *store, grid, o.layer, layer_tile_cells(*store, grid, info, region_of(o.region)), o.max_size);
  write_quicklook_png(mosaic, style, o.out);
  spdlog::info("wrote {} ({} x {} px, {:.6f} degrees/px, lon/lat)", o.out, mosaic.width,
               mosaic.height, mosaic.step);
}

void add_gtiff_command(CLI::App* exp) {
  auto o = std::make_shared<GtiffOptions>();
  CLI::App* cmd = exp->add_subcommand(
      "gtiff", "Write a layer as a tiled, compressed GeoTIFF (rHEALPix plane or an EPSG CRS)");
  cmd->add_option("STORE", o->store, "Store file")->required();
  cmd->add_option("OUT", o->out, "Output GeoTIFF (its CRS and class names also in OUT.aux.xml)")
      ->required();
  cmd->add_option("--layer", o->spec.layer, "Layer to write")->required();
  add_region_options(cmd, o->region);
  cmd->add_option(
      "--level", o->spec.level,
      "Cell level of the tiles written (default: the layer's; coarser reads overviews)");
  cmd->add_option("--crs", o->spec.crs,
                  "rhealpix (the grid's plane, tiles written exactly) or EPSG:NNNN (resampled: "
                  "nearest for categorical layers, bilinear otherwise)")
      ->capture_default_str();
  cmd->add_option("--resolution", o->spec.resolution,
                  "Pixel size in --crs units (default: the layer's pixel at the region centre)");
  cmd->callback([o] { export_gtiff(*o); });
}

void add_png_command(CLI::App* exp) {
  auto o = std::make_shared<PngOptions>();
  CLI::App* cmd = exp->add_subcommand(
      "png", "Write a PNG quicklook of a layer (colour ramp, hillshade, class colours, stretch)");
  cmd->add_option("STORE", o->store, "Store file")->required();
  cmd->add_option("OUT", o->out, "Output PNG file")->required();
  cmd->add_option("--layer", o->layer, "Layer to draw")->required();
  add_region_options(cmd, o->region);
  cmd->add_option("--ramp", o->ramp,
                  "Colour ramp for one-channel layers: grey, terrain, slope (default: terrain for "
                  "heights in metres, else grey)");
  cmd->add_flag("--hillshade", o->hillshade, "Multiply the ramp by a hillshade of the layer");
  cmd->add_option("--range", o->range,
                  "Values drawn as the ramp's ends (default: 2-98 % of the data, per band)")
      ->expected(2);
  cmd->add_option("--bands", o->bands, "Channels drawn as R,G,B for imagery (1-based)")
      ->delimiter(',')
      ->check(CLI::PositiveNumber);
  cmd->add_option("--max-size", o->max_size,
                  "Longest side in pixels (coarser overviews are used above it)")
      ->capture_default_str()
      ->check(CLI::Range(16, 65536));
  cmd->callback([o] { export_png(*o); });
}

}  // namespace

void add_export_command(CLI::App& app) {
  CLI::App* exp = app.add_subcommand("export", "Get layers out of a store");
  exp->require_subcommand(1);
  add_gtiff_command(exp);
  add_png_command(exp);
}

}  // namespace maquette::cli
