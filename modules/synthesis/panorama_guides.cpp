#include "panorama_guides.h"

#include <gdal_priv.h>

#include <cstring>
#include <memory>

#include "core/error.h"
#include "core/sibling_path.h"
#include "painting.h"

namespace maquette::synthesis {

PanoramaPicture read_panorama(const std::string& picture, bool with_shading) {
  PanoramaPicture p;
  const Exemplar colours = read_painting(picture, "panorama");  // any 8-bit RGB image
  p.width = colours.width;
  p.height = colours.height;
  p.rgb.assign(colours.rgb.begin(), colours.rgb.end());

  const std::string path = sibling_path(picture, "-guides.tif");
  GDALAllRegister();
  const std::unique_ptr<GDALDataset> ds(
      GDALDataset::Open(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
  if (!ds) throw Error(path + ": GDAL cannot open the panorama's guides");
  if (ds->GetRasterXSize() != p.width || ds->GetRasterYSize() != p.height)
    throw Error(path + ": the guides are " + std::to_string(ds->GetRasterXSize()) + " x " +
                std::to_string(ds->GetRasterYSize()) + " pixels, the picture " + picture + " " +
                std::to_string(p.width) + " x " + std::to_string(p.height));
  const auto band = [&](const char* name, const char* hint, bool required) {
    std::vector<float> values;
    for (int b = 1; b <= ds->GetRasterCount(); ++b) {
      GDALRasterBand* band = ds->GetRasterBand(b);
      if (std::strcmp(band->GetDescription(), name) != 0) continue;
      values.resize(size_t(p.width) * size_t(p.height));
      if (band->RasterIO(GF_Read, 0, 0, p.width, p.height, values.data(), p.width, p.height,
                         GDT_Float32, 0, 0) != CE_None)
        throw Error(path + ": GDAL cannot read band '" + name + "'");
      return values;
    }
    if (required) throw Error(path + ": no band '" + name + "' (" + hint + ")");
    return values;
  };
  p.land_cover = band("land_cover", "render the panorama with --land-cover", true);
  p.altitude = band("altitude", "not a panorama's guides?", true);
  p.distance = band("distance", "not a panorama's guides?", true);
  p.shading = band("shading",
                   "rendered before it existed: render the panorama again, or give \"shading\": 0",
                   with_shading);
  return p;
}

}  // namespace maquette::synthesis
