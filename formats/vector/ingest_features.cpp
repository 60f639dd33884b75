// ingest_features: OGR layers into a features layer, in batches recorded for --resume.
#include <cpl_error.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <set>

#include "core/error.h"
#include "core/region.h"
#include "vector/feature_attributes.h"
#include "vector/geometry_cells.h"
#include "vector/ogr_source.h"
#include "vector/vector_ingest.h"

namespace maquette {
namespace {

using json = nlohmann::json;

constexpr int kMinDefaultLevel = 6;
constexpr int kMaxDefaultLevel = 18;

// One layer of one source, with the transformation of its geometries to lon/lat.
struct SourceLayer {
  std::string source;
  OGRLayer* layer;
  std::unique_ptr<OGRCoordinateTransformation> to_lonlat;
  std::string where(GIntBig ogr_fid) const {
    return source + " layer '" + layer->GetName() + "' feature " + std::to_string(ogr_fid);
  }
};

struct Sources {
  std::vector<VectorDataset> datasets;
  std::vector<SourceLayer> layers;  // in source order, then layer order: the ingest's steps
};

Sources open_sources(const std::vector<std::string>& paths, const std::string& src_crs) {
  if (paths.empty()) throw Error("no vector source given");
  Sources s;
  for (const std::string& path : paths) {
    GDALDataset& ds = *s.datasets.emplace_back(open_vector(path));
    for (OGRLayer* layer : ds.GetLayers())
      s.layers.push_back({path, layer, lonlat_transform(*layer, path, src_crs)});
  }
  return s;
}

// Stops at the first coordinate that is not finite (NaN or infinite), recording it.
class NonFiniteFinder : public OGRDefaultConstGeometryVisitor {
 public:
  using OGRDefaultConstGeometryVisitor::visit;
  void visit(const OGRPoint* p) override {
    if (found_) return;
    const double c[] = {p->getX(), p->getY(), p->Is3D() ? p->getZ() : 0.0};
    if (!std::isfinite(c[0]) || !std::isfinite(c[1]) || !std::isfinite(c[2]))
      found_ = "(" + std::to_string(c[0]) + ", " + std::to_string(c[1]) +
               (p->Is3D() ? ", " + std::to_string(c[2]) : "") + ")";
  }
  const std::optional<std::string>& found() const { return found_; }

 private:
  std::optional<std::string> found_;
};

// Why a feature's geometry cannot be a stroke, or nothing when it can: none, empty, a coordinate
// that is not finite, or one GEOS rejects (OGRGeometry::IsValid: self-intersections, ...).
std::optional<std::string> geometry_fault(const OGRFeature& f) {
  const OGRGeometry* g = f.GetGeometryRef();
  if (!g) return "has no geometry";
  if (g->IsEmpty()) return "has an empty geometry";
  NonFiniteFinder finder;
  g->accept(&finder);
  if (finder.found()) return "has a coordinate that is not a number: " + *finder.found();
  // GEOS reports why a geometry is invalid as a GDAL error, quoted here.
  CPLErrorHandlerPusher quiet(CPLQuietErrorHandler);
  CPLErrorReset();
  if (g->IsValid()) return std::nullopt;
  const std::string why = CPLGetLastErrorMsg();
  return "has an invalid geometry" + (why.empty() ? std::string() : " (" + why + ")");
}

// Throws maquette::Error naming the source, layer and feature id of the first feature whose
// geometry is at fault (geometry_fault), before anything is written.
void check_geometries(const Sources& sources) {
  for (const SourceLayer& l : sources.layers) {
    l.layer->ResetReading();
    for (const auto& f : *l.layer)
      if (const auto fault = geometry_fault(*f)) throw Error(l.where(f->GetFID()) + " " + *fault);
  }
}

// A feature's size: the larger side of its lon/lat bounding box, in metres; nullopt for
// features without a usable geometry.
std::optional<double> feature_size_m(const OGRFeature& f, OGRCoordinateTransformation& ct) {
  const OGRGeometry* g = f.GetGeometryRef();
  if (!g || g->IsEmpty()) return std::nullopt;
  OGREnvelope env;
  g->getEnvelope(&env);
  double w, s, e, n;
  if (!ct.TransformBounds(env.MinX, env.MinY, env.MaxX, env.MaxY, &w, &s, &e, &n, 21))
    return std::nullopt;
  const double mid = (s + n) / 2;
  return std::max(approx_distance_m({w, mid}, {e, mid}), approx_distance_m({w, s}, {w, n}));
}

// The finest level in [6, 18] whose cells are at least as large as the median feature, so that
// a typical feature touches one to four cells (points: 18).
int default_level(const Grid& grid, const Sources& sources) {
  std::vector<double> sizes;
  for (const SourceLayer& l : sources.layers) {
    l.layer->ResetReading();
    for (const auto& f : *l.layer)
      if (auto size = feature_size_m(*f, *l.to_lonlat)) sizes.push_back(*size);
  }
  if (sizes.empty()) return kMaxDefaultLevel;
  const auto median = sizes.begin() + sizes.size() / 2;
  std::nth_element(sizes.begin(), median, sizes.end());
  for (int level = kMaxDefaultLevel; level > kMinDefaultLevel; --level)
    if (grid.level_info(level, 1).cell_side_m >= *median) return level;
  return kMinDefaultLevel;
}

// Whether any of `cells` meets the region (given as merged descendant ranges).
bool touches(std::span<const IdRange> region, std::span<const CellId> cells) {
  for (CellId c : cells) {
    auto it = std::lower_bound(region.begin(), region.end(), c.range_min(),
                               [](const IdRange& r, CellId v) { return r.max < v; });
    if (it != region.end() && it->min <= c.range_max()) return true;
  }
  return false;
}

// A feature ready to store, or why it is skipped.
struct Prepared {
  Feature feature;
  std::vector<CellId> cells;
  std::string invalid;  // non-empty: the reason it is skipped
};

Prepared prepare(const OGRFeature& f, const SourceLayer& l, const Grid& grid, int level) {
  Prepared p;
  // check_geometries has checked the geometry.
  std::unique_ptr<OGRGeometry> g(f.GetGeometryRef()->clone());
  if (g->transform(l.to_lonlat.get()) != OGRERR_NONE) {
    p.invalid = "cannot be transformed to WGS84";
    return p;
  }
  try {
    p.cells = geometry_cells(grid, *g, level);
  } catch (const Error& e) {
    p.invalid = e.what();
    return p;
  }
  OGREnvelope env;
  g->getEnvelope(&env);
  p.feature.bbox = {env.MinX, env.MinY, env.MaxX, env.MaxY};
  p.feature.wkb.resize(g->WkbSize());
  g->exportToWkb(wkbNDR, reinterpret_cast<unsigned char*>(p.feature.wkb.data()), wkbVariantIso);
  p.feature.attributes = feature_attributes(f);
  return p;
}

// What identifies an ingest: a run with the same key may be resumed, and a layer written by
// another key is not overwritten. Sources by absolute path, as the raster ingest names them: the
// same pipeline run from another directory is the same ingest.
json ingest_key(const std::vector<std::string>& paths, const FeatureIngestOptions& o, int level) {
  json sources = json::array();
  for (const std::string& p : paths) sources.push_back(std::filesystem::absolute(p).string());
  json region = json::array();
  for (CellId c : normalize(o.region)) region.push_back(c.ToText());
  return {
      {"ingest", "features"}, {"layer", o.layer},     {"sources", sources},        {"level", level},
      {"region", region},     {"src_crs", o.src_crs}, {"batch_size", o.batch_size}};
}

void create_features_layer(Store& store, const std::string& name, int level, const json& prov) {
  if (auto old = store.layer(name); old && old->kind == LayerKind::Features &&
                                    old->provenance.value("ingest", json()) != prov["ingest"] &&
                                    store.feature_count(name) > 0)
    throw Error("layer '" + name + "' in " + store.path() +
                " already holds features of another ingest (" +
                old->provenance.value("ingest", json()).dump() + "): use another layer name");
  LayerInfo info;
  info.name = name;
  info.kind = LayerKind::Features;
  info.dtype = DType::U8;
  info.tile_size = 1;
  info.level = level;
  info.codec = "raw";
  info.provenance = prov;
  store.create_layer(info);
}

// Writes the features of every source layer, one batch of `batch_size` features (by position
// in the layer) per transaction with its run record; batches done by `done` are skipped.
class Writer {
 public:
  Writer(Store& store, const FeatureIngestOptions& o, int64_t run, int level,
         const FeatureIngestProgress& progress)
      : store_(store),
        options_(o),
        run_(run),
        level_(level),
        region_(to_ranges(normalize(o.region))),
        progress_(progress) {
    report_.level = level;
  }

  // Returns the first fid and the number of features of the layer (fids are 1-based positions
  // over all layers read so far, so they do not depend on what is skipped).
  std::pair<int64_t, int64_t> write_layer(int step, const SourceLayer& l) {
    const std::vector<int64_t> keys = store_.done_keys(run_, step);
    const std::set<int64_t> done(keys.begin(), keys.end());
    report_.batches_resumed += int64_t(done.size());
    const int64_t first_fid = next_fid_;
    std::unique_ptr<Store::Batch> batch;
    int64_t key = 0;
    l.layer->ResetReading();
    for (;;) {
      CPLErrorReset();
      OGRFeatureUniquePtr f(l.layer->GetNextFeature());
      if (!f) {
        if (CPLGetLastErrorType() == CE_Failure)
          throw Error(l.source + " layer '" + l.layer->GetName() +
                      "': read error: " + CPLGetLastErrorMsg());
        break;
      }
      const int64_t fid = next_fid_++;
      if (batch && (fid - first_fid) / options_.batch_size != key) commit(batch, step, key);
      key = (fid - first_fid) / options_.batch_size;
      if (done.contains(key)) continue;
      if (!batch) batch = std::make_unique<Store::Batch>(store_);
      add(*batch, *f, fid, l);
    }
    if (batch) commit(batch, step, key);
    return {first_fid, next_fid_ - first_fid};
  }

  const FeatureIngestReport& report() const { return report_; }

 private:
  void add(Store::Batch& batch, const OGRFeature& f, int64_t fid, const SourceLayer& l) {
    Prepared p = prepare(f, l, default_grid(), level_);
    if (!p.invalid.empty()) {
      spdlog::warn("{}: {}; skipped", l.where(f.GetFID()), p.invalid);
      ++report_.invalid_skipped;
    } else if (!region_.empty() && !touches(region_, p.cells)) {
      ++report_.outside_skipped;
    } else {
      p.feature.fid = fid;
      batch.put_feature(options_.layer, p.feature, p.cells);
      ++report_.features;
      report_.cell_entries += int64_t(p.cells.size());
    }
  }

  void commit(std::unique_ptr<Store::Batch>& batch, int step, int64_t key) {
    batch->mark_done(run_, step, key);
    batch->commit();
    batch.reset();
    if (progress_) progress_(report_);
  }

  Store& store_;
  const FeatureIngestOptions& options_;
  const int64_t run_;
  const int level_;
  const std::vector<IdRange> region_;
  const FeatureIngestProgress& progress_;
  FeatureIngestReport report_;
  int64_t next_fid_ = 1;
};

}  // namespace

FeatureIngestReport ingest_features(Store& store, const std::vector<std::string>& sources,
                                    const FeatureIngestOptions& options,
                                    const FeatureIngestProgress& progress) {
  if (options.batch_size < 1) throw Error("the batch size must be at least 1");
  const Sources src = open_sources(sources, options.src_crs);
  check_geometries(src);
  const int level = options.level ? *options.level : default_level(default_grid(), src);
  const json key = ingest_key(sources, options, level);
  json provenance = {{"ingest", key}};
  const bool new_layer = !store.layer(options.layer);
  create_features_layer(store, options.layer, level, provenance);

  std::optional<int64_t> run;
  if (options.resume) run = store.latest_unfinished_run(key);
  if (!run) run = store.begin_run(key);
  // Readers refuse the layer until finish_run(run, "ok") (a killed ingest leaves it marked).
  store.mark_incomplete(options.layer, *run);
  Writer writer(store, options, *run, level, progress);
  try {
    json layers = json::array();
    for (size_t step = 0; step < src.layers.size(); ++step) {
      const SourceLayer& l = src.layers[step];
      const auto [first_fid, count] = writer.write_layer(int(step), l);
      layers.push_back({{"source", l.source},
                        {"layer", l.layer->GetName()},
                        {"first_fid", first_fid},
                        {"features", count},
                        {"fields", field_definitions(*l.layer->GetLayerDefn())}});
    }
    if (store.feature_count(options.layer) == 0) {  // an empty layer, which a user never wants
      const FeatureIngestReport& r = writer.report();
      throw Error("no feature stored in layer '" + options.layer + "': " +
                  (r.invalid_skipped + r.outside_skipped == 0
                       ? std::string("the sources hold none")
                       : std::to_string(r.outside_skipped) + " outside the region, " +
                             std::to_string(r.invalid_skipped) + " not placeable on the grid"));
    }
    provenance["layers"] = layers;
    create_features_layer(store, options.layer, level, provenance);
  } catch (const std::exception& e) {
    store.finish_run(*run, std::string("failed: ") + e.what());
    // A layer this ingest created is removed again; an older one stays marked for --resume.
    if (new_layer) store.drop_layer(options.layer, *run);
    throw;
  }
  store.finish_run(*run, "ok");
  return writer.report();
}

}  // namespace maquette
