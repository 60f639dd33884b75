// PixelMapper (formats/gdal/pixel_map.h) against the exact transform, independently of it: each
// sample's grid pixel centre (core/halo.h pixel_centre) taken to the source's pixels by PROJ and
// the source's inverse geotransform. On tiles of face N that its diagonals cross (the meridians
// 0 and 90 E, where rows of samples bend by about 50 degrees on the ground) and one far from
// them, for a lon/lat source and an Arctic polar stereographic one.
#include "gdal/pixel_map.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "core/halo.h"
#include "gdal/raster_source.h"
#include "ingest_fixture.h"
#include "synthetic_raster.h"

namespace maquette::test {
namespace {

constexpr int kSize = 256;

struct Case {
  const char* name;
  LonLat point;
  int level;
};

// The largest distance, in source pixels, between PixelMapper's coordinates of the samples of
// `cell`'s tile and the exact ones; every sample must have both.
double worst_error(const RasterSource& source, const Projector& to_crs, CellId cell) {
  const Grid& grid = default_grid();
  PixelMapper mapper(grid, source);
  PixelMap map;
  mapper.map(cell, kSize, map);
  const auto& g = source.geotransform;
  const double det = g[1] * g[5] - g[2] * g[4];
  const int level = cell.level() + log2_tile_size(kSize);
  double worst = 0;
  for (int row = 0; row < kSize; ++row)
    for (int col = 0; col < kSize; ++col) {
      const LonLat p = pixel_centre(grid, *pixel_source(grid, cell, kSize, col, row), level);
      const auto [x, y] = to_crs(p.lon, p.lat);
      // The inverse of the geotransform, by hand.
      const double dx = x - g[0], dy = y - g[3];
      const double px = (g[5] * dx - g[2] * dy) / det, py = (g[1] * dy - g[4] * dx) / det;
      const size_t k = size_t(row) * size_t(kSize) + size_t(col);
      const double e = std::hypot(map.x[k] - px, map.y[k] - py);
      EXPECT_FALSE(std::isnan(e)) << cell.ToText() << " " << col << " " << row;
      worst = std::max(worst, e);
    }
  return worst;
}

// The cases' tiles (the diagonals at lon 0 and 90 E at 50 to 70 N, a control at 45 E), mapped in
// `crs` with pixels of `pixel` (the sample's ground size in its units) from (west, north).
void expect_within_promise(const std::string& crs, double west, double north,
                           double (*pixel)(double sample_m, double lat)) {
  const Grid& grid = default_grid();
  const Projector to_crs("EPSG:4326", crs);
  for (const Case& c :
       {Case{"lon 0, 50 N", {0.0005, 50.0}, 10}, Case{"lon 0, 60 N", {0.0005, 60.0}, 10},
        Case{"lon 0, 70 N", {-0.0005, 70.0}, 10}, Case{"lon 90 E, 55 N", {90.0005, 55.0}, 9},
        Case{"lon 90 E, 65 N", {89.9995, 65.0}, 9}, Case{"control 45 E, 60 N", {45.0, 60.0}, 10}}) {
    const CellId cell = grid.cell_from_point(c.point, c.level);
    ASSERT_EQ(cell.ToText()[0], 'N') << c.name;
    const double sample = grid.level_info(c.level, kSize).pixel_m;
    // Source pixels of a sample's size (the ingest's level for the finest source) and 2.8
    // times larger (a coarser source of a mosaic). Measured before the lattice's bends were
    // checked: 0.34 and 0.41 source pixels (lon 0, 70 N, lon/lat; lon 0, 50 N, stereographic),
    // the centres of the blocks that the diagonal cuts a corner off within 1/8 pixel; after:
    // below 0.002.
    for (const double fine : {0.354, 1.0}) {
      const double d = pixel(sample, c.point.lat) / fine;
      RasterSpec spec;
      spec.width = spec.height = 16;  // only the pixels' coordinates matter, beyond it too
      spec.geotransform = {west, d, 0, north, 0, -d};
      spec.crs = crs;
      const std::string tif = temp_dir() + "/pixel_map.tif";
      write_raster(tif, spec, [](int, double, double) { return 0.0; });
      const double worst = worst_error(describe_source(tif, {}, ""), to_crs, cell);
      std::printf("%s %s, %g source pixels per sample: worst %.4f source pixels\n", crs.c_str(),
                  c.name, fine, worst);
      EXPECT_LE(worst, PixelMapper::kMaxError) << crs << " " << c.name << " " << fine;
    }
  }
}

TEST(PixelMapper, WithinAnEighthOfASourcePixelAcrossThePolarDiagonals) {
  // Lon/lat pixels of a sample's size across the meridian at the case's latitude.
  expect_within_promise("EPSG:4326", -180, 90, [](double sample_m, double lat) {
    return sample_m / (111.32e3 * std::cos(lat * M_PI / 180));
  });
  // Metres of polar stereographic (scale ~1.03 at 60 N), from a corner off the pole.
  expect_within_promise("EPSG:3995", -4e6, 4e6, [](double sample_m, double) { return sample_m; });
}

}  // namespace
}  // namespace maquette::test
