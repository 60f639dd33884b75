#include "geotiff/band_metadata.h"

#include <cmath>
#include <limits>
#include <string>

#include "geotiff/gdal_util.h"
#include "image/class_table.h"

namespace maquette {
namespace {

void set_classes(GDALRasterBand& band, const LayerInfo& layer) {
  const ClassTable classes = class_table(layer);
  if (classes.empty() || classes.begin()->first < 0) return;
  const int64_t last = classes.rbegin()->first;
  const bool palette = (layer.dtype == DType::U8 || layer.dtype == DType::U16) && last < 65536;
  CPLStringList names;
  GDALColorTable table;
  for (int64_t v = 0; v <= last; ++v) {
    const auto it = classes.find(v);
    names.AddString(it == classes.end() ? "" : it->second.name.c_str());
    if (!palette) continue;
    GDALColorEntry e{0, 0, 0, 0};  // values that name no class: transparent black
    if (it != classes.end()) {
      const Rgb c = class_colour(classes, v);
      e = {c[0], c[1], c[2], 255};
    }
    table.SetColorEntry(int(v), &e);
  }
  if (palette && band.SetColorTable(&table) != CE_None)
    gdal_error("cannot set the colour table of layer '" + layer.name + "'");
  if (band.SetCategoryNames(names.List()) != CE_None)
    gdal_error("cannot set the class names of layer '" + layer.name + "'");
}

}  // namespace

std::optional<double> export_nodata(const LayerInfo& layer) {
  if (layer.nodata) return layer.nodata;
  if (layer.dtype == DType::F32 || layer.dtype == DType::F64)
    return std::numeric_limits<double>::quiet_NaN();
  return std::nullopt;
}

void describe_bands(GDALDataset& ds, const LayerInfo& layer, int level) {
  ds.SetMetadataItem("MAQUETTE_LAYER", layer.name.c_str());
  ds.SetMetadataItem("MAQUETTE_LEVEL", std::to_string(level).c_str());
  ds.SetMetadataItem("MAQUETTE_SEMANTICS", std::string(semantics_name(layer.semantics)).c_str());
  const auto nodata = export_nodata(layer);
  for (int k = 1; k <= ds.GetRasterCount(); ++k) {
    GDALRasterBand& band = *ds.GetRasterBand(k);
    const std::string name =
        ds.GetRasterCount() == 1 ? layer.name : layer.name + " channel " + std::to_string(k);
    band.SetDescription(name.c_str());
    if (!layer.units.empty()) band.SetUnitType(layer.units.c_str());
    if (nodata && band.SetNoDataValue(*nodata) != CE_None)
      gdal_error("cannot set the nodata value of layer '" + layer.name + "'");
    if (layer.semantics == Semantics::Categorical && k == 1) set_classes(band, layer);
  }
}

}  // namespace maquette
