#include "gdal/raster_source.h"

#include <gdal_priv.h>
#include <ogr_spatialref.h>
#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <string>

#include "core/error.h"
#include "core/file_access.h"
#include "gdal/class_table.h"
#include "gdal/gdal_drivers.h"
#include "gdal/gdal_env.h"

namespace maquette {
namespace {

DType dtype_from_gdal(GDALDataType t, const std::string& where) {
  switch (t) {
    case GDT_Byte:
      return DType::U8;
    case GDT_UInt16:
      return DType::U16;
    case GDT_Int16:
      return DType::I16;
    case GDT_UInt32:
      return DType::U32;
    case GDT_Int32:
      return DType::I32;
    case GDT_Float32:
      return DType::F32;
    case GDT_Float64:
      return DType::F64;
    default:
      throw Error(where + ": data type " + GDALGetDataTypeName(t) +
                  " is not supported (byte, (u)int16, (u)int32, float32, float64)");
  }
}

// Opens with the GTiff driver alone first, and with every driver only when that fails (another
// format, or a bad file: the message is then the one every driver gives).
GDALDataset* open_dataset(const std::string& path) {
  init_gdal();
  register_gtiff_driver();
  const auto open = [&path] {
    CPLErrorReset();
    return GDALDataset::FromHandle(
        GDALOpenEx(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY, nullptr, nullptr, nullptr));
  };
  GDALDataset* ds = open();
  if (!ds) {
    register_all_gdal_drivers();
    ds = open();
  }
  if (!ds) {
    if (const auto problem = file_access_problem(path))
      throw Error(path + ": cannot read the raster: " + *problem);
    throw Error(path + ": cannot read the raster: not a raster GDAL can read: " +
                gdal_last_error("unknown format"));
  }
  return ds;
}

std::shared_ptr<const OGRSpatialReference> crs_of(GDALDataset& ds, const std::string& path,
                                                  const std::string& src_crs) {
  auto srs = std::make_shared<OGRSpatialReference>();
  const OGRSpatialReference* own = ds.GetSpatialRef();
  const bool has_own = own && !own->IsEmpty();
  if (!src_crs.empty()) {
    if (srs->SetFromUserInput(src_crs.c_str()) != OGRERR_NONE)
      throw Error("--src-crs: '" + src_crs + "' is not a CRS GDAL understands");
    // For sources without one: one of its own another CRS silently misplaced the raster.
    const char* same[] = {"IGNORE_DATA_AXIS_TO_SRS_AXIS_MAPPING=YES",
                          "CRITERION=EQUIVALENT_EXCEPT_AXIS_ORDER_GEOGCRS", nullptr};
    if (has_own && !srs->IsSame(own, same))
      throw Error(path + ": the raster has its own CRS (" +
                  std::string(own->GetName() ? own->GetName() : "unnamed") + "), not --src-crs " +
                  src_crs + ": --src-crs is for sources without one (to correct a wrong CRS: " +
                  "gdal_edit.py -a_srs)");
  } else if (has_own) {
    *srs = *own;
  } else {
    throw Error(path + ": the raster has no CRS; give one with --src-crs (e.g. EPSG:4326)");
  }
  return srs;
}

std::string wkt2(const OGRSpatialReference& srs) {
  char* wkt = nullptr;
  const char* options[] = {"FORMAT=WKT2_2019", nullptr};
  srs.exportToWkt(&wkt, options);
  std::string out = wkt ? wkt : "";
  CPLFree(wkt);
  return out;
}

}  // namespace

RasterSource describe_source(const std::string& path, const std::vector<int>& bands,
                             const std::string& src_crs) {
  GDALDataset* ds = open_dataset(path);
  struct Closer {
    GDALDataset* ds;
    ~Closer() { GDALClose(ds); }
  } closer{ds};

  RasterSource s;
  s.path = path;
  s.width = ds->GetRasterXSize();
  s.height = ds->GetRasterYSize();
  if (s.width <= 0 || s.height <= 0 || ds->GetRasterCount() == 0)
    throw Error(path + ": the file holds no raster bands");
  if (ds->GetGeoTransform(s.geotransform.data()) != CE_None)
    throw Error(path + ": the raster has no georeferencing (geotransform)");
  if (!GDALInvGeoTransform(s.geotransform.data(), s.inverse.data()))
    throw Error(path + ": the geotransform is not invertible");
  s.crs = crs_of(*ds, path, src_crs);
  s.crs_wkt = wkt2(*s.crs);
  s.geographic = s.crs->IsGeographic();
  const auto& gt = s.geotransform;
  s.wraps = s.geographic && gt[2] == 0 && gt[4] == 0 &&
            std::abs(std::abs(gt[1]) * s.width - 360.0) < 1e-6 * std::abs(gt[1]);

  s.bands = bands;
  if (s.bands.empty())
    for (int b = 1; b <= ds->GetRasterCount(); ++b) s.bands.push_back(b);
  for (int b : s.bands) {
    if (b < 1 || b > ds->GetRasterCount())
      throw Error("--bands: " + path + " has no band " + std::to_string(b) + " (it has " +
                  std::to_string(ds->GetRasterCount()) + ")");
    GDALRasterBand* band = ds->GetRasterBand(b);
    const DType t = dtype_from_gdal(band->GetRasterDataType(), path);
    if (s.nodata.empty()) {
      s.dtype = t;
      s.unit_type = band->GetUnitType();
    }
    int has = 0;
    const double nd = band->GetNoDataValue(&has);
    s.nodata.push_back(has ? std::optional<double>(nd) : std::nullopt);
    s.scale.push_back(band->GetScale());
    s.offset.push_back(band->GetOffset());
    s.scaled = s.scaled || s.scale.back() != 1.0 || s.offset.back() != 0.0;
  }
  s.classes = band_class_table(*ds->GetRasterBand(s.bands.front()));
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0) {
    s.file_size = int64_t(st.st_size);
    s.mtime = int64_t(st.st_mtim.tv_sec) * 1000000000 + st.st_mtim.tv_nsec;
  }
  return s;
}

struct SourceReader::Handle {
  GDALDataset* dataset;
  std::mutex mutex;  // held while the dataset reads
  explicit Handle(GDALDataset* ds) : dataset(ds) {}
  ~Handle() { GDALClose(dataset); }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
};

std::shared_ptr<SourceReader::Handle> SourceReader::shared_handle(const std::string& path) {
  static std::mutex mutex;
  static std::map<std::string, std::weak_ptr<Handle>> open;
  const std::lock_guard lock(mutex);
  std::weak_ptr<Handle>& slot = open[path];
  if (auto handle = slot.lock()) return handle;
  auto handle = std::make_shared<Handle>(open_dataset(path));
  slot = handle;
  return handle;
}

SourceReader::SourceReader(const RasterSource& source)
    : source_(source), handle_(shared_handle(source.path)) {}

SourceReader::~SourceReader() = default;

void SourceReader::read_span(int band, int64_t x0, int64_t y0, int w, int h, int step,
                             bool categorical, float* out, int out_stride) {
  GDALRasterIOExtraArg extra;
  INIT_RASTERIO_EXTRA_ARG(extra);
  extra.eResampleAlg = step == 1     ? GRIORA_NearestNeighbour
                       : categorical ? GRIORA_Mode
                                     : GRIORA_Average;
  const std::lock_guard lock(handle_->mutex);
  GDALRasterBand* b = handle_->dataset->GetRasterBand(source_.bands[size_t(band)]);
  CPLErrorReset();
  if (b->RasterIO(GF_Read, int(x0), int(y0), w * step, h * step, out, w, h, GDT_Float32,
                  sizeof(float), GSpacing(out_stride) * GSpacing(sizeof(float)), &extra) != CE_None)
    throw Error(source_.path + ": read error: " + gdal_last_error("RasterIO failed"));
}

void SourceReader::read(int64_t x0, int64_t y0, int w, int h, int step, bool categorical,
                        Window& out) {
  out.x0 = x0;
  out.y0 = y0;
  out.w = w;
  out.h = h;
  out.step = step;
  out.planes.resize(source_.bands.size());
  const int64_t W = source_.width, H = source_.height;
  // Window rows and columns whose `step` source pixels all lie in the raster (or in one turn of
  // a wrapping raster); the rest stay NaN.
  const int j0 = int(std::clamp<int64_t>((-y0 + step - 1) / step, 0, h));
  const int j1 = int(std::clamp<int64_t>((H - y0) >= 0 ? (H - y0) / step : 0, j0, h));
  for (size_t band = 0; band < out.planes.size(); ++band) {
    auto& plane = out.planes[band];
    plane.assign(size_t(w) * size_t(h), std::numeric_limits<float>::quiet_NaN());
    if (j1 <= j0) continue;
    int i = 0;
    while (i < w) {
      int64_t sx = x0 + int64_t(i) * step;  // first source column of window column i
      int64_t turn = 0;
      if (source_.wraps) {
        turn = sx >= 0 ? sx / W : -((-sx + W - 1) / W);
        sx -= turn * W;
      } else if (sx < 0) {
        i = int(std::min<int64_t>(w, (-x0 + step - 1) / step));
        continue;
      }
      if (sx + step > W) {  // straddles the raster's edge (or the wrap): stays NaN
        if (!source_.wraps) break;
        ++i;
        continue;
      }
      const int n = int(std::min<int64_t>(w - i, (W - sx) / step));
      read_span(int(band), sx, y0 + int64_t(j0) * step, n, j1 - j0, step, categorical,
                plane.data() + size_t(j0) * size_t(w) + size_t(i), w);
      i += n;
    }
    // Nodata to NaN, then scale and offset, on the rows read (the others are NaN); one loop per
    // case, so that each is a vector loop.
    const auto& nd = source_.nodata[band];
    const float nodata = nd ? float(*nd) : 0.0f;
    const float scale = float(source_.scale[band]), offset = float(source_.offset[band]);
    constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
    float* const begin = plane.data() + size_t(j0) * size_t(w);
    const size_t n = size_t(j1 - j0) * size_t(w);
    if (nd && source_.scaled)
      for (size_t k = 0; k < n; ++k)
        begin[k] = begin[k] == nodata ? kNaN : begin[k] * scale + offset;
    else if (nd)
      for (size_t k = 0; k < n; ++k) begin[k] = begin[k] == nodata ? kNaN : begin[k];
    else if (source_.scaled)
      for (size_t k = 0; k < n; ++k) begin[k] = begin[k] * scale + offset;
    // +-Inf (in a float source, or out of float's range after scaling) is missing like NaN.
    if (source_.dtype == DType::F32 || source_.dtype == DType::F64 || source_.scaled)
      for (size_t k = 0; k < n; ++k) begin[k] = std::isfinite(begin[k]) ? begin[k] : kNaN;
  }
}

bool SourceReader::any_valid() {
  constexpr int kChunk = 1024;  // columns per read: bounded memory whatever the width
  std::vector<float> buf;
  for (size_t band = 0; band < source_.bands.size(); ++band) {
    int bw = 0, bh = 0;
    handle_->dataset->GetRasterBand(source_.bands[band])->GetBlockSize(&bw, &bh);
    const int rows = std::clamp(bh, 1, 1024);
    for (int y = 0; y < source_.height; y += rows) {
      const int h = std::min(rows, source_.height - y);
      for (int x = 0; x < source_.width; x += kChunk) {
        const int w = std::min(kChunk, source_.width - x);
        buf.resize(size_t(w) * size_t(h));
        read_span(int(band), x, y, w, h, 1, false, buf.data(), w);
        const auto& nd = source_.nodata[band];
        for (float v : buf)
          if (std::isfinite(v) && !(nd && v == float(*nd))) return true;
      }
    }
  }
  return false;
}

}  // namespace maquette
