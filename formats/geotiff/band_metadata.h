// What a GeoTIFF tells about the layer it holds: nodata, band descriptions, units, and for
// categorical layers the colour table and class names.
#pragma once

#include <gdal_priv.h>

#include "store/store.h"

namespace maquette {

// The nodata value written: the layer's, or NaN for a float layer without one (tiles mark
// missing samples with NaN then); nullopt for an integer layer without one.
std::optional<double> export_nodata(const LayerInfo& layer);

// Sets the metadata of every band of `ds` (one band per channel) and the dataset's MAQUETTE_*
// items. Colour tables need 8 or 16-bit unsigned samples (a GeoTIFF limit); other categorical
// layers keep their class names only. Throws maquette::Error on a GDAL failure.
void describe_bands(GDALDataset& ds, const LayerInfo& layer, int level);

}  // namespace maquette
