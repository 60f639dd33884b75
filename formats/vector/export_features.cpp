#include "vector/export_features.h"

#include <cpl_error.h>
#include <cpl_vsi.h>
#include <gdal_priv.h>
#include <ogrsf_frmts.h>

#include <atomic>
#include <map>
#include <set>
#include <span>

#include "core/error.h"
#include "core/output_file.h"
#include "gdal/gdal_drivers.h"
#include "gdal/gdal_env.h"
#include "vector/feature_attributes.h"

namespace maquette {
namespace {

using GeometryPtr = std::unique_ptr<OGRGeometry>;

GeometryPtr geometry_of(const Feature& f, const std::string& layer) {
  OGRGeometry* g = nullptr;
  if (OGRGeometryFactory::createFromWkb(f.wkb.data(), nullptr, &g, f.wkb.size()) != OGRERR_NONE)
    throw Error("layer '" + layer + "' feature " + std::to_string(f.fid) +
                ": stored geometry is not valid WKB");
  return GeometryPtr(g);
}

// Whether `g` meets the lon/lat box w s e n.
bool meets(const OGRGeometry& g, double w, double s, double e, double n) {
  OGRLinearRing ring;
  for (const auto& [x, y] : {std::pair{w, s}, {e, s}, {e, n}, {w, n}, {w, s}}) ring.addPoint(x, y);
  OGRPolygon box;
  box.addRing(&ring);
  return g.Intersects(&box);
}

// Whether `g` meets the lon/lat box W S E N (W > E: across the antimeridian).
bool meets_box(const OGRGeometry& g, const std::array<double, 4>& b) {
  if (b[0] <= b[2]) return meets(g, b[0], b[1], b[2], b[3]);
  return meets(g, b[0], b[1], 180, b[3]) || meets(g, -180, b[1], b[2], b[3]);
}

// The layer's geometry type: the features' common type, else any type.
OGRwkbGeometryType common_type(const std::vector<GeometryPtr>& geometries) {
  std::set<OGRwkbGeometryType> types;
  for (const GeometryPtr& g : geometries) types.insert(g->getGeometryType());
  return types.size() == 1 ? *types.begin() : wkbUnknown;
}

// The fields recorded at ingest (source layers in order, a name's first definition kept), then
// any attribute without a record, typed from its first non-null value.
std::vector<std::unique_ptr<OGRFieldDefn>> fields_of(const LayerInfo& layer,
                                                     const std::vector<Feature>& features) {
  std::vector<std::unique_ptr<OGRFieldDefn>> fields;
  std::set<std::string> names;
  for (const nlohmann::json& l : layer.provenance.value("layers", nlohmann::json::array()))
    for (const nlohmann::json& d : l.value("fields", nlohmann::json::array()))
      if (names.insert(d.at("name").get<std::string>()).second)
        fields.push_back(field_definition(d));
  for (const Feature& f : features)
    for (auto it = f.attributes.begin(); it != f.attributes.end(); ++it)
      if (!it.value().is_null() && names.insert(it.key()).second)
        fields.push_back(inferred_field(it.key(), it.value()));
  return fields;
}

[[noreturn]] void write_error(const std::string& out, const std::string& what) {
  const std::string why = CPLGetLastErrorMsg();
  throw Error("cannot write " + out + ": " + what + (why.empty() ? "" : ": " + why));
}

struct DatasetCloser {
  void operator()(GDALDataset* d) const { GDALClose(d); }
};

// A /vsimem/ file, unlinked when it goes.
class MemoryFile {
 public:
  MemoryFile() {
    static std::atomic<uint64_t> serial = 0;
    path_ = "/vsimem/maquette_features_" + std::to_string(serial++) + ".geojson";
  }
  ~MemoryFile() { VSIUnlink(path_.c_str()); }
  MemoryFile(const MemoryFile&) = delete;
  MemoryFile& operator=(const MemoryFile&) = delete;
  const std::string& path() const { return path_; }
  std::span<const char> bytes() const {
    vsi_l_offset size = 0;
    const GByte* data = VSIGetMemFileBuffer(path_.c_str(), &size, FALSE);
    return {reinterpret_cast<const char*>(data), size_t(size)};
  }

 private:
  std::string path_;
};

}  // namespace

std::vector<Feature> features_in_region(const Store& store, const Grid& grid,
                                        const LayerInfo& layer, const RegionSpec& region) {
  std::map<int64_t, Feature> by_fid;
  for (CellId c : region_cells(grid, layer.level, region))
    for (Feature& f : store.features_in(layer.name, c.range_min(), c.range_max()))
      if (!by_fid.contains(f.fid) &&
          (!region.bbox || meets_box(*geometry_of(f, layer.name), *region.bbox)))
        by_fid.emplace(f.fid, std::move(f));
  if (by_fid.empty())
    throw Error("layer '" + layer.name + "' in " + store.path() + " has no features in the region");
  std::vector<Feature> out;
  out.reserve(by_fid.size());
  for (auto& [fid, f] : by_fid) out.push_back(std::move(f));
  return out;
}

void write_features(const LayerInfo& layer, const std::vector<Feature>& features,
                    FeatureFormat format, const std::string& out) {
  init_gdal();  // GDAL's errors become ours, not lines on stderr
  register_all_gdal_drivers();
  const bool geojson = format == FeatureFormat::GeoJson;
  GDALDriver* driver = GetGDALDriverManager()->GetDriverByName(geojson ? "GeoJSON" : "GPKG");
  if (!driver)
    throw Error("cannot write " + out + ": GDAL has no " + (geojson ? "GeoJSON" : "GPKG") +
                " driver");
  std::vector<GeometryPtr> geometries;
  for (const Feature& f : features) geometries.push_back(geometry_of(f, layer.name));

  OutputFile file(out);
  // GeoJSON is written in memory first, then to the file with every write checked: its driver
  // does not report failed writes (on a full disk: a truncated file, and success).
  const MemoryFile memory;
  const std::string& target = geojson ? memory.path() : file.temp_path();
  file.write([&] {
    CPLErrorReset();
    std::unique_ptr<GDALDataset, DatasetCloser> ds;
    {
      // The GeoPackage driver warns about the temporary name's extension.
      CPLErrorHandlerPusher quiet(CPLQuietErrorHandler);
      ds.reset(driver->Create(target.c_str(), 0, 0, 0, GDT_Unknown, nullptr));
    }
    if (!ds) write_error(out, "cannot create it");
    OGRSpatialReference wgs84;
    wgs84.importFromEPSG(4326);
    wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    // GeoJSON: every digit of the stored doubles, so that a read gives back the same coordinates.
    const char* geojson_options[] = {"SIGNIFICANT_FIGURES=17", nullptr};
    OGRLayer* ol = ds->CreateLayer(layer.name.c_str(), &wgs84, common_type(geometries),
                                   const_cast<char**>(geojson ? geojson_options : nullptr));
    if (!ol) write_error(out, "cannot create layer '" + layer.name + "'");
    for (const auto& field : fields_of(layer, features))
      if (ol->CreateField(field.get()) != OGRERR_NONE)
        write_error(out, std::string("cannot create field '") + field->GetNameRef() + "'");
    if (!geojson && ds->StartTransaction() != OGRERR_NONE) write_error(out, "cannot start writing");
    for (size_t i = 0; i < features.size(); ++i) {
      OGRFeature f(ol->GetLayerDefn());
      f.SetFID(features[i].fid);
      f.SetGeometryDirectly(geometries[i].release());
      set_feature_attributes(f, features[i].attributes);
      if (ol->CreateFeature(&f) != OGRERR_NONE)
        write_error(out, "feature " + std::to_string(features[i].fid));
    }
    if (!geojson && ds->CommitTransaction() != OGRERR_NONE) write_error(out, "cannot commit");
    CPLErrorReset();
    ds.reset();  // closes, flushing the file
    if (CPLGetLastErrorType() >= CE_Failure) write_error(out, "cannot close it");
    if (geojson) write_new_file(file.temp_path(), memory.bytes());
  });
  file.commit();
}

}  // namespace maquette
