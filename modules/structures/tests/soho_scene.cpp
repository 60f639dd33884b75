#include "soho_scene.h"

#include <gdal_priv.h>
#include <ogrsf_frmts.h>

#include <cmath>
#include <memory>
#include <stdexcept>

#include "core/geometry.h"

namespace maquette::structures {
namespace {

std::vector<VectorFeature> read_footprints(const std::string& path) {
  GDALAllRegister();
  std::unique_ptr<GDALDataset> ds(
      GDALDataset::Open(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY));
  if (!ds) throw std::runtime_error("GDAL cannot open " + path);
  std::vector<VectorFeature> out;
  OGRLayer* layer = ds->GetLayer(0);
  for (std::unique_ptr<OGRFeature> f(layer->GetNextFeature()); f;
       f.reset(layer->GetNextFeature())) {
    const OGRGeometry* g = f->GetGeometryRef();
    std::vector<std::byte> wkb(size_t(g->WkbSize()));
    g->exportToWkb(wkbNDR, reinterpret_cast<unsigned char*>(wkb.data()), wkbVariantIso);
    VectorFeature v;
    v.id = f->GetFID();
    v.geometry = parse_wkb(wkb, "feature " + std::to_string(v.id));
    out.push_back(std::move(v));
  }
  return out;
}

CellId cell_of(const VectorFeature& f) {
  const GeoPoint& first = f.geometry.polygons[0].rings[0][0];
  return default_grid().cell_from_point({first.lon, first.lat}, kSohoLevel);
}

Tile<float> dem_tile(const Grid& grid, CellId cell) {
  const PlaneSquare sq = grid.plane_square(cell);
  const double pixel = sq.side / kSohoTileSize;
  const int halo = kDemHaloPixels;
  Tile<float> dem(kSohoTileSize, 1, halo);
  for (int r = -halo; r < kSohoTileSize + halo; ++r)
    for (int c = -halo; c < kSohoTileSize + halo; ++c)
      dem.at(c, r) =
          float(soho_terrain({sq.x_min + (c + 0.5) * pixel, sq.y_max - (r + 0.5) * pixel}));
  return dem;
}

}  // namespace

double soho_terrain(const PlanePoint& p) {
  return 30 + 18 * std::sin(p.x / 900) + 3 * std::sin(p.x / 37) * std::cos(p.y / 23);
}

SohoScene::SohoScene(const std::string& path) : footprints(read_footprints(path)) {
  for (const VectorFeature& f : footprints)
    if (const CellId cell = cell_of(f); !dems.count(cell))
      dems.emplace(cell, dem_tile(default_grid(), cell));
}

BuildingSite SohoScene::site(const VectorFeature& footprint) const {
  const CellId cell = cell_of(footprint);
  const LonLat centre = default_grid().centre(cell);
  // The roof drapes an orthophoto of the DEM's tiling.
  return {&default_grid(),
          cell,
          &dems.at(cell),
          {centre.lon, centre.lat, 0},
          TextureWindow{kSohoTileSize, kDemHaloPixels}};
}

}  // namespace maquette::structures
