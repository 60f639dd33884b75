// export gtiff in the rHEALPix plane, read back with GDAL: CRS, geotransform, bit-identical
// samples, nodata, tiling and compression, band metadata and the colour table.
#include <gtest/gtest.h>
#include <ogr_spatialref.h>

#include <cmath>
#include <cstring>

#include "export_fixture.h"

namespace maquette::test {
namespace {

std::string export_rhealpix(const std::string& layer, const std::string& extra = "") {
  return export_layer("gtiff", layer, "tif", extra);
}

// The output must hold each tile at its plane position, sample for sample (bit for bit).
template <typename T>
void expect_tiles_exact(GDALDataset& ds, const std::string& layer, const std::vector<CellId>& cells,
                        bool overview = false) {
  const auto store = Store::open(export_fixture().store_path, Store::Mode::ReadOnly);
  double gt[6];
  ASSERT_EQ(ds.GetGeoTransform(gt), CE_None);
  const int n = kTileSize;
  for (CellId c : cells) {
    const auto tile = overview ? store->get_overview(layer, c) : store->get_tile(layer, c);
    ASSERT_TRUE(tile);
    const PlaneSquare sq = default_grid().plane_square(c);
    const int col = int(std::lround((sq.x_min - gt[0]) / gt[1]));
    const int row = int(std::lround((gt[3] - sq.y_max) / -gt[5]));
    std::vector<T> got(size_t(n) * n);
    ASSERT_EQ(
        ds.GetRasterBand(1)->RasterIO(GF_Read, col, row, n, n, got.data(), n, n,
                                      tile->dtype == DType::U8 ? GDT_Byte : GDT_Float32, 0, 0),
        CE_None);
    EXPECT_EQ(std::memcmp(got.data(), tile->bytes.data(), tile->bytes.size()), 0) << c.ToText();
  }
}

// The plane squares of the cells, as a GeoTIFF geotransform and size.
void expect_plane_extent(GDALDataset& ds, const std::vector<CellId>& cells) {
  const Grid& grid = default_grid();
  double x0 = INFINITY, y1 = -INFINITY, x1 = -INFINITY, y0 = INFINITY;
  for (CellId c : cells) {
    const PlaneSquare s = grid.plane_square(c);
    x0 = std::min(x0, s.x_min), y1 = std::max(y1, s.y_max);
    x1 = std::max(x1, s.x_min + s.side), y0 = std::min(y0, s.y_max - s.side);
  }
  const double pixel = grid.plane_square(cells[0]).side / kTileSize;
  double gt[6];
  ASSERT_EQ(ds.GetGeoTransform(gt), CE_None);
  EXPECT_NEAR(gt[0], x0, 1e-6);
  EXPECT_NEAR(gt[3], y1, 1e-6);
  EXPECT_NEAR(gt[1], pixel, 1e-9);
  EXPECT_NEAR(gt[5], -pixel, 1e-9);
  EXPECT_EQ(gt[2], 0);
  EXPECT_EQ(gt[4], 0);
  EXPECT_EQ(ds.GetRasterXSize(), std::lround((x1 - x0) / pixel));
  EXPECT_EQ(ds.GetRasterYSize(), std::lround((y1 - y0) / pixel));
}

TEST(GtiffRhealpix, DemIsExactTiledCompressedAndInTheRhealpixCrs) {
  const auto ds = open_raster(export_rhealpix("dem"));
  ASSERT_TRUE(ds);
  OGRSpatialReference expected;
  ASSERT_EQ(expected.importFromProj4("+proj=rhealpix +ellps=WGS84 +north_square=0 "
                                     "+south_square=0 +units=m +no_defs"),
            OGRERR_NONE);
  ASSERT_NE(ds->GetSpatialRef(), nullptr);
  EXPECT_TRUE(ds->GetSpatialRef()->IsSame(&expected));
  expect_plane_extent(*ds, export_fixture().dem_cells);
  expect_tiles_exact<float>(*ds, "dem", export_fixture().dem_cells);

  GDALRasterBand& band = *ds->GetRasterBand(1);
  int has_nodata = 0;
  EXPECT_EQ(band.GetNoDataValue(&has_nodata), -9999);
  EXPECT_TRUE(has_nodata);
  EXPECT_STREQ(band.GetUnitType(), "m");
  EXPECT_STREQ(band.GetDescription(), "dem");
  EXPECT_EQ(band.GetRasterDataType(), GDT_Float32);
  int bx = 0, by = 0;
  band.GetBlockSize(&bx, &by);
  EXPECT_EQ(bx, 256);
  EXPECT_EQ(by, 256);
  EXPECT_STREQ(ds->GetMetadataItem("COMPRESSION", "IMAGE_STRUCTURE"), "DEFLATE");
}

TEST(GtiffRhealpix, LandcoverHasItsColourTableAndClassNames) {
  const auto ds = open_raster(export_rhealpix("landcover"));
  ASSERT_TRUE(ds);
  expect_tiles_exact<uint8_t>(*ds, "landcover", export_fixture().dem_cells);
  GDALRasterBand& band = *ds->GetRasterBand(1);
  EXPECT_EQ(band.GetRasterDataType(), GDT_Byte);
  EXPECT_EQ(band.GetNoDataValue(), 0);
  const GDALColorTable* table = band.GetColorTable();
  ASSERT_NE(table, nullptr);
  EXPECT_EQ(band.GetColorInterpretation(), GCI_PaletteIndex);
  const GDALColorEntry expected[] = {
      {0x22, 0x8b, 0x22, 255}, {0x1e, 0x90, 0xff, 255}, {0xff, 0x00, 0x00, 255}};
  for (int v = 1; v <= 3; ++v) {
    const GDALColorEntry* e = table->GetColorEntry(v);
    ASSERT_NE(e, nullptr);
    EXPECT_EQ(e->c1, expected[v - 1].c1);
    EXPECT_EQ(e->c2, expected[v - 1].c2);
    EXPECT_EQ(e->c3, expected[v - 1].c3);
    EXPECT_EQ(e->c4, 255);
  }
  char** names = band.GetCategoryNames();
  ASSERT_NE(names, nullptr);
  ASSERT_GE(CSLCount(names), 4);
  EXPECT_STREQ(names[1], "forest");
  EXPECT_STREQ(names[2], "water");
  EXPECT_STREQ(names[3], "urban");
}

TEST(GtiffRhealpix, CellsOnTwoFacesShareOneRasterWithNodataBetween) {
  const auto& cells = export_fixture().twofaces_cells;
  ASSERT_NE(cells[0].face(), cells[1].face());
  const auto ds = open_raster(export_rhealpix("twofaces"));
  ASSERT_TRUE(ds);
  expect_plane_extent(*ds, cells);
  expect_tiles_exact<float>(*ds, "twofaces", cells);
  int has_nodata = 0;
  EXPECT_TRUE(std::isnan(ds->GetRasterBand(1)->GetNoDataValue(&has_nodata)));
  EXPECT_TRUE(has_nodata);
  // The columns between the two cells hold no data.
  const std::vector<double> v = read_band(*ds);
  const int w = ds->GetRasterXSize();
  ASSERT_GT(w, 2 * kTileSize);
  for (int row = 0; row < ds->GetRasterYSize(); ++row)
    for (int col = kTileSize; col < w - kTileSize; ++col)
      ASSERT_TRUE(std::isnan(v[size_t(row) * w + col])) << col << ", " << row;
}

TEST(GtiffRhealpix, CoarserLevelWritesOverviewTiles) {
  const auto ds = open_raster(export_rhealpix("dem", "--level 5"));
  ASSERT_TRUE(ds);
  const CellId parent = export_fixture().dem_cells[0].parent();
  expect_plane_extent(*ds, {parent});
  expect_tiles_exact<float>(*ds, "dem", {parent}, true);
}

TEST(GtiffRhealpix, CellsSelectTheRegion) {
  const CellId one = export_fixture().dem_cells[2];
  const auto ds = open_raster(export_rhealpix("dem", "--cells " + one.ToText()));
  ASSERT_TRUE(ds);
  expect_plane_extent(*ds, {one});
  expect_tiles_exact<float>(*ds, "dem", {one});
  // A compacted id (the parent) selects all four.
  const auto all = open_raster(export_rhealpix("dem", "--cells " + one.parent().ToText()));
  ASSERT_TRUE(all);
  expect_plane_extent(*all, export_fixture().dem_cells);
}

}  // namespace
}  // namespace maquette::test
