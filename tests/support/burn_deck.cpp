#include "burn_deck.h"

#include <gdal_alg.h>
#include <ogr_geometry.h>
#include <ogr_spatialref.h>

#include <memory>
#include <numeric>

namespace maquette::test {

bool burn_deck(GDALDataset& dataset, const nlohmann::json& first_edge,
               const nlohmann::json& second_edge, const std::vector<double>& values) {
  if (dataset.GetSpatialRef() == nullptr || int(values.size()) != dataset.GetRasterCount())
    return false;
  OGRLinearRing ring;
  for (const nlohmann::json& p : first_edge) ring.addPoint(p[0].get<double>(), p[1].get<double>());
  for (auto p = second_edge.rbegin(); p != second_edge.rend(); ++p)
    ring.addPoint((*p)[0].get<double>(), (*p)[1].get<double>());
  ring.closeRings();
  OGRPolygon deck;
  deck.addRing(&ring);
  deck.segmentize(1e-6);
  OGRSpatialReference wgs84;
  wgs84.importFromEPSG(4326);
  wgs84.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  OGRSpatialReference target(*dataset.GetSpatialRef());
  target.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  const std::unique_ptr<OGRCoordinateTransformation> transform(
      OGRCreateCoordinateTransformation(&wgs84, &target));
  if (!transform || deck.transform(transform.get()) != OGRERR_NONE) return false;
  std::vector<int> bands(values.size());
  std::iota(bands.begin(), bands.end(), 1);
  OGRGeometryH geometry = OGRGeometry::ToHandle(&deck);
  return GDALRasterizeGeometries(&dataset, int(bands.size()), bands.data(), 1, &geometry, nullptr,
                                 nullptr, values.data(), nullptr, nullptr, nullptr) == CE_None;
}

}  // namespace maquette::test
