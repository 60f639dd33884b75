#include "painting.h"

#include <cpl_vsi.h>
#include <gdal_alg.h>
#include <gdal_priv.h>
#include <ogrsf_frmts.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>

#include "../texture/hs_histogram.h"
#include "../texture/kmeans.h"
#include "../texture/majority_filter.h"
#include "core/error.h"
#include "gdal/gdal_env.h"

namespace maquette::synthesis {

// A missing file said as such: a relative path is the working directory's, not the pipeline's
// (whose ingest sources are the pipeline file's).
void require_file(const std::string& path, const std::string& what) {
  if (path.empty()) throw Error(what + ": an empty path");
  VSIStatBufL stat;
  if (VSIStatL(path.c_str(), &stat) == 0) return;
  std::error_code error;
  const auto cwd = std::filesystem::current_path(error).string();
  throw Error(path + ": " + what + ": no such file" +
              (path.starts_with("/") ? "" : " (relative to the working directory " + cwd + ")"));
}

namespace {

// `kinds`: GDAL_OF_RASTER, GDAL_OF_VECTOR or both.
// Under a GdalSession (GDAL's reason in the error, not printed by GDAL besides).
std::unique_ptr<GDALDataset> open_image(const std::string& path, const std::string& what,
                                        unsigned kinds = GDAL_OF_RASTER) {
  std::unique_ptr<GDALDataset> ds(
      GDALDataset::Open(path.c_str(), kinds | GDAL_OF_READONLY | GDAL_OF_VERBOSE_ERROR));
  if (ds) return ds;
  require_file(path, "GDAL cannot open the " + what);
  gdal_error(path + ": GDAL cannot open the " + what);
}

// The one band of `ds` as bytes: it must be one 8-bit band of the painting's size. Read as bytes,
// another type would be clamped (a float 0..1 altitude all 0 or 1, 16-bit classes all 255), and
// of an RGB image band 1, its red, would be read alone.
std::vector<uint8_t> read_band(GDALDataset& ds, const std::string& path, int width, int height,
                               const std::string& what) {
  if (ds.GetRasterCount() != 1)
    throw Error(path + ": the " + what + " has " + std::to_string(ds.GetRasterCount()) +
                " bands: it must be one 8-bit band (grey, not RGB or with alpha)");
  if (const GDALDataType type = ds.GetRasterBand(1)->GetRasterDataType(); type != GDT_Byte)
    throw Error(path + ": the " + what + " is " + GDALGetDataTypeName(type) +
                ": it must be one 8-bit band (Byte, values 0..255)");
  if (ds.GetRasterXSize() != width || ds.GetRasterYSize() != height)
    throw Error(path + ": the " + what + " is " + std::to_string(ds.GetRasterXSize()) + " x " +
                std::to_string(ds.GetRasterYSize()) + ", the painting " + std::to_string(width) +
                " x " + std::to_string(height));
  std::vector<uint8_t> out(size_t(width) * size_t(height));
  if (ds.GetRasterBand(1)->RasterIO(GF_Read, 0, 0, width, height, out.data(), width, height,
                                    GDT_Byte, 0, 0, nullptr) != CE_None)
    gdal_error(path + ": GDAL cannot read the " + what);
  return out;
}

// The "class" of each feature of the GeoJSON `path` as written (its JSON value), by feature id;
// empty when the file is no GeoJSON. A GeoJSON layer whose features mix numbers and text has its
// attribute typed String, the numbers read as text too: only the features' own JSON (the
// driver's NATIVE_DATA) tells which is written as text.
std::map<GIntBig, nlohmann::json> written_classes(GDALDataset& ds, const std::string& path) {
  std::map<GIntBig, nlohmann::json> out;
  if (!ds.GetDriver() || std::string(ds.GetDriver()->GetDescription()) != "GeoJSON") return out;
  const char* const options[] = {"NATIVE_DATA=YES", nullptr};
  const char* const drivers[] = {"GeoJSON", nullptr};
  std::unique_ptr<GDALDataset> native(
      GDALDataset::Open(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY, drivers, options));
  if (!native || native->GetLayerCount() != 1) return out;
  for (const auto& feature : *native->GetLayer(0)) {
    const char* text = feature->GetNativeData();
    const auto json = nlohmann::json::parse(text ? text : "", nullptr, false);
    if (json.is_object() && json.contains("properties") && json["properties"].is_object() &&
        json["properties"].contains("class"))
      out[feature->GetFID()] = json["properties"]["class"];
  }
  return out;
}

// The polygons of `ds` (read_class_image's hand-drawn class image) burnt in file order into the
// painting's pixels, their "class" attribute checked first.
std::vector<uint8_t> rasterized_classes(GDALDataset& ds, const std::string& path, int width,
                                        int height) {
  if (ds.GetLayerCount() != 1)
    throw Error(path + ": a class image's polygons are one layer, not " +
                std::to_string(ds.GetLayerCount()));
  OGRLayer* layer = ds.GetLayer(0);
  const int field = layer->GetLayerDefn()->GetFieldIndex("class");
  if (field < 0) throw Error(path + ": the class image's polygons have no attribute \"class\"");
  // A String field would be read (and burnt) as atof's value: "forest" as 0, "7a" as 7.
  const OGRFieldType type = layer->GetLayerDefn()->GetFieldDefn(field)->GetType();
  const bool numeric = type == OFTInteger || type == OFTInteger64 || type == OFTReal;
  // Not numeric: which features are written as text (without the file's own JSON, all of them).
  const auto written = numeric ? std::map<GIntBig, nlohmann::json>() : written_classes(ds, path);
  for (const auto& feature : *layer) {
    const std::string name = path + ": feature " + std::to_string(feature->GetFID());
    const OGRGeometry* geometry = feature->GetGeometryRef();
    const auto shape = geometry ? wkbFlatten(geometry->getGeometryType()) : wkbNone;
    if (shape != wkbPolygon && shape != wkbMultiPolygon)
      throw Error(name + " is " +
                  (geometry ? std::string("a ") + geometry->getGeometryName() : "no geometry") +
                  ", not a polygon");
    const auto as_written = written.find(feature->GetFID());
    const bool found = as_written != written.end();
    const bool text = !numeric && (written.empty() || (found && as_written->second.is_string()));
    const bool number = numeric || (found && as_written->second.is_number());
    const double value = feature->GetFieldAsDouble(field);
    if (text || !number || !feature->IsFieldSetAndNotNull(field) || value != std::floor(value) ||
        value < 0 || value >= kUnknownLabel)
      throw Error(name + "'s class '" +
                  (found && !as_written->second.is_string()
                       ? as_written->second.dump()
                       : std::string(feature->GetFieldAsString(field))) +
                  (!text ? "' is not an integer in 0.." + std::to_string(kUnknownLabel - 1)
                         : std::string("' is written as text (the attribute \"class\" is of "
                                       "type ") +
                               OGRFieldDefn::GetFieldTypeName(type) +
                               ": write the classes as numbers, not in quotes)"));
  }
  layer->ResetReading();
  std::vector<uint8_t> out(size_t(width) * size_t(height), kUnknownLabel);
  double pixels[6] = {0, 1, 0, 0, 0, 1};  // x the column, y the row downwards
  char attribute[] = "ATTRIBUTE=class";
  char* options[] = {attribute, nullptr};
  OGRLayerH layers[] = {OGRLayer::ToHandle(layer)};
  if (GDALRasterizeLayersBuf(out.data(), width, height, GDT_Byte, 0, 0, 1, layers, nullptr, pixels,
                             nullptr, nullptr, 0, options, nullptr, nullptr) != CE_None)
    gdal_error(path + ": GDAL cannot rasterize the class image's polygons");
  const auto outside = std::count(out.begin(), out.end(), kUnknownLabel);
  if (outside > 0)
    throw Error(path + ": " + std::to_string(outside) +
                " painting pixels lie in no polygon of the class image");
  return out;
}

// The class map through texture's majority filter, which filters a square tile with a ring
// around it: the painting is placed in a square of unclassified pixels (they do not vote).
std::vector<uint8_t> majority_filtered(const std::vector<uint8_t>& labels, int width, int height,
                                       int radius) {
  const int n = std::max(width, height), side = n + 2 * radius;
  std::vector<int> square(size_t(side) * size_t(side), -1);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      square[size_t(y + radius) * size_t(side) + size_t(x + radius)] =
          labels[size_t(y) * size_t(width) + size_t(x)];
  const std::vector<int> filtered = texture::majority_filter(square, n, radius);
  std::vector<uint8_t> out(labels.size());
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      out[size_t(y) * size_t(width) + size_t(x)] =
          uint8_t(filtered[size_t(y) * size_t(n) + size_t(x)]);
  return out;
}

}  // namespace

Exemplar read_painting(const std::string& path, const std::string& what) {
  const GdalSession gdal;
  const auto ds = open_image(path, what);
  const int bands = ds->GetRasterCount();
  if (bands < 1 || bands > 4)
    throw Error(path + ": a " + what + " has 1 (grey), 3 or 4 (RGB, alpha) bands, not " +
                std::to_string(bands));
  // GDAL reads the pixels as stored; a viewer shows them turned by the EXIF orientation.
  if (const char* turn = ds->GetMetadataItem("EXIF_Orientation"); turn && std::string(turn) != "1")
    spdlog::warn(
        "{}: EXIF orientation {}: the {} is read as stored, not turned as a viewer shows "
        "it; its class image, masks and \"rows\" are taken in that orientation (save it "
        "turned to use it as seen)",
        path, turn, what);
  Exemplar e;
  e.width = ds->GetRasterXSize();
  e.height = ds->GetRasterYSize();
  const size_t n = size_t(e.width) * size_t(e.height);
  e.rgb.resize(3 * n);
  e.labels.assign(n, 0);
  e.excluded.assign(n, 0);
  GDALRasterBand* first = ds->GetRasterBand(1);
  const GDALColorTable* palette =
      first->GetColorInterpretation() == GCI_PaletteIndex ? first->GetColorTable() : nullptr;
  if (palette) {
    // A palette image's values are indices: its colours are the table's (transparent: excluded).
    std::vector<int32_t> index(n);
    if (first->RasterIO(GF_Read, 0, 0, e.width, e.height, index.data(), e.width, e.height,
                        GDT_Int32, 0, 0, nullptr) != CE_None)
      gdal_error(path + ": GDAL cannot read the " + what + "'s pixels");
    for (size_t i = 0; i < n; ++i) {
      const GDALColorEntry* c = palette->GetColorEntry(index[i]);
      if (!c)
        throw Error(path + ": pixel value " + std::to_string(index[i]) + " is not in the " + what +
                    "'s colour table of " + std::to_string(palette->GetColorEntryCount()) +
                    " entries");
      e.rgb[3 * i] = c->c1;
      e.rgb[3 * i + 1] = c->c2;
      e.rgb[3 * i + 2] = c->c3;
      e.excluded[i] = c->c4 == 0;
    }
  } else {
    std::vector<int> band_map = bands >= 3 ? std::vector<int>{1, 2, 3} : std::vector<int>{1, 1, 1};
    // 8-bit values as they are; 16-bit ones over their whole range (as viewers show them).
    const GDALDataType type = first->GetRasterDataType();
    const float divisor = type == GDT_Byte ? 1.0f : type == GDT_UInt16 ? 257.0f : 0.0f;
    for (const int b : band_map)
      if (divisor == 0 || ds->GetRasterBand(b)->GetRasterDataType() != type)
        throw Error(path + ": the " + what + "'s band " + std::to_string(b) + " is " +
                    GDALGetDataTypeName(ds->GetRasterBand(b)->GetRasterDataType()) + ": a " + what +
                    " is 8-bit or 16-bit (unsigned) in every band");
    const auto size = GSpacing(sizeof(float));
    if (ds->RasterIO(GF_Read, 0, 0, e.width, e.height, e.rgb.data(), e.width, e.height, GDT_Float32,
                     3, band_map.data(), 3 * size, 3 * size * e.width, size, nullptr) != CE_None)
      gdal_error(path + ": GDAL cannot read the " + what + "'s pixels");
    if (divisor != 1)
      for (float& v : e.rgb) v /= divisor;
  }
  // What is not the painting (transparent under an alpha band, nodata, outside GDAL's mask) is
  // never copied.
  if (!(first->GetMaskFlags() & GMF_ALL_VALID)) {
    std::vector<uint8_t> mask(n);
    if (first->GetMaskBand()->RasterIO(GF_Read, 0, 0, e.width, e.height, mask.data(), e.width,
                                       e.height, GDT_Byte, 0, 0, nullptr) != CE_None)
      gdal_error(path + ": GDAL cannot read the " + what + "'s transparency");
    for (size_t i = 0; i < n; ++i) e.excluded[i] |= mask[i] == 0;
  }
  return e;
}

std::vector<uint8_t> read_mask(const std::string& path, int width, int height,
                               const std::string& what) {
  const GdalSession gdal;
  return read_band(*open_image(path, what), path, width, height, what);
}

std::vector<float> read_value_band(const std::string& path, int& width, int& height,
                                   const std::string& what) {
  const GdalSession gdal;
  const auto ds = open_image(path, what);
  if (ds->GetRasterCount() != 1)
    throw Error(path + ": the " + what + " has " + std::to_string(ds->GetRasterCount()) +
                " bands: it must be one band");
  width = ds->GetRasterXSize();
  height = ds->GetRasterYSize();
  GDALRasterBand* band = ds->GetRasterBand(1);
  std::vector<float> values(size_t(width) * size_t(height));
  if (band->RasterIO(GF_Read, 0, 0, width, height, values.data(), width, height, GDT_Float32, 0, 0,
                     nullptr) != CE_None)
    gdal_error(path + ": GDAL cannot read the " + what);
  int has_nodata = 0;
  if (const double nodata = band->GetNoDataValue(&has_nodata); has_nodata)
    std::replace(values.begin(), values.end(), float(nodata), float(NAN));
  return values;
}

std::vector<uint8_t> read_class_image(const std::string& path, int width, int height) {
  const GdalSession gdal;
  const auto ds = open_image(path, "class image", GDAL_OF_RASTER | GDAL_OF_VECTOR);
  if (ds->GetRasterCount() > 0) return read_band(*ds, path, width, height, "class image");
  return rasterized_classes(*ds, path, width, height);
}

std::vector<uint8_t> segment_by_colour(const Exemplar& painting, int k) {
  const size_t n = size_t(painting.width) * size_t(painting.height);
  std::vector<int> bin_of(n);
  std::vector<uint64_t> histogram(size_t(texture::histogram_bins(texture::ColourSpace::Lab)), 0);
  for (size_t i = 0; i < n; ++i) {
    bin_of[i] = texture::lab_bin(texture::srgb_to_lab(painting.rgb[3 * i], painting.rgb[3 * i + 1],
                                                      painting.rgb[3 * i + 2]));
    ++histogram[size_t(bin_of[i])];
  }
  const auto bins = texture::occupied_bins(histogram, texture::ColourSpace::Lab);
  const texture::Partition partition = texture::kmeans(bins, k);
  // occupied_bins lists the occupied bins in ascending order: their ranks among them.
  std::vector<int> rank(histogram.size(), -1);
  for (size_t i = 0, r = 0; i < histogram.size(); ++i)
    if (histogram[i] > 0) rank[i] = int(r++);
  std::vector<uint8_t> labels(n);
  for (size_t i = 0; i < n; ++i)
    labels[i] = uint8_t(partition.assign[size_t(rank[size_t(bin_of[i])])]);
  return majority_filtered(labels, painting.width, painting.height, kClassSmoothingRadius);
}

}  // namespace maquette::synthesis
