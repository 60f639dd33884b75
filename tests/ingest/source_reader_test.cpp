// SourceReader: readers of one file in several threads share its GDAL handle; their windows are
// the file's pixels (nodata as NaN), whatever the other threads read meanwhile.
#include <gtest/gtest.h>

#include <cmath>
#include <thread>
#include <vector>

#include "gdal/raster_source.h"
#include "ingest_fixture.h"
#include "synthetic_raster.h"

namespace maquette::test {
namespace {

// Pixel (i, j) of the test raster: i + 1000 j, nodata (65535) where i + j is a multiple of 7.
double pixel(int i, int j) { return (i + j) % 7 == 0 ? 65535 : i + 1000 * j; }

TEST(SourceReader, ThreadsReadTheFilesPixelsThroughOneHandle) {
  const std::string tif = temp_dir() + "/reader.tif";
  RasterSpec spec;
  spec.width = 300;
  spec.height = 40;
  spec.geotransform = {500000, 30, 0, 4100000, 0, -30};
  spec.crs = "EPSG:32612";
  spec.type = "UInt16";
  spec.nodata = 65535;
  write_raster(tif, spec, [](int, double x, double y) {
    return pixel(int((x - 500000) / 30), int((4100000 - y) / 30));
  });
  const RasterSource source = describe_source(tif, {}, "");
  std::vector<int> errors(4, 0);
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([&, t] {
      SourceReader reader(source);
      Window w;
      for (int k = 0; k < 600; ++k) {
        // Windows across the raster's edges too (outside: NaN).
        const int x0 = (37 * k + 11 * t) % 320 - 10, y0 = (13 * k + t) % 50 - 5;
        reader.read(x0, y0, 25, 9, 1, false, w);
        for (int j = 0; j < w.h; ++j)
          for (int i = 0; i < w.w; ++i) {
            const int si = x0 + i, sj = y0 + j;
            const bool in = si >= 0 && sj >= 0 && si < spec.width && sj < spec.height;
            const double want = in ? pixel(si, sj) : 65535;
            const float got = w.at(0, i, j);
            if (want == 65535 ? !std::isnan(got) : got != float(want)) ++errors[size_t(t)];
          }
      }
    });
  for (auto& th : threads) th.join();
  for (int t = 0; t < 4; ++t) EXPECT_EQ(errors[size_t(t)], 0) << "thread " << t;
}

}  // namespace
}  // namespace maquette::test
