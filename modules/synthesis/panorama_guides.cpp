#include "panorama_guides.h"

#include <gdal_priv.h>

#include <memory>
#include <utility>

#include "core/error.h"
#include "core/sibling_path.h"
#include "gdal/gdal_env.h"
#include "painting.h"

namespace maquette::synthesis {

std::vector<std::vector<float>> read_guide_bands(const std::string& path, int width, int height,
                                                 const std::string& of,
                                                 const std::vector<GuideBand>& wanted) {
  const GdalSession gdal;
  const std::unique_ptr<GDALDataset> ds(
      GDALDataset::Open(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
  if (!ds) gdal_error(path + ": GDAL cannot open the guides");
  if (ds->GetRasterXSize() != width || ds->GetRasterYSize() != height)
    throw Error(path + ": the guides are " + std::to_string(ds->GetRasterXSize()) + " x " +
                std::to_string(ds->GetRasterYSize()) + " pixels, " + of + " " +
                std::to_string(width) + " x " + std::to_string(height));
  std::vector<std::vector<float>> out;
  for (const GuideBand& wish : wanted) {
    std::vector<float>& values = out.emplace_back();
    for (int b = 1; b <= ds->GetRasterCount() && values.empty(); ++b) {
      GDALRasterBand* band = ds->GetRasterBand(b);
      if (band->GetDescription() != wish.name) continue;
      values.resize(size_t(width) * size_t(height));
      if (band->RasterIO(GF_Read, 0, 0, width, height, values.data(), width, height, GDT_Float32, 0,
                         0) != CE_None)
        gdal_error(path + ": GDAL cannot read band '" + wish.name + "'");
    }
    if (values.empty() && wish.required)
      throw Error(path + ": no band '" + wish.name + "' (" + wish.hint + ")");
  }
  return out;
}

PanoramaPicture read_panorama(const std::string& picture, bool with_shading) {
  PanoramaPicture p;
  const Exemplar colours = read_painting(picture, "panorama");  // any 8-bit RGB image
  p.width = colours.width;
  p.height = colours.height;
  p.rgb.assign(colours.rgb.begin(), colours.rgb.end());
  auto bands = read_guide_bands(
      sibling_path(picture, "-guides.tif"), p.width, p.height, "the picture " + picture,
      {{"land_cover", "render the panorama with --land-cover"},
       {"altitude", "not a panorama's guides?"},
       {"distance", "not a panorama's guides?"},
       {"shading",
        "rendered before it existed: render the panorama again, or give \"shading\": 0 and no "
        "\"w_light\"",
        with_shading},
       {"coverage", "", false}});
  p.land_cover = std::move(bands[0]);
  p.altitude = std::move(bands[1]);
  p.distance = std::move(bands[2]);
  p.shading = std::move(bands[3]);
  p.coverage = std::move(bands[4]);
  return p;
}

}  // namespace maquette::synthesis
