// maquette export gtiff|png|geojson|gpkg|tiles3d|glb|drc: layers out of a store as GeoTIFF, PNG
// quicklooks, GeoJSON or GeoPackage features, 3D Tiles, GLB or Draco terrain meshes.
#include <charconv>
#include <memory>

#include "cli/commands.h"
#include "cli/export_jobs.h"

namespace maquette::cli {
namespace {

// --bbox (`bbox_help` says what the export does with the box) or --cells.
void add_region_options(CLI::App* cmd, RegionOptions& o, const std::string& bbox_help) {
  auto* bbox = cmd->add_option("--bbox", o.bbox, bbox_help + ": W S E N")->expected(4);
  cmd->add_option("--cells", o.cells, "Only tiles in these cells (text ids, any levels)")
      ->excludes(bbox);
}

// --max-mib (in bytes) and --force: refuse exports estimated above a size unless forced.
void add_size_guard(CLI::App* cmd, int64_t& max_bytes, bool& force, const std::string& force_help) {
  constexpr int64_t kMostMib = int64_t(1) << 30;  // 1 PiB: its bytes fit int64_t
  cmd->add_option("--max-mib", max_bytes, "Refuse exports estimated above this size (MiB)")
      ->default_str(std::to_string(max_bytes >> 20))
      ->transform([](const std::string& v) {
        int64_t mib = 0;
        const auto [end, error] = std::from_chars(v.data(), v.data() + v.size(), mib);
        if (error != std::errc() || end != v.data() + v.size() || mib < 0 || mib > kMostMib)
          throw CLI::ValidationError("expected a whole number of MiB in 0.." +
                                     std::to_string(kMostMib) + ", got '" + v + "'");
        return std::to_string(mib << 20);
      });
  cmd->add_flag("--force", force, force_help);
}

void add_gtiff_command(CLI::App* exp) {
  auto o = std::make_shared<GtiffJob>();
  CLI::App* cmd = exp->add_subcommand(
      "gtiff", "Write a layer as a tiled, compressed GeoTIFF (rHEALPix plane or an EPSG CRS)");
  cmd->add_option("STORE", o->store, "Store file")->required();
  cmd->add_option("OUT", o->out, "Output GeoTIFF (its CRS and class names also in OUT.aux.xml)")
      ->required();
  cmd->add_option("--layer", o->spec.layer, "Layer to write")->required();
  add_region_options(cmd, o->region, "The lon/lat box the GeoTIFF is clipped to");
  cmd->add_option(
      "--level", o->spec.level,
      "Cell level of the tiles written (default: the layer's; coarser reads overviews)");
  cmd->add_option("--crs", o->spec.crs,
                  "rhealpix (the grid's plane, tiles written exactly) or EPSG:NNNN (resampled: "
                  "nearest for categorical layers, bilinear otherwise)")
      ->capture_default_str();
  cmd->add_option("--resolution", o->spec.resolution,
                  "Pixel size in --crs units (default: the layer's pixel at the region centre)");
  add_size_guard(cmd, o->spec.max_bytes, o->spec.force,
                 "Write above --max-mib (uncompressed size)");
  cmd->callback([o] { run_export(*o); });
}

void add_png_command(CLI::App* exp) {
  auto o = std::make_shared<PngJob>();
  CLI::App* cmd = exp->add_subcommand(
      "png", "Write a PNG quicklook of a layer (colour ramp, hillshade, class colours, stretch)");
  cmd->add_option("STORE", o->store, "Store file")->required();
  cmd->add_option("OUT", o->out,
                  "Output PNG file (its georeferencing in OUT.aux.xml and the world file .pgw)")
      ->required();
  cmd->add_option("--layer", o->layer,
                  "Layer to draw (a features layer: its features on a plain background)")
      ->required();
  cmd->add_option("--overlay", o->overlay,
                  "Features layer drawn over the picture (outlines, lines and points)");
  add_region_options(cmd, o->region, "The lon/lat box the picture shows");
  cmd->add_option("--ramp", o->ramp,
                  "Colour ramp for one-channel layers: hypsometric (atlas tints by metres, water "
                  "blue), or stretched: viridis, diverging (blue-white-red, centred on 0), grey, "
                  "terrain, slope (default: hypsometric for heights in metres, else diverging for "
                  "values of both signs, viridis for the others)");
  cmd->add_option("--projection", o->projection,
                  "lonlat, polar (Lambert azimuthal equal-area on the pole) or auto (polar for "
                  "a region around one pole)")
      ->capture_default_str();
  cmd->add_flag(
      "--no-legend", [o](int64_t) { o->legend = false; },
      "No legend (colour bar with values and units, or class names) below the picture");
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
  cmd->callback([o] { run_export(*o); });
}

void add_features_command(CLI::App* exp, const std::string& name, FeatureFormat format) {
  auto o = std::make_shared<FeaturesJob>();
  o->format = format;
  CLI::App* cmd = exp->add_subcommand(
      name, "Write a features layer as " +
                std::string(format == FeatureFormat::GeoJson ? "GeoJSON" : "a GeoPackage") +
                " (geometry in lon/lat and attributes as ingested)");
  cmd->add_option("STORE", o->store, "Store file")->required();
  cmd->add_option("OUT", o->out, "Output file")->required();
  cmd->add_option("--layer", o->layer, "Features layer to write")->required();
  auto* bbox =
      cmd->add_option("--bbox", o->region.bbox, "Only features meeting this lon/lat box: W S E N")
          ->expected(4);
  cmd->add_option("--cells", o->region.cells, "Only features indexed in these cells (text ids)")
      ->excludes(bbox);
  cmd->callback([o] { run_export(*o); });
}

void add_terrain_options(CLI::App* cmd, TerrainSettings& t, bool texture,
                         bool dem_required = true) {
  cmd->add_option("--dem", t.dem, "DEM layer (one-channel heights in metres)")
      ->required(dem_required);
  if (texture) cmd->add_option("--texture", t.texture, "Imagery layer (uint8, 1, 3 or 4 channels)");
  cmd->add_option("--decimation", t.decimation, "A vertex every K DEM pixels")
      ->capture_default_str();
  cmd->add_option("--position-bits", t.bits.position, "Draco position quantization bits")
      ->capture_default_str();
  cmd->add_option("--texcoord-bits", t.bits.texcoord, "Draco texture coordinate bits")
      ->capture_default_str();
  cmd->add_option("--normal-bits", t.bits.normal, "Draco normal bits")->capture_default_str();
  add_size_guard(cmd, t.max_bytes, t.force, "Write into a non-empty output and above --max-mib");
  if (texture)
    cmd->add_flag(
        "--no-stretch", [&t](int64_t) { t.stretch = false; },
        "The texture's values as stored (default: stretched like `export png`, 2-98 % per band)");
}

void add_tiles3d_command(CLI::App* exp) {
  auto o = std::make_shared<Tiles3dJob>();
  CLI::App* cmd = exp->add_subcommand(
      "tiles3d", "Write terrain as a 3D Tiles 1.1 tileset of Draco-compressed GLB (cell tree)");
  cmd->add_option("STORE", o->store, "Store file")->required();
  cmd->add_option("OUTDIR", o->out, "Output directory (tileset.json, tiles/, subtrees/)")
      ->required();
  add_terrain_options(cmd, o->spec.terrain, true);
  add_region_options(cmd, o->region, "Only tiles overlapping this lon/lat box");
  cmd->add_option("--content", o->spec.content,
                  "3D content layers (kinds mesh, instances, volume) added to the tiles of "
                  "their cells");
  cmd->add_option("--levels", o->levels,
                  "Cell levels A..B (default: the DEM's level and 4 above; coarser levels read "
                  "overviews)");
  cmd->add_flag(
      "--no-draco", [o](int64_t) { o->spec.terrain.draco = false; },
      "Plain (uncompressed) GLB, for comparisons");
  cmd->callback([o] { run_export(*o); });
}

void add_glb_command(CLI::App* exp) {
  auto o = std::make_shared<MeshJob>();
  CLI::App* cmd = exp->add_subcommand(
      "glb", "Write the terrain and 3D content of a few cells into one Draco-compressed GLB");
  cmd->add_option("STORE", o->store, "Store file")->required();
  cmd->add_option("OUT", o->out, "Output .glb file")->required();
  cmd->add_option("--cells", o->cells, "Cells (text ids), each at its own level")->required();
  add_terrain_options(cmd, o->terrain, true, false);
  cmd->add_option("--content", o->content,
                  "3D content layers (kinds mesh, instances, volume) of the cells, each cell's "
                  "content under a node of its own (with --dem, over the terrain)");
  cmd->add_flag(
      "--no-draco", [o](int64_t) { o->terrain.draco = false; }, "Plain (uncompressed) GLB");
  cmd->callback([o] { run_glb_export(*o); });
}

void add_drc_command(CLI::App* exp) {
  auto o = std::make_shared<MeshJob>();
  CLI::App* cmd = exp->add_subcommand("drc", "Write one raw Draco terrain mesh per cell");
  cmd->add_option("STORE", o->store, "Store file")->required();
  cmd->add_option("OUTDIR", o->out, "Output directory (CELL.drc, frame.json)")->required();
  cmd->add_option("--cells", o->cells, "Cells (text ids), each at its own level")->required();
  add_terrain_options(cmd, o->terrain, false);
  cmd->callback([o] { run_drc_export(*o); });
}

}  // namespace

void add_export_command(CLI::App& app) {
  CLI::App* exp = app.add_subcommand("export", "Get layers out of a store");
  exp->require_subcommand(1);
  add_gtiff_command(exp);
  add_png_command(exp);
  add_features_command(exp, "geojson", FeatureFormat::GeoJson);
  add_features_command(exp, "gpkg", FeatureFormat::GeoPackage);
  add_tiles3d_command(exp);
  add_glb_command(exp);
  add_drc_command(exp);
}

}  // namespace maquette::cli
