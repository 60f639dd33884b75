#include "cli/export_jobs.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <string_view>

#include "core/error.h"
#include "core/geojson.h"
#include "core/grid.h"
#include "core/output_clash.h"
#include "image/quicklook.h"
#include "plugins/mesh_export.h"
#include "runtime/plugin.h"
#include "store/store.h"
#include "vector/draw_features.h"

namespace maquette::cli {
namespace {

RegionSpec region_of(const RegionOptions& o) {
  RegionSpec region;
  if (!o.bbox.empty()) {
    check_bbox(o.bbox, "--bbox");
    region.bbox = {o.bbox[0], o.bbox[1], o.bbox[2], o.bbox[3]};
  }
  for (const std::string& id : o.cells) region.cells.push_back(CellId::Parse(id));
  return region;
}

bool metres(const std::string& units) {
  return units == "m" || units == "metre" || units == "metres" || units == "meter" ||
         units == "meters";
}

// Runs an export writing files into the directory `dir`. Each file is written whole or not at all
// (core/output_file.h); if the export fails, the files it wrote into a directory that did not
// exist or was empty are removed again, so that a failed export leaves nothing behind.
// Anything else at `dir` (a file: the store itself) is never removed.
template <typename Export>
void into_directory(const std::string& dir, Export&& write) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const bool existed = fs::exists(fs::symlink_status(dir, ec));
  const bool empty_directory = fs::is_directory(dir, ec) && fs::is_empty(dir, ec);
  try {
    write();
  } catch (...) {
    if (!existed) fs::remove_all(dir, ec);
    if (empty_directory)
      for (const auto& entry : fs::directory_iterator(dir, ec)) fs::remove_all(entry.path(), ec);
    throw;
  }
}

// The store an export reads, once its output `out` is known not to be it (however spelled).
std::unique_ptr<Store> open_source(const std::string& store, const std::string& out) {
  check_outputs_spare_inputs({out}, {{"the store", store}});
  return Store::open(store, Store::Mode::ReadOnly);
}

// Sorted, each once (a cell given twice was meshed twice).
std::vector<CellId> parse_cells(const std::vector<std::string>& ids) {
  std::vector<CellId> cells;
  for (const std::string& id : ids) cells.push_back(CellId::Parse(id));
  std::sort(cells.begin(), cells.end());
  cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  return cells;
}

}  // namespace

void run_export(GtiffJob job) {
  const auto store = open_source(job.store, job.out);
  job.spec.region = region_of(job.region);
  export_geotiff(*store, default_grid(), job.spec, job.out);
  spdlog::info("wrote {} ({})", job.out, job.spec.crs);
}

void run_export(const PngJob& o) {
  const auto store = open_source(o.store, o.out);
  const Grid& grid = default_grid();
  const LayerInfo info = store->require_layer(o.layer);
  QuicklookStyle style;
  if (info.semantics == Semantics::Categorical) style.classes = class_table(info);
  if (!o.ramp.empty())
    style.ramp = parse_ramp(o.ramp);
  else if (metres(info.units) && info.channels == 1 && !style.classes)
    style.ramp = Ramp::Hypsometric;
  if (!o.range.empty()) style.range = std::make_pair(o.range[0], o.range[1]);
  style.hillshade = o.hillshade;
  style.legend = o.legend;
  style.units = info.units;
  for (int b : o.bands) style.bands.push_back(b - 1);
  const RegionSpec region = region_of(o.region);
  // A features layer is drawn alone on a plain background; --overlay draws one over a raster.
  const bool features_alone = info.kind == LayerKind::Features;
  check_quicklook_style(style, features_alone ? 0 : info.channels);
  if (features_alone && !o.overlay.empty())
    throw Error("--overlay draws features over a raster layer; '" + o.layer +
                "' is a features layer (drawn alone)");
  const std::vector<Feature> features =
      features_alone ? features_in_region(*store, grid, info, region)
      : o.overlay.empty()
          ? std::vector<Feature>{}
          : features_in_region(*store, grid, store->require_layer(o.overlay), region);
  Overlay overlay;
  if (!features.empty())
    overlay = [&](RgbaImage& map, const PictureFrame& frame) {
      if (features_alone) fill_background(map);
      draw_features(map, frame, features);
    };
  if (features_alone) style.legend = false;  // nothing but the features to explain
  const Projection projection = parse_projection(o.projection);
  const PictureRaster mosaic =
      features_alone
          ? blank_picture(grid, region, features, projection, o.max_size)
          : mosaic_layer(
                *store, grid, o.layer, layer_tile_cells(*store, grid, info, region),
                {region.bbox, projection, o.max_size, info.semantics != Semantics::Categorical});
  write_quicklook_png(mosaic, style, o.out, overlay);
  const PictureFrame& f = *mosaic.frame;
  spdlog::info("wrote {} ({} x {} px of {:.6g} x {:.6g} {}, {})", o.out, mosaic.width,
               mosaic.height, f.x_step, f.y_step,
               f.projection == Projection::LonLat ? "degrees" : "m", f.crs_name());
}

void run_export(const FeaturesJob& job) {
  const auto store = open_source(job.store, job.out);
  const LayerInfo layer = store->require_layer(job.layer);
  const std::vector<Feature> features =
      features_in_region(*store, default_grid(), layer, region_of(job.region));
  write_features(layer, features, job.format, job.out);
  spdlog::info("wrote {} ({} features)", job.out, features.size());
}

void run_export(Tiles3dJob job) {
  const auto store = open_source(job.store, job.out);
  job.spec.region = region_of(job.region);
  if (!job.levels.empty()) {
    // Whole numbers A <= B within the grid's levels, nothing else (-5..-1 and 9..10x were taken).
    const auto level = [&](std::string_view text) {
      int v = -1;
      const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), v);
      return error == std::errc() && end == text.data() + text.size() ? v : -1;
    };
    const size_t dots = job.levels.find("..");
    const std::string_view levels = job.levels;
    const int a = dots == std::string::npos ? -1 : level(levels.substr(0, dots)),
              b = dots == std::string::npos ? -1 : level(levels.substr(dots + 2));
    if (a < 0 || b < a || b > CellId::kMaxLevel)
      throw Error("--levels '" + job.levels + "': expected A..B, levels 0 <= A <= B <= " +
                  std::to_string(CellId::kMaxLevel) + ", e.g. 6..10");
    job.spec.min_level = a;
    job.spec.max_level = b;
  }
  int64_t tiles = 0;
  into_directory(job.out, [&] {
    tiles = plugin_function<decltype(maquette_mesh_tiles3d)>(kMeshPlugin, kTiles3dEntry)(
        *store, default_grid(), job.spec, job.out);
  });
  spdlog::info("wrote {}/tileset.json ({} tiles)", job.out, tiles);
}

void run_glb_export(const MeshJob& job) {
  const auto store = open_source(job.store, job.out);
  plugin_function<decltype(maquette_mesh_glb)>(kMeshPlugin, kGlbEntry)(
      *store, default_grid(), GlbExport{job.terrain, job.content}, parse_cells(job.cells), job.out);
  spdlog::info("wrote {}", job.out);
}

void run_drc_export(const MeshJob& job) {
  const auto store = open_source(job.store, job.out);
  into_directory(job.out, [&] {
    plugin_function<decltype(maquette_mesh_drc)>(kMeshPlugin, kDrcEntry)(
        *store, default_grid(), job.terrain, parse_cells(job.cells), job.out);
  });
  spdlog::info("wrote {}", job.out);
}

}  // namespace maquette::cli
