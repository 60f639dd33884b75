#include "gdal/vertical_datum.h"

#include <proj.h>
#include <proj_experimental.h>
#include <spdlog/spdlog.h>
#include <tbb/enumerable_thread_specific.h>

#include <cmath>
#include <mutex>
#include <vector>

#include "core/error.h"

namespace maquette {
namespace {

struct ContextDeleter {
  void operator()(PJ_CONTEXT* c) const { proj_context_destroy(c); }
};
struct PjDeleter {
  void operator()(PJ* p) const { proj_destroy(p); }
};
using Context = std::unique_ptr<PJ_CONTEXT, ContextDeleter>;
using Pj = std::unique_ptr<PJ, PjDeleter>;

// A PROJ context that keeps its errors to itself (they become maquette::Error messages).
Context quiet_context() {
  Context ctx(proj_context_create());
  proj_log_level(ctx.get(), PJ_LOG_NONE);
  return ctx;
}

std::string auth_code(PJ* obj) {
  const char* auth = proj_get_id_auth_name(obj, 0);
  const char* code = proj_get_id_code(obj, 0);
  return auth && code ? std::string(auth) + ":" + code : "";
}

// The vertical CRS of `crs` (itself, or a compound CRS's vertical part); null when it has none.
Pj vertical_part(PJ_CONTEXT* ctx, PJ* crs) {
  if (proj_get_type(crs) == PJ_TYPE_VERTICAL_CRS) return Pj(proj_clone(ctx, crs));
  if (proj_get_type(crs) == PJ_TYPE_COMPOUND_CRS)
    for (int i = 0;; ++i) {
      Pj sub(proj_crs_get_sub_crs(ctx, crs, i));
      if (!sub) break;
      if (proj_get_type(sub.get()) == PJ_TYPE_VERTICAL_CRS) return sub;
    }
  return nullptr;
}

VerticalDatum datum_of(PJ_CONTEXT* ctx, PJ* vertical, const std::string& from) {
  std::string crs = auth_code(vertical);
  if (crs.empty()) crs = proj_as_wkt(ctx, vertical, PJ_WKT2_2019, nullptr);
  return {crs, proj_get_name(vertical), from};
}

VerticalDatum ellipsoid(const std::string& from) {
  return {VerticalDatum::kEllipsoid, "WGS 84 ellipsoid", from};
}

}  // namespace

nlohmann::json VerticalDatum::to_json() const {
  return {{"crs", crs}, {"name", name}, {"from", from}};
}

std::string VerticalDatum::describe() const {
  return name + (ellipsoidal() ? "" : " (" + (crs.size() > 40 ? "WKT" : crs) + ")") + ", " + from;
}

VerticalDatum parse_vertical_datum(const std::string& text, const std::string& option) {
  const std::string from = option + " " + text;
  if (text == "ellipsoid") return ellipsoid(from);
  const std::string input = text == "egm96" ? "EPSG:5773" : text == "egm2008" ? "EPSG:3855" : text;
  const Context ctx = quiet_context();
  const Pj crs(proj_create(ctx.get(), input.c_str()));
  if (!crs)
    throw Error(option + " '" + text +
                "': not egm96, egm2008, ellipsoid or a vertical CRS PROJ knows (" +
                proj_context_errno_string(ctx.get(), proj_context_errno(ctx.get())) + ")");
  if (proj_get_type(crs.get()) == PJ_TYPE_GEOGRAPHIC_3D_CRS) return ellipsoid(from);
  const Pj vertical = vertical_part(ctx.get(), crs.get());
  if (!vertical)
    throw Error(option + " '" + text + "': PROJ reads it as " + proj_get_name(crs.get()) +
                ", not a vertical CRS (give egm96, egm2008, ellipsoid or e.g. EPSG:5703)");
  return datum_of(ctx.get(), vertical.get(), from);
}

std::optional<VerticalDatum> source_vertical_datum(const std::string& crs_wkt,
                                                   const std::string& source) {
  if (crs_wkt.empty()) return std::nullopt;
  const Context ctx = quiet_context();
  const Pj crs(proj_create(ctx.get(), crs_wkt.c_str()));
  if (!crs) return std::nullopt;
  const std::string from = "the CRS of " + source;
  if (proj_get_type(crs.get()) == PJ_TYPE_GEOGRAPHIC_3D_CRS) return ellipsoid(from);
  const Pj vertical = vertical_part(ctx.get(), crs.get());
  if (!vertical) return std::nullopt;
  return datum_of(ctx.get(), vertical.get(), from);
}

VerticalDatum default_dem_vertical_datum() {
  return {"EPSG:5773", "EGM96 height",
          "default for --as dem (SRTM and most global DEMs are on EGM96)"};
}

std::optional<VerticalDatum> layer_vertical_datum(const LayerInfo& layer) {
  const auto it = layer.provenance.find("vertical_datum");
  if (it == layer.provenance.end() || !it->is_object()) return std::nullopt;
  return VerticalDatum{it->value("crs", ""), it->value("name", ""), it->value("from", "")};
}

// The chosen operation, and a clone of it per thread (PROJ objects are not thread-safe).
struct EllipsoidalHeights::Transform {
  struct PerThread {
    Context ctx;
    Pj op;
  };
  Context ctx;
  Pj op;
  VerticalDatum datum;
  tbb::enumerable_thread_specific<PerThread> threads;
  std::mutex cloning;  // `op` is read by one clone at a time

  PJ* local() {
    PerThread& t = threads.local();
    if (!t.op) {
      t.ctx = quiet_context();
      const std::lock_guard lock(cloning);
      t.op.reset(proj_clone(t.ctx.get(), op.get()));
    }
    return t.op.get();
  }
};

EllipsoidalHeights::EllipsoidalHeights() = default;
EllipsoidalHeights::~EllipsoidalHeights() = default;
EllipsoidalHeights::EllipsoidalHeights(EllipsoidalHeights&&) noexcept = default;

EllipsoidalHeights::EllipsoidalHeights(const VerticalDatum& datum) {
  if (datum.ellipsoidal()) return;
  auto t = std::make_unique<Transform>();
  t->datum = datum;
  PJ_CONTEXT* ctx = (t->ctx = quiet_context()).get();
  const std::string where = "vertical datum " + datum.describe();
  const Pj horizontal(proj_create(ctx, "EPSG:4326"));
  const Pj given(proj_create(ctx, datum.crs.c_str()));
  const Pj vertical = given ? vertical_part(ctx, given.get()) : nullptr;
  if (!vertical) throw Error(where + ": PROJ does not know it as a vertical CRS");
  const Pj source(
      proj_create_compound_crs(ctx, "WGS 84 + vertical", horizontal.get(), vertical.get()));
  const Pj target(proj_create(ctx, "EPSG:4979"));
  // Every candidate, whether its grids are here or not, to name the missing ones.
  PJ_OPERATION_FACTORY_CONTEXT* factory = proj_create_operation_factory_context(ctx, nullptr);
  proj_operation_factory_context_set_grid_availability_use(ctx, factory,
                                                           PROJ_GRID_AVAILABILITY_IGNORED);
  proj_operation_factory_context_set_spatial_criterion(ctx, factory,
                                                       PROJ_SPATIAL_CRITERION_PARTIAL_INTERSECTION);
  PJ_OBJ_LIST* ops = proj_create_operations(ctx, source.get(), target.get(), factory);
  proj_operation_factory_context_destroy(factory);
  std::vector<std::string> missing;
  for (int i = 0; ops && i < proj_list_get_count(ops) && !t->op; ++i) {
    Pj op(proj_list_get(ctx, ops, i));
    // A "ballpark" operation leaves heights as they are: never what a geoid conversion means.
    if (proj_coordoperation_has_ballpark_transformation(ctx, op.get())) continue;
    bool available = true;
    for (int g = 0; g < proj_coordoperation_get_grid_used_count(ctx, op.get()); ++g) {
      const char* name = nullptr;
      int here = 0;
      proj_coordoperation_get_grid_used(ctx, op.get(), g, &name, nullptr, nullptr, nullptr, nullptr,
                                        nullptr, &here);
      if (!here) {
        available = false;
        missing.push_back(name ? name : "?");
      }
    }
    if (available && proj_coordoperation_is_instantiable(ctx, op.get()))
      t->op.reset(proj_normalize_for_visualization(ctx, op.get()));  // lon, lat order
  }
  proj_list_destroy(ops);
  if (!t->op) {
    std::string names;
    for (const std::string& m : missing) names += (names.empty() ? "" : ", ") + m;
    const PJ_INFO info = proj_info();
    throw Error(where + ": no geoid grid to convert heights to the ellipsoid: " +
                (missing.empty() ? std::string("PROJ knows no transformation to WGS 84")
                                 : "PROJ looked for " + names + " in " + info.searchpath +
                                       " (Debian: proj-data ships egm96_15.gtx)"));
  }
  transform_ = std::move(t);
}

EllipsoidalHeights ellipsoidal_heights(const LayerInfo& layer) {
  const auto datum = layer_vertical_datum(layer);
  if (!datum) {
    spdlog::info(
        "layer '{}' records no vertical datum: its heights are taken as above the "
        "ellipsoid",
        layer.name);
    return {};
  }
  spdlog::info("layer '{}': heights above {}, converted to the ellipsoid", layer.name,
               datum->describe());
  return EllipsoidalHeights(*datum);
}

double EllipsoidalHeights::operator()(LonLat p, double height) const {
  if (!transform_) return height;
  PJ_COORD c = proj_coord(p.lon, p.lat, height, 0);
  c = proj_trans(transform_->local(), PJ_FWD, c);
  if (!std::isfinite(c.xyz.z))
    throw Error("vertical datum " + transform_->datum.describe() + ": no geoid height at lon " +
                std::to_string(p.lon) + ", lat " + std::to_string(p.lat));
  return c.xyz.z;
}

}  // namespace maquette
