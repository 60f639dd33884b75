// plan_raster_ingest: sources, layer definition, level, cells and the size check.
#include <ogr_spatialref.h>
#include <sys/statvfs.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iterator>
#include <limits>

#include "core/data_footprint.h"
#include "core/error.h"
#include "core/json_file.h"
#include "core/region.h"
#include "gdal/class_table.h"
#include "gdal/footprint.h"
#include "gdal/raster_ingest.h"
#include "gdal/vertical_datum.h"

namespace maquette {
namespace {

std::string join(const std::vector<int>& v) {
  std::string s;
  for (int x : v) s += (s.empty() ? "" : ",") + std::to_string(x);
  return s;
}

std::string gib(double bytes) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f GiB", bytes / double(int64_t(1) << 30));
  return buf;
}

std::string crs_name(const std::string& wkt) {
  const OGRSpatialReference srs(wkt.c_str());
  const char* name = srs.GetName();
  const char* auth = srs.GetAuthorityName(nullptr);
  const char* code = srs.GetAuthorityCode(nullptr);
  std::string out = name ? name : "unknown";
  if (auth && code) out += std::string(" (") + auth + ":" + code + ")";
  return out;
}

// A DEM's vertical datum: --vertical-datum, else the first source's CRS, else the default.
VerticalDatum dem_vertical_datum(const RasterIngestOptions& o, const RasterSource& first) {
  if (!o.vertical_datum.empty()) return parse_vertical_datum(o.vertical_datum, "--vertical-datum");
  if (auto stated = source_vertical_datum(first.crs_wkt, first.path)) return *stated;
  return default_dem_vertical_datum();
}

std::string dem_units(const std::string& unit_type) {
  if (unit_type.empty() || unit_type == "metre" || unit_type == "meter" || unit_type == "metres")
    return "m";
  if (unit_type == "foot" || unit_type == "feet") return "ft";
  return unit_type;
}

// Unsigned dtypes: the largest value, signed: the smallest; imagery: 0 (the usual fill).
double sentinel_nodata(DType t, bool imagery) {
  if (imagery) return 0;
  switch (t) {
    case DType::U8:
      return 255;
    case DType::U16:
      return 65535;
    case DType::I16:
      return -32768;
    case DType::U32:
      return 4294967295.0;
    case DType::I32:
      return -2147483648.0;
    default:
      return std::numeric_limits<double>::quiet_NaN();
  }
}

int choose_level(const Grid& grid, int tile_size, double source_pixel_m) {
  for (int l = 0; l < CellId::kMaxLevel; ++l)
    if (grid.level_info(l, tile_size).pixel_m <= source_pixel_m * (1 + 1e-9)) return l;
  return CellId::kMaxLevel;
}

// The --bbox or --region as lon/lat polygons, empty without one.
std::vector<PolygonRings> region_polygons(const RasterIngestOptions& o) {
  if (o.bbox) {
    const auto& b = *o.bbox;
    check_bbox({b[0], b[1], b[2], b[3]}, "--bbox");
    const double east = b[2] < b[0] ? b[2] + 360 : b[2];  // across the antimeridian
    return {{{{b[0], b[1]}, {east, b[1]}, {east, b[3]}, {b[0], b[3]}, {b[0], b[1]}}}};
  }
  return o.region.empty() ? std::vector<PolygonRings>{} : read_geojson_polygons(o.region);
}

// Where the layer's samples come from: the sources' outlines, within the --bbox or --region.
DataFootprint data_footprint(const std::vector<Footprint>& footprints,
                             const std::vector<PolygonRings>& region) {
  std::vector<PolygonRings> sources;
  for (const Footprint& f : footprints)
    sources.insert(sources.end(), f.polygons.begin(), f.polygons.end());
  return DataFootprint(std::move(sources), region);
}

// Refuses a job of `tiles` tiles (unless force), with the estimate.
void check_size(const RasterIngestPlan& p, int64_t tiles, const std::string& store_path,
                bool force) {
  const auto dir = std::filesystem::absolute(store_path).parent_path();
  struct statvfs fs {};
  const double free_bytes = ::statvfs(dir.c_str(), &fs) == 0
                                ? double(fs.f_bavail) * double(fs.f_frsize)
                                : std::numeric_limits<double>::infinity();
  const int n = p.layer.tile_size;
  const double bytes = double(tiles) * n * n * p.layer.channels * double(dtype_size(p.layer.dtype));
  if (force ||
      (tiles <= kMaxIngestTiles && bytes <= double(kMaxIngestBytes) && bytes <= 0.5 * free_bytes))
    return;
  throw Error("the ingest would write " + std::to_string(tiles) + " tiles of " + std::to_string(n) +
              "x" + std::to_string(n) + "x" + std::to_string(p.layer.channels) + " " +
              std::string(dtype_name(p.layer.dtype)) + " at level " +
              std::to_string(p.layer.level) + " (up to " + gib(bytes) + " before compression; " +
              gib(free_bytes) + " free): over the limit of " + std::to_string(kMaxIngestTiles) +
              " tiles, " + gib(double(kMaxIngestBytes)) +
              " or half the free disk. Choose a coarser --level or a smaller --bbox/--region, "
              "or pass --force");
}

// Cells at `level` in the boxes of a source's part in the region, one box per polygon (a part
// across the antimeridian is two; a box edge follows a parallel, so a box 360 degrees wide is
// not a polygon of area 0 here).
double part_cells_estimate(const Footprint& part, int level) {
  double cells = 0;
  for (const PolygonRings& polygon : part.polygons) cells += cover_size_estimate({polygon}, level);
  return cells;
}

}  // namespace

RasterIngestPlan plan_raster_ingest(const std::string& store_path,
                                    const std::vector<std::string>& sources,
                                    const RasterIngestOptions& o) {
  static const std::vector<std::string> kAs{"dem", "imagery", "climate", "landcover", "raster"};
  if (std::find(kAs.begin(), kAs.end(), o.as) == kAs.end())
    throw Error("--as '" + excerpt(o.as) +
                "' is not one of dem, imagery, climate, landcover, raster (rasters), features, "
                "stations (vectors), model (a glTF file)");
  if (!o.vertical_datum.empty() && o.as != "dem")
    throw Error("--vertical-datum is for height layers (--as dem), not --as " + o.as);
  if (!o.classes.empty() && o.as != "landcover")  // it was ignored
    throw Error("--classes is for class layers (--as landcover), not --as " + o.as);
  if (sources.empty()) throw Error("no SOURCE given");
  if (o.layer.empty()) throw Error("--layer: a layer name is required");
  try {
    check_overview_tile_size(o.tile_size);
  } catch (const Error& e) {
    throw Error(std::string("--tile-size: ") + e.what());
  }
  if (o.level && (*o.level < 0 || *o.level > CellId::kMaxLevel))
    throw Error("--level " + std::to_string(*o.level) + " is outside 0.." +
                std::to_string(CellId::kMaxLevel));
  const Grid& grid = default_grid();
  const bool categorical = o.as == "landcover";
  const nlohmann::json classes =
      categorical && !o.classes.empty() ? parse_class_table(o.classes) : nlohmann::json();

  RasterIngestPlan p;
  p.source_pixel_m = std::numeric_limits<double>::infinity();
  std::vector<Footprint> footprints;
  for (const std::string& path : sources) {
    p.sources.push_back(describe_source(path, o.bands, o.src_crs));
    const RasterSource& s = p.sources.back();
    const RasterSource& first = p.sources.front();
    if (s.bands.size() != first.bands.size())
      throw Error("band counts differ: " + first.path + " has " +
                  std::to_string(first.bands.size()) + " band(s) (" + join(first.bands) + "), " +
                  s.path + " has " + std::to_string(s.bands.size()) + " (" + join(s.bands) +
                  "); use --bands to pick the same number from each");
    footprints.push_back(source_footprint(s));
    p.source_pixel_m = std::min(p.source_pixel_m, ground_pixel_m(s));
  }
  const RasterSource& first = p.sources.front();
  const int level = o.level ? *o.level : choose_level(grid, o.tile_size, p.source_pixel_m);
  p.target_pixel_m = grid.level_info(level, o.tile_size).pixel_m;

  // The layer's shape, needed by the size checks.
  LayerInfo& l = p.layer;
  l.channels = int(first.bands.size());
  l.tile_size = o.tile_size;
  l.level = level;
  const bool keep_dtype = (categorical || o.as == "imagery") && !first.scaled;
  l.dtype = keep_dtype ? first.dtype : DType::F32;
  // Limited to a --bbox or --region, each source's part inside it: a global source is not
  // covered whole at a fine level for a region of a few cells.
  const std::vector<PolygonRings> region = region_polygons(o);
  std::vector<Footprint> parts = footprints;
  if (!region.empty()) {
    for (Footprint& f : parts) f = clipped_footprint(f, region);
    if (std::ranges::all_of(parts, [](const Footprint& f) { return f.polygons.empty(); })) {
      std::string where;
      for (size_t i = 0; i < footprints.size(); ++i)
        where += (i ? "; " : "") + p.sources[i].path + ": " + footprints[i].describe();
      throw Error(std::string(o.bbox ? "--bbox" : "--region " + o.region) +
                  " does not overlap the sources (" + where + ")");
    }
  }
  // A first estimate before covering, since a cover at a level far too fine would itself
  // exhaust memory: from each source's ground area, or from its part in the region.
  double rough_tiles = 0;
  for (size_t i = 0; i < p.sources.size(); ++i)
    rough_tiles += region.empty() ? double(p.sources[i].width) * p.sources[i].height *
                                        std::pow(ground_pixel_m(p.sources[i]), 2) / grid.area(level)
                                  : part_cells_estimate(parts[i], level);
  if (rough_tiles > 4.0 * kMaxIngestTiles) check_size(p, int64_t(rough_tiles), store_path, o.force);

  for (const Footprint& f : parts) {
    std::vector<CellId> c = cover_footprint(grid, f, level), merged;
    std::set_union(p.cells.begin(), p.cells.end(), c.begin(), c.end(), std::back_inserter(merged));
    p.cells = std::move(merged);
  }

  l.name = o.layer;
  l.kind = LayerKind::Raster;
  l.semantics = categorical ? Semantics::Categorical : Semantics::Continuous;
  if (keep_dtype) {
    const auto& nd = first.nodata.front();
    l.nodata = nd ? *nd : sentinel_nodata(l.dtype, o.as == "imagery");
  }
  l.units = o.as == "dem"                           ? dem_units(first.unit_type)
            : o.as == "climate" || o.as == "raster" ? first.unit_type
                                                    : "";
  p.resampling = o.resampling ? *o.resampling
                 : p.target_pixel_m > p.source_pixel_m * (1 + 1e-6)
                     ? (categorical ? Resampling::Mode : Resampling::Average)
                     : (categorical ? Resampling::Nearest : Resampling::Bilinear);

  nlohmann::json srcs = nlohmann::json::array(), ids = nlohmann::json::array();
  for (size_t i = 0; i < p.sources.size(); ++i) {
    const RasterSource& s = p.sources[i];
    nlohmann::json nodata = nlohmann::json::array();
    for (const auto& nd : s.nodata) nodata.push_back(nd ? nlohmann::json(*nd) : nlohmann::json());
    srcs.push_back({{"path", s.path},
                    {"crs", crs_name(s.crs_wkt)},
                    {"size", {s.width, s.height}},
                    {"bands", s.bands},
                    {"dtype", dtype_name(s.dtype)},
                    {"nodata", nodata},
                    {"scale", s.scale},
                    {"offset", s.offset},
                    {"ground_pixel_m", ground_pixel_m(s)},
                    {"footprint", footprints[i].describe()}});
    ids.push_back({{"path", std::filesystem::absolute(s.path).string()},
                   {"bytes", s.file_size},
                   {"mtime_ns", s.mtime}});
  }
  l.provenance = {{"ingest", o.as},
                  {"sources", srcs},
                  {"resampling", resampling_name(p.resampling)},
                  {"source_pixel_m", p.source_pixel_m},
                  {"pixel_m", p.target_pixel_m},
                  {"footprint", data_footprint(footprints, region).to_json()}};
  if (!o.src_crs.empty()) l.provenance["src_crs"] = o.src_crs;
  if (o.as == "dem") l.provenance["vertical_datum"] = dem_vertical_datum(o, first).to_json();
  if (categorical) l.provenance["classes"] = classes.is_null() ? first.classes : classes;

  nlohmann::json limit;
  if (o.bbox) limit = {{"bbox", *o.bbox}};
  if (!o.region.empty()) limit = {{"geojson", std::filesystem::absolute(o.region).string()}};
  p.run = {{"maquette_ingest",
            {{"layer", o.layer},
             {"as", o.as},
             {"sources", ids},
             {"bands", o.bands},
             {"level", level},
             {"tile_size", o.tile_size},
             {"region", limit},
             {"src_crs", o.src_crs},
             {"resampling", resampling_name(p.resampling)},
             {"classes", l.provenance.value("classes", nlohmann::json())}}}};

  p.estimate_bytes = int64_t(p.cells.size()) * int64_t(o.tile_size) * o.tile_size * l.channels *
                     int64_t(dtype_size(l.dtype));
  check_size(p, int64_t(p.cells.size()), store_path, o.force);
  for (const RasterSource& s : p.sources) {
    std::string nd;
    for (const auto& v : s.nodata)
      nd += (nd.empty() ? "" : ", ") + (v ? std::to_string(*v) : "none");
    if (!SourceReader(s).any_valid())
      throw Error(s.path + ": every sample is nodata (nodata " + nd + "): nothing to ingest");
  }
  return p;
}

}  // namespace maquette
