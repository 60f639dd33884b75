// maquette export gtiff|png|tiles3d|glb|drc: layers out of a store as GeoTIFF, PNG quicklooks,
// 3D Tiles, GLB or Draco terrain meshes.
#include <spdlog/spdlog.h>

#include <memory>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "core/error.h"
#include "core/geojson.h"
#include "core/grid.h"
#include "geotiff/export_geotiff.h"
#include "gltf/export_glb.h"
#include "image/quicklook.h"
#include "store/store.h"
#include "tiles3d/export_tiles3d.h"

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

void add_terrain_options(CLI::App* cmd, TerrainSettings& t, bool texture) {
  cmd->add_option("--dem", t.dem, "DEM layer (one-channel heights in metres)")->required();
  if (texture) cmd->add_option("--texture", t.texture, "Imagery layer (uint8, 1, 3 or 4 channels)");
  cmd->add_option("--decimation", t.decimation, "A vertex every K DEM pixels")
      ->capture_default_str();
  cmd->add_option("--position-bits", t.bits.position, "Draco position quantization bits")
      ->capture_default_str();
  cmd->add_option("--texcoord-bits", t.bits.texcoord, "Draco texture coordinate bits")
      ->capture_default_str();
  cmd->add_option("--normal-bits", t.bits.normal, "Draco normal bits")->capture_default_str();
  cmd->add_option("--max-mib", t.max_bytes, "Refuse exports estimated above this size (MiB)")
      ->capture_default_str()
      ->transform([](std::string v) { return std::to_string(std::stoll(v) << 20); });
  cmd->add_flag("--force", t.force, "Write into a non-empty output and above --max-mib");
}

std::vector<CellId> parse_cells(const std::vector<std::string>& ids) {
  std::vector<CellId> cells;
  for (const std::string& id : ids) cells.push_back(CellId::Parse(id));
  return cells;
}

struct Tiles3dOptions {
  std::string store, out, levels;
  RegionOptions region;
  Tiles3dExport spec;
};

void export_3d_tiles(Tiles3dOptions& o) {
  const auto store = Store::open(o.store, Store::Mode::ReadOnly);
  o.spec.region = region_of(o.region);
  if (!o.levels.empty()) {
    const size_t dots = o.levels.find("..");
    try {
      if (dots == std::string::npos) throw std::invalid_argument("no ..");
      o.spec.min_level = std::stoi(o.levels.substr(0, dots));
      o.spec.max_level = std::stoi(o.levels.substr(dots + 2));
    } catch (const std::exception&) {
      throw Error("--levels '" + o.levels + "': expected A..B, e.g. 6..10");
    }
  }
  const int64_t tiles = export_tiles3d(*store, default_grid(), o.spec, o.out);
  spdlog::info("wrote {}/tileset.json ({} tiles)", o.out, tiles);
}

void add_tiles3d_command(CLI::App* exp) {
  auto o = std::make_shared<Tiles3dOptions>();
  CLI::App* cmd = exp->add_subcommand(
      "tiles3d", "Write terrain as a 3D Tiles 1.1 tileset of Draco-compressed GLB (cell tree)");
  cmd->add_option("STORE", o->store, "Store file")->required();
  cmd->add_option("OUTDIR", o->out, "Output directory (tileset.json, tiles/, subtrees/)")
      ->required();
  add_terrain_options(cmd, o->spec.terrain, true);
  add_region_options(cmd, o->region);
  cmd->add_option("--content", o->spec.content,
                  "3D content layers (meshes, instances) added to the tiles of their cells");
  cmd->add_option("--levels", o->levels,
                  "Cell levels A..B (default: the DEM's level and 4 above; coarser levels read "
                  "overviews)");
  cmd->add_flag(
      "--no-draco", [o](int64_t) { o->spec.terrain.draco = false; },
      "Plain (uncompressed) GLB, for comparisons");
  cmd->callback([o] { export_3d_tiles(*o); });
}

struct MeshOptions {
  std::string store, out;
  std::vector<std::string> cells;
  TerrainSettings terrain;
};

void add_glb_command(CLI::App* exp) {
  auto o = std::make_shared<MeshOptions>();
  CLI::App* cmd =
      exp->add_subcommand("glb", "Write the terrain of a few cells into one Draco-compressed GLB");
  cmd->add_option("STORE", o->store, "Store file")->required();
  cmd->add_option("OUT", o->out, "Output .glb file")->required();
  cmd->add_option("--cells", o->cells, "Cells (text ids), each at its own level")->required();
  add_terrain_options(cmd, o->terrain, true);
  cmd->add_flag(
      "--no-draco", [o](int64_t) { o->terrain.draco = false; }, "Plain (uncompressed) GLB");
  cmd->callback([o] {
    const auto store = Store::open(o->store, Store::Mode::ReadOnly);
    export_glb(*store, default_grid(), o->terrain, parse_cells(o->cells), o->out);
    spdlog::info("wrote {}", o->out);
  });
}

void add_drc_command(CLI::App* exp) {
  auto o = std::make_shared<MeshOptions>();
  CLI::App* cmd = exp->add_subcommand("drc", "Write one raw Draco terrain mesh per cell");
  cmd->add_option("STORE", o->store, "Store file")->required();
  cmd->add_option("OUTDIR", o->out, "Output directory (CELL.drc, frame.json)")->required();
  cmd->add_option("--cells", o->cells, "Cells (text ids), each at its own level")->required();
  add_terrain_options(cmd, o->terrain, false);
  cmd->callback([o] {
    const auto store = Store::open(o->store, Store::Mode::ReadOnly);
    export_drc(*store, default_grid(), o->terrain, parse_cells(o->cells), o->out);
    spdlog::info("wrote {}", o->out);
  });
}

}  // namespace

void add_export_command(CLI::App& app) {
  CLI::App* exp = app.add_subcommand("export", "Get layers out of a store");
  exp->require_subcommand(1);
  add_gtiff_command(exp);
  add_png_command(exp);
  add_tiles3d_command(exp);
  add_glb_command(exp);
  add_drc_command(exp);
}

}  // namespace maquette::cli
